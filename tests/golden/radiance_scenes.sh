#!/bin/bash
# RADIANCE's own test models (../shared/radiance-tests, RADIANCE 5.4's answers at -ab 0):
# every view of every model must match (>= 98 % of rays with each channel within 2 % plus
# 1 % of the view's mean, plus 3 standard deviations of RADIANCE's own runs where it
# samples at random, the README's rule, applied by its `compare` script).
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared radiance-tests
BIN="${RP_BIN:?RP_BIN not set}"
TESTS="${RP_SHARED_DIR:?RP_SHARED_DIR not set}/radiance-tests"
fail=0
bad() { echo "FAIL: $*"; fail=1; }

out=$("$TESTS/compare" "$BIN" glass mirror patterns tfunc trans trans2 mesh dielectric prism1 prism2 inst mixtex \
    mist combined 2>&1)
echo "$out"
views=$(echo "$out" | grep -c '^[a-z0-9]*\.v[0-9]')
[ "$views" -eq 28 ] || bad "expected 28 views, got $views"
echo "$out" | awk '/^[a-z0-9]*\.v[0-9]/ { if ($2 == "-" || $2 < 0.98) print }' | while read -r line; do
    echo "FAIL: below 98 %: $line"
done | grep . && fail=1

exit $fail
