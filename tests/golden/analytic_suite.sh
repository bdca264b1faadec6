#!/bin/bash
# The analytic physics suite (tests/analytic, CIE 171:2006 style) at light size: every
# case against its closed form, classic and with a photon map, on three of its points
# with fewer photons (200-300 k), a bandwidth of 500 (200 for the final gather) and 8
# classic repeats. The tolerances are those of the full run (scripts/validate_analytic),
# derived from the same statistics at this size (tests/analytic/lib/suite.sh): 4 sigma of
# a 500-photon density estimate is 18 % per point and ~10 % on a case's mean, Student's t
# over 8 repeats for the classic; biases as each case's README states. A row out of
# tolerance fails the test: a closed form off by 3 % (point_source's lamp 1030 for 1000)
# fails classic rows, one off by 10 % (sky_opening's sky 9 for 10) its classic rows
# and photon mean.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
for t in oconv rtrace mkpmap getinfo; do
    [ -x "$BIN/$t" ] || { echo "skipped: $BIN/$t not built"; exit 77; }
done
export AN_BIN=$BIN AN_MODE=light AN_TMP
AN_TMP=$(mktemp -d)
trap 'rm -rf "$AN_TMP"' EXIT
# shellcheck source=SCRIPTDIR/../analytic/lib/suite.sh
. "$SRC/tests/analytic/lib/suite.sh"
fail=0
an_header
for d in "$SRC"/tests/analytic/*/case.sh; do
    an_case "$(dirname "$d")" || fail=1
done
exit $fail
