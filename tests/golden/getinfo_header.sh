#!/bin/bash
# Golden test for getinfo: exact RADIANCE output format (file name line, tab-indented
# header lines, a tab-only line), -d dimensions, standard input, and the error exit for
# files without a RADIANCE header.
set -u
GETINFO="${RP_BIN:?RP_BIN not set}/getinfo"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
check() {  # name expected-file actual-file
    if ! diff -u "$2" "$3"; then
        echo "FAIL: $1"
        fail=1
    fi
}

# A small picture: header, resolution line, one flat scanline of 2 pixels.
printf '#?RADIANCE\nrpict -vf view.vf -x 2 -y 1 scene.oct\nVIEW= -vtv -vp 0 0 0\nEXPOSURE=1.5\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n\200\200\200\201\100\100\100\201' > pic.hdr
# A photon-map-like header with tabs inside lines, as mkpmap writes them.
printf '#?RADIANCE\nmkpmap -apg g.pm 1k x.oct\nNumPhotons\t= 1000\nFORMAT=Radiance_Global_kdT_Photon_Map\n\n\001\002\003' > g.pm
printf 'just some text\n\nmore\n' > plain.txt

printf 'pic.hdr:\n\t#?RADIANCE\n\trpict -vf view.vf -x 2 -y 1 scene.oct\n\tVIEW= -vtv -vp 0 0 0\n\tEXPOSURE=1.5\n\tFORMAT=32-bit_rle_rgbe\n\t\ng.pm:\n\t#?RADIANCE\n\tmkpmap -apg g.pm 1k x.oct\n\tNumPhotons\t= 1000\n\tFORMAT=Radiance_Global_kdT_Photon_Map\n\t\n' > expect_header
"$GETINFO" pic.hdr g.pm > out_header 2> err_header
st=$?
check "header output" expect_header out_header
[ "$st" -eq 0 ] || { echo "FAIL: exit status $st for good files"; fail=1; }
[ -s err_header ] && { echo "FAIL: unexpected stderr"; cat err_header; fail=1; }

printf 'pic.hdr: -Y 1 +X 2\n' > expect_dim
"$GETINFO" -d pic.hdr > out_dim
check "-d output" expect_dim out_dim

printf '#?RADIANCE\nmkpmap -apg g.pm 1k x.oct\nNumPhotons\t= 1000\nFORMAT=Radiance_Global_kdT_Photon_Map\n\n' > expect_stdin
"$GETINFO" < g.pm > out_stdin
check "stdin output" expect_stdin out_stdin

# Not a RADIANCE file and a missing file: one error line each, others still printed,
# non-zero exit at the end.
"$GETINFO" plain.txt missing.hdr pic.hdr > out_err 2> err_err
st=$?
[ "$st" -ne 0 ] || { echo "FAIL: exit status 0 with a non-RADIANCE file"; fail=1; }
printf 'getinfo: plain.txt: not a RADIANCE file\ngetinfo: cannot open missing.hdr\n' > expect_err
check "error messages" expect_err err_err
head -n 1 out_err > out_err_first
printf 'pic.hdr:\n' > expect_err_first
check "later files still printed" expect_err_first out_err_first

# -d on octrees and meshes prints the cube strings stored after the magic number. The
# cube is woman.rtm's: RADIANCE's `getinfo -d woman.rtm` printed the expected line.
printf '#?RADIANCE\nobj2mesh -a woman.mat\nFORMAT=Radiance_tmesh\n\n\001\103-0.35954959\000-0.00265538\000-0.34914834\0000.71904138\000\000' > w.rtm
printf '#?RADIANCE\noconv -f x.rad\nFORMAT=Radiance_octree\n\n\001\037-1.5\0000\0002\00010\000\000' > x.oct
printf 'w.rtm: -0.35954959 -0.00265538 -0.34914834 0.71904138\nx.oct: -1.5 0 2 10\n' > expect_cube
"$GETINFO" -d w.rtm x.oct > out_cube
check "-d cube output" expect_cube out_cube

# Our scene files store no octree: -d prints the cube RADIANCE's oconv would store for the
# scene (oconv.c: bounds grown by 1e-5, largest side). A 2 x 1 x 0.5 box at (1, 2, 3):
# cube side 2.00002 from (1 - 1e-5, 2.5 - 1.00001, 3.25 - 1.00001).
printf 'void plastic p 0 0 5 .5 .5 .5 0 0\np sphere a 0 0 4 1.5 2.5 3.25 .001\np polygon b 0 0 12 1 2 3 3 2 3 3 3 3.5 1 3 3.5\n' > box.rad
"${RP_BIN}/oconv" box.rad > box.oct
"$GETINFO" -d box.oct x.oct > out_scene 2> err_scene || { echo "FAIL: -d on a scene file"; fail=1; }
printf 'box.oct: 0.99999 1.49999 2.24999 2.00002\nx.oct: -1.5 0 2 10\n' > expect_scene_out
check "-d on a scene file" expect_scene_out out_scene
# A damaged scene file: an error line for it, the others still printed, non-zero exit.
printf '#?RADIANCE\noconv x.rad\nFORMAT=radphoton_scene\n\nRPSCENE\000' > s.oct
"$GETINFO" -d s.oct x.oct > out_scene 2> err_scene
st=$?
[ "$st" -ne 0 ] || { echo "FAIL: exit status 0 for -d on a damaged scene file"; fail=1; }
grep -q "^getinfo: s.oct" err_scene && [ "$(wc -l < err_scene)" -eq 1 ] || { echo "FAIL: -d damaged scene file error"; cat err_scene; fail=1; }
printf 'x.oct: -1.5 0 2 10\n' > expect_scene_out
check "-d after a damaged scene file" expect_scene_out out_scene

exit $fail
