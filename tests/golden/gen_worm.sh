#!/bin/bash
# Golden test for genworm: RADIANCE's text (header line, name.s<i>/name.c<i>, space-
# separated %18.12g columns) for a straight worm whose radius drops from 0.5 to 0.25:
# a cylinder, then the cone tangent to both spheres (rims at z = 0.75 and 1.125, radii
# 0.5*sqrt(3)/2 and 0.25*sqrt(3)/2), compared with gen_worm.expected (RADIANCE genworm
# 2.12's output); then the error exits.
set -u
GENWORM="${RP_BIN:?RP_BIN not set}/genworm"
EXPECTED="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/golden/gen_worm.expected"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

"$GENWORM" m w 0 0 t 'if(t-.6,small,.5)' 2 -e 'small = .25' \
    > "$tmp/out" 2> "$tmp/err" || { echo "FAIL: genworm exited non-zero"; fail=1; }
if ! diff -u "$EXPECTED" "$tmp/out"; then
    echo "FAIL: genworm output differs from gen_worm.expected"
    fail=1
fi
[ -s "$tmp/err" ] && { echo "FAIL: unexpected stderr"; cat "$tmp/err"; fail=1; }

check_error() {  # expected-message args...
    local want=$1; shift
    "$GENWORM" "$@" > "$tmp/eout" 2> "$tmp/eerr"
    local st=$?
    [ "$st" -eq 1 ] || { echo "FAIL: genworm $* exited $st, expected 1"; fail=1; }
    [ -s "$tmp/eout" ] && { echo "FAIL: genworm $* wrote to stdout"; fail=1; }
    if [ "$(cat "$tmp/eerr")" != "$want" ]; then
        echo "FAIL: genworm $*: stderr '$(cat "$tmp/eerr")', expected '$want'"
        fail=1
    fi
}
check_error "genworm: nseg must be positive, got 0" m w t 0 0 1 0
check_error "genworm: r(t) is negative (-1) at t = 0: radii must be >= 0" m w t 0 0 -1 3
check_error "genworm: x(t): undefined function 'f'" m w 'f(t)' 0 0 1 3

[ "$fail" -eq 0 ] && echo "gen_worm: all checks passed"
exit "$fail"
