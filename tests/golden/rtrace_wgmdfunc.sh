#!/bin/bash
# WGMDfunc against RADIANCE's plastic2, trans2 and plastic where the models coincide
# (tests/data/wgmdfunc/README.md): every value within 2 % of RADIANCE 5.4's.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
DATA="$SRC/tests/data/wgmdfunc"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$DATA" || exit 1
fail=0
for s in p2 t2 pl; do
    "$BIN/oconv" light.rad "wgmd_$s.rad" > "$tmp/$s.oct" || exit 1
    "$BIN/rtrace" -h -ab 0 -ss 0 -st 1 -av 0 0 0 -dj 0 -ds 0 -ov "$tmp/$s.oct" < rays.txt \
        > "$tmp/$s.out" || exit 1
    worst=$(paste "$tmp/$s.out" "radiance_$s.ref" | awk '
        { for (k = 1; k <= 3; k++) { a = $k; b = $(k + 3); m = a > b ? a : b
              d = m > 1e-9 ? (a - b) / m : 0; if (d < 0) d = -d; if (d > w) w = d } }
        END { printf "%.4f", w + 0 }')
    n=$(wc -l < "$tmp/$s.out")
    echo "wgmd_$s: $n rays, largest relative difference to RADIANCE $worst"
    [ "$n" -eq "$(wc -l < "radiance_$s.ref")" ] || { echo "FAIL: ray count"; fail=1; }
    awk -v w="$worst" 'BEGIN { exit !(w <= 0.02) }' || { echo "FAIL: wgmd_$s above 2 %"; fail=1; }
done
exit $fail
