#!/bin/bash
# Golden test for rtrace on the bundled Cornell box (needs the renderer): header lines,
# results identical for -n 1 and -n 4 (-u-, direct light only, so no shared ambient cache;
# rtrace's default -u+ seeds from the clock as RADIANCE does),
# bogus records for a zero direction, -ff/-fd/-fc record sizes, -x/-y resolution line and
# ray count, -I, and "bad ray at input line N" after the complete results before it.
set -u
RT="${RP_BIN:?RP_BIN not set}/rtrace"
SCENE="${RP_SOURCE_DIR:?}/examples/cornell/scene.rad"
POINTS="${RP_SOURCE_DIR:?}/examples/cornell/points.txt"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# Views from each sensor point straight down: ray from 1 m above.
awk '{ print $1, $2, 1, 0, 0, -1 }' "$POINTS" | head -40 > rays.txt
n=$(wc -l < rays.txt)

"$RT" -ab 0 -ovLs "$SCENE" < rays.txt > h.out || bad "exit status"
head -1 h.out | grep -q '^#?RADIANCE$' || bad "magic line"
grep -q '^SOFTWARE= radphoton' h.out || bad "SOFTWARE line"
grep -q '^FORMAT=ascii$' h.out || bad "FORMAT line"
[ "$(sed '1,/^$/d' h.out | wc -l)" -eq "$n" ] || bad "one line per ray"
sed '1,/^$/d' h.out | awk -F'\t' 'NF != 6 || $5 == "" || $6 != "" { exit 1 }' || bad "v L s fields"

"$RT" -h- -ab 0 -u- -n 1 "$SCENE" < rays.txt > n1.out || bad "-n 1"
"$RT" -h- -ab 0 -u- -n 4 "$SCENE" < rays.txt > n4.out || bad "-n 4"
cmp -s n1.out n4.out || bad "-n 4 differs from -n 1"

printf '2.75 2.75 1 0 0 -1\n2.75 2.75 1 0 0 0\n' | "$RT" -h- -ab 0 "$SCENE" > bogus.out
[ "$(sed -n 2p bogus.out)" = $'0.000000e+00\t0.000000e+00\t0.000000e+00\t' ] || bad "bogus record"

"$RT" -h- -ab 0 -faf "$SCENE" < rays.txt > f.out
[ "$(wc -c < f.out)" -eq $((n * 12)) ] || bad "-faf size"
"$RT" -h- -ab 0 -fad -ovw "$SCENE" < rays.txt > d.out
[ "$(wc -c < d.out)" -eq $((n * 32)) ] || bad "-fad -ovw size"
"$RT" -ab 0 -fac "$SCENE" < rays.txt > c.out
grep -aq '^FORMAT=32-bit_rle_rgbe$' c.out || bad "-fac FORMAT"
[ "$(sed '1,/^$/d' c.out | wc -c)" -eq $((n * 4)) ] || bad "-fac size"

"$RT" -h- -ab 0 -x 5 -y 2 "$SCENE" < rays.txt > xy.out
[ "$(head -1 xy.out)" = "-Y 2 +X 5" ] || bad "resolution line"
[ "$(wc -l < xy.out)" -eq 11 ] || bad "-x 5 -y 2 reads 10 rays"
head -3 rays.txt | "$RT" -h- -ab 0 -x 2 -y 2 "$SCENE" > /dev/null 2> e.txt
[ $? -eq 1 ] && grep -q "unexpected EOF on input" e.txt || bad "short -x*-y input"

awk '{ print $1, $2, 0.001, 0, 0, 1 }' "$POINTS" | head -3 | "$RT" -h- -ab 0 -I "$SCENE" > I.out ||
    bad "-I exit status"
awk -F'\t' '$1 <= 0 { exit 1 }' I.out || bad "-I irradiance on the floor must be > 0"

# -ld: a direction shorter than the way to the floor sees nothing (clipped, value 0); a
# longer one sees what -ld- sees.
printf '2.75 2.75 1 0 0 -0.5\n2.75 2.75 1 0 0 -3\n' | "$RT" -h- -ab 0 -u- -ld+ -ov "$SCENE" > ld.out
printf '2.75 2.75 1 0 0 -1\n' | "$RT" -h- -ab 0 -u- -ov "$SCENE" > nold.out
[ "$(sed -n 1p ld.out)" = $'0.000000e+00\t0.000000e+00\t0.000000e+00\t' ] || bad "-ld+ short ray: $(sed -n 1p ld.out)"
[ "$(sed -n 2p ld.out)" = "$(cat nold.out)" ] || bad "-ld+ long ray differs from -ld-"

{ head -3 rays.txt; echo "1 2 3 nope 0 1"; head -2 rays.txt; } |
    "$RT" -h- -ab 0 "$SCENE" > partial.out 2> e.txt
[ $? -eq 1 ] || bad "bad ray exit status"
[ "$(cat e.txt)" = "rtrace: bad ray at input line 4: 'nope' is not a number" ] || bad "bad ray message: $(cat e.txt)"
[ "$(wc -l < partial.out)" -eq 3 ] || bad "results before the bad ray"
exit $fail
