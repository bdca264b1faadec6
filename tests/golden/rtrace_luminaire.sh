#!/bin/bash
# A luminaire with an intensity table (RADIANCE's rect_fixture: brightdata `flatcorr` of
# source.cal over rect_fixture.dat, its pattern transform in inches and turned -rz 90)
# 3 m above a floor: rtrace -I -ab 0 at 0-65 degrees off nadir along both fixture axes
# and on two diagonals, with and without the -rz 90, against RADIANCE 5.4's answers.
# Tolerance 2 %; we agree within 0.05 %. Before the pattern saw unit directions through
# the transform's scale, the table was read at 0 degrees everywhere: 1.5x RADIANCE at 45
# degrees, 4-7x at 60-65, and the -rz 90 changed nothing.
# Reference (RADIANCE 5.4, same scene and points, $rad the RADIANCE install):
#   RAYPATH=.:$rad/lib rtrace -h -I -ab 0 -ds 0.05 -dj 0 -dt 0 -dc 1 fixture.oct < points
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared radiance-tests
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
LIB="${RP_SHARED_DIR:?RP_SHARED_DIR not set}/radiance-tests"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

cp "$LIB/lib/source.cal" . || exit 1
# The table without its comment line (data-file comments are another test's subject).
grep -v '^#' "$LIB/renders/rect_fixture.dat" > fixture.dat || exit 1
scene() {  # $1: the pattern's turn ("-rz 90" or nothing), $2: its string count
    cat <<SCENE
void brightdata lum_dist
$2 flatcorr fixture.dat source.cal src_phi4 src_theta
	-s 0.0253999863 $1 -t -4 2.5 2.999
0
0
lum_dist light lum_bright
0
0
3 20 20 20
lum_bright polygon luminaire
0
0
12
	-3.42215031167 2.22695014727 2.999
	-4.57784968833 2.22695014728 2.999
	-4.57784968833 2.77304985273 2.999
	-3.42215031167 2.77304985272 2.999
void plastic grey
0
0
5 .5 .5 .5 0 0
grey polygon floor
0
0
12 -20 -20 0  20 -20 0  20 20 0  -20 20 0
SCENE
}
scene "" 11 > plain.rad
scene "-rz 90" 13 > turned.rad

# x y, RADIANCE's irradiance without and with -rz 90. Rows: nadir, then 30 45 60 65
# degrees off nadir along x, the same along y, then 45 and 60 degrees at azimuths 30
# and 60 degrees.
cat > ref.txt <<'REF'
-4.000000 2.500000 1.136427e+00 1.132215e+00
-2.268527 2.500000 7.260146e-01 6.491504e-01
-1.001000 2.500000 2.778532e-01 2.387454e-01
1.194420 2.500000 3.602040e-02 3.309794e-02
2.431376 2.500000 1.375338e-02 1.290457e-02
-4.000000 4.231473 6.418266e-01 7.127452e-01
-4.000000 5.499000 2.292335e-01 2.633719e-01
-4.000000 7.694420 3.163990e-02 3.430368e-02
-4.000000 8.931376 1.257160e-02 1.337669e-02
-1.402790 3.999500 2.615734e-01 2.488810e-01
0.498500 5.097210 2.997434e-02 2.901547e-02
-2.500500 5.097210 2.415879e-01 2.557093e-01
-1.402790 6.998500 2.851492e-02 2.951865e-02
REF
awk '{ print $1, $2, 0.001, 0, 0, 1 }' ref.txt > points.txt

col=3
for s in plain turned; do
    "$BIN/oconv" "$s.rad" > "$s.oct" 2> oconv.err || bad "oconv $s: $(head -1 oconv.err)"
    RAYPATH=".:$SRC/lib" "$BIN/rtrace" -h -I -ab 0 -ds 0.05 -dj 0 -dt 0 -dc 1 "$s.oct" \
        < points.txt > "$s.txt" 2> rtrace.err || bad "rtrace $s: $(head -1 rtrace.err)"
    # ref.txt's column $col beside our red channel (column 5).
    worst=$(paste ref.txt "$s.txt" | awk -v c=$col '{ r = $5 / $(c); d = r > 1 ? r - 1 : 1 - r
        if (d > w) { w = d; at = "at " $1 " " $2 ": ratio " r } }
        END { if (NR != 13) print "rows " NR; else print w + 0, at }')
    echo "$s: worst ours/RADIANCE deviation $worst"
    awk -v w="${worst%% *}" 'BEGIN { exit !(w == w + 0 && w <= 0.02) }' ||
        bad "$s: beyond 2 % of RADIANCE: $worst"
    col=4
done
exit $fail
