#!/usr/bin/env bash
# rpict renders a small lit box: RADIANCE's header lines (command line without the scene,
# SOFTWARE=, VIEW=, FORMAT=), the size rule for non-square views, a picture that reads
# back, a z-file of one float per pixel, the same pixels for -n 1 and -n 2 and for -o and
# standard output, and one-line "rpict: ..." errors with exit status 1.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cat > box.rad <<'RAD'
void light bright
0
0
3 10 10 10

void plastic white
0
0
5 .7 .7 .7 0 0

!genbox white room 4 4 3 -i

bright polygon lamp
0
0
12 1.5 1.5 2.9  1.5 2.5 2.9  2.5 2.5 2.9  2.5 1.5 2.9
RAD
view="-vp 2 0.5 1.5 -vd 0 1 0 -vu 0 0 1 -vh 90 -vv 90"

"$RP_BIN/rpict" $view -x 32 -y 32 -z a.z -o a.hdr box.rad
[ "$("$RP_BIN/getinfo" -d a.hdr)" = "a.hdr: -Y 32 +X 32" ]
"$RP_BIN/getinfo" a.hdr > info
grep -q "^	rpict -vp 2 0.5 1.5 -vd 0 1 0 -vu 0 0 1 -vh 90 -vv 90 -x 32 -y 32 -z a.z -o a.hdr$" info
grep -q "^	SOFTWARE= radphoton" info
grep -q "^	VIEW= -vtv -vp 2 0.5 1.5 -vd 0 1 0 -vu 0 0 1 -vh 90 -vv 90 -vo 0 -va 0 -vs 0 -vl 0$" info
grep -q "^	FORMAT=32-bit_rle_rgbe$" info
if grep -q PIXASPECT info; then exit 1; fi
[ "$(wc -c < a.z)" -eq $((32 * 32 * 4)) ]
"$RP_BIN/ra_png" a.hdr a.png   # reads the whole picture back
[ -s a.png ]
ls > files; [ "$(wc -l < files)" -eq 6 ]   # box.rad a.hdr a.z info a.png files: no temporaries

# Same pixels and depths with two threads and on standard output (header dates may differ).
"$RP_BIN/rpict" $view -x 32 -y 32 -n 2 -z b.z box.rad > b.hdr  # -z: depth also guides sampling
sed '1,/^$/d' a.hdr > a.pix; sed '1,/^$/d' b.hdr > b.pix
cmp -s a.pix b.pix; cmp -s a.z b.z

# A wider view keeps its aspect: 32 wide, 32 * tan(30)/tan(45) + .5 = 18 high.
"$RP_BIN/rpict" -vp 2 0.5 1.5 -vd 0 1 0 -vh 90 -vv 60 -x 32 -y 32 box.rad > c.hdr
[ "$("$RP_BIN/getinfo" -d < c.hdr)" = "-Y 18 +X 32" ]
# -pa 0 keeps the resolution and records the pixel aspect.
"$RP_BIN/rpict" -vp 2 0.5 1.5 -vd 0 1 0 -vh 90 -vv 60 -x 32 -y 32 -pa 0 box.rad > d.hdr
[ "$("$RP_BIN/getinfo" -d < d.hdr)" = "-Y 32 +X 32" ]
grep -a -q "^PIXASPECT=0.57" d.hdr

"$RP_BIN/rpict" -defaults | grep -q "^-ps 4 "

expect_error() {  # pattern, then the command's arguments
    local pattern=$1; shift
    if "$RP_BIN/rpict" "$@" > out 2> err; then echo "rpict $* should fail"; exit 1; fi
    [ "$(wc -l < err)" -eq 1 ] || { cat err; exit 1; }
    grep -q "^rpict: .*$pattern" err || { cat err; exit 1; }
}
expect_error "unknown option '-q'" -q box.rad
expect_error "missing scene" $view -x 8 -y 8
expect_error "" -vf no_such_view.vf box.rad
expect_error "" -vd 0 0 0 box.rad
expect_error "" -x 8 -y 8 no_such_scene.rad
expect_error "" $view -x 8 -y 8 -o no/such/dir/x.hdr box.rad
[ ! -e no ]
echo "rpict golden: ok"
