#!/bin/bash
# The caustic map against the direct light it stands for (issue 42): a zenith sun through
# a 4 x 4 m port pane 3 m above a floor; 25 sensors in the middle of the sunlit square.
# Through a trans pane that passes everything the closed form is L 2 pi (1 - cos 0.2665
# deg) = 67.967 W/m2; through clear glass the classic -ab 0 (RADIANCE's glass formula,
# 59.910). rtrace -I -ab 0 with a caustic map of 1M photons and bandwidth 1000: 25 x 1000
# independent photons give 0.63 % standard error for the mean; the estimator's own bias
# at 1000 photons is 0.05 %; tolerance 2.5 % (4 sigma). Measured: -0.4 % (trans), +0.5 %
# (glass); RADIANCE 5.4a's own map reads +0.3 % here, and +3.4 % at bandwidth 200.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/caustic_pane"
mean() { awk '{s += 0.265 * $1 + 0.670 * $2 + 0.065 * $3} END {printf "%.4f", s / NR}'; }
fail=0
for pane in trans glass; do
    "$BIN/oconv" "$data/floor_sun.rad" "$data/$pane.rad" > "$tmp/$pane.oct" || exit 1
    "$BIN/mkpmap" -apc "$tmp/$pane.pm" 1m -apo pane -apr 5 -n 2 "$tmp/$pane.oct" 2> "$tmp/err" ||
        { echo "FAIL $pane: mkpmap: $(cat "$tmp/err")"; fail=1; continue; }
    ref=67.967
    [ $pane = glass ] && ref=$("$BIN/rtrace" -h -I -ab 0 "$tmp/$pane.oct" < "$data/points.txt" | mean)
    got=$("$BIN/rtrace" -h -I -ab 0 -ap "$tmp/$pane.pm" 1000 "$tmp/$pane.oct" < "$data/points.txt" | mean)
    echo "$pane: caustic photons $got, direct $ref"
    awk -v g="$got" -v r="$ref" 'BEGIN { d = g / r - 1; exit (d < 0.025 && d > -0.025) ? 0 : 1 }' ||
        { echo "FAIL $pane: caustic photons $got against $ref"; fail=1; }
done
exit $fail
