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
# The plastic2 case again with its coefficients, roughnesses and u vector from a function
# file (u rotated into place by the transform) and a white pattern as the reflection
# modifier: the same numbers as the constants.
export RAYPATH=".:$SRC/lib"
"$BIN/oconv" light.rad wgmd_p2_functions.rad > "$tmp/f.oct" || exit 1
"$BIN/rtrace" -h -ab 0 -ss 0 -st 1 -av 0 0 0 -dj 0 -ds 0 -ov "$tmp/f.oct" < rays.txt \
    > "$tmp/f.out" || exit 1
if cmp -s "$tmp/f.out" "$tmp/p2.out"; then
    echo "wgmd_p2_functions: the same values as wgmd_p2"
else
    echo "FAIL: wgmd_p2_functions differs from wgmd_p2"; fail=1
fi
# A component modifier that does not exist stops rtrace at the material's line.
sed 's/pat rsv/nosuch rsv/' wgmd_p2_functions.rad > "$tmp/bad.rad"
"$BIN/oconv" light.rad "$tmp/bad.rad" > "$tmp/bad.oct" || exit 1
msg=$("$BIN/rtrace" -h -ab 0 "$tmp/bad.oct" < rays.txt 2>&1 >/dev/null)
case "$msg" in
    *"bad.rad:2: WGMDfunc 'm2': unknown specular reflection modifier 'nosuch'"*) ;;
    *) echo "FAIL: unknown modifier: $msg"; fail=1 ;;
esac
exit $fail
