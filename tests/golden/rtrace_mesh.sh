#!/bin/bash
# Meshes against RADIANCE: our obj2mesh converts the OBJ files of tests/data/obj2mesh, our
# rtrace traces the rays RADIANCE traced on the same meshes (README there), and every ray
# must give RADIANCE's first hit (distance, point, unperturbed normal, modifier: -oLpNM;
# void triangles are reported as RADIANCE reports them) and, on meshes whose material
# shows Lu and Lv, RADIANCE's (u, v) (-ov). Misses must be misses.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
D="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/obj2mesh"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
# Column-wise comparison of numbers (relative 1e-4) and of the words.
same() {  # same NAME OURS REFERENCE COLUMNS
    paste "$2" "$3" | awk -v name="$1" -v nc="$4" '
        { n++; for (k = 1; k <= nc; k++) { a = $k; b = $(k + nc)
              if (a ~ /^[-0-9.e+]+$/) { e = a - b; if (e < 0) e = -e; m = b < 0 ? -b : b
                                        if (e > 1e-4 * (1 + m)) bad++ }
              else if (a != b) bad++ } }
        END { printf "%s: %d rays, %d differences\n", name, n, bad; exit bad > 0 || n == 0 }'
}
for m in cube grid dense; do
    mat=(); [ $m = dense ] || mat=(-a "$D/cube.rad")
    "$BIN/obj2mesh" "${mat[@]}" "$D/$m.obj" $m.rtm 2>/dev/null || { echo "FAIL: obj2mesh $m"; fail=1; continue; }
    echo "void mesh m 1 $m.rtm 0 0" > $m.rad
    if [ $m = dense ]; then "$BIN/oconv" $m.rad > $m.oct; else "$BIN/oconv" "$D/cube.rad" $m.rad > $m.oct; fi
    "$BIN/rtrace" -h -oLpNM $m.oct < "$D/$m.rays" > $m.out || fail=1
    same "$m -oLpNM" $m.out "$D/$m.rtrace_LpNM" 8 || fail=1
done
for m in cube grid; do
    "$BIN/obj2mesh" -a "$D/uv.rad" "$D/$m.obj" ${m}_uv.rtm 2>/dev/null || fail=1
    echo "void mesh m 1 ${m}_uv.rtm 0 0" > ${m}_uv.rad
    "$BIN/oconv" ${m}_uv.rad > ${m}_uv.oct
    "$BIN/rtrace" -h -w -ab 0 -ov ${m}_uv.oct < "$D/$m.rays" > ${m}_uv.out || fail=1
    same "$m (u, v)" ${m}_uv.out "$D/$m.rtrace_uv" 3 || fail=1
done
# A mesh file that is cut short: one line naming the mesh primitive and the file.
head -c 700 grid.rtm > cut.rtm
echo "void mesh cut 1 cut.rtm 0 0" > cut.rad
"$BIN/oconv" cut.rad > cut.oct
err=$("$BIN/rtrace" -h cut.oct < /dev/null 2>&1); rc=$?
echo "$err"
[ $rc -ne 0 ] && [ "$(echo "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q "cut.rad:1: mesh 'cut': .*cut.rtm" ||
    { echo "FAIL: truncated mesh"; fail=1; }
# Photons land on meshes; a map older than a mesh the scene places is stale.
cat > lit.rad <<'END'
void plastic white 0 0 5 .6 .6 .6 0 0
white mesh m 1 grid.rtm 0 0
void light lamp 0 0 3 100 100 100
lamp sphere bulb 0 0 4 0 0 3 .1
END
"$BIN/oconv" lit.rad > lit.oct
"$BIN/mkpmap" -apg lit.pm 2k lit.oct 2>/dev/null || { echo "FAIL: mkpmap on a mesh"; fail=1; }
n=$("$BIN/pmapdump" -a lit.pm 2>/dev/null | grep -c .)
echo "photons stored on the mesh: $n"
[ "$n" -gt 1000 ] || { echo "FAIL: too few photons on the mesh"; fail=1; }
touch -d "@$(( $(date +%s) + 5 ))" grid.rtm
err=$(echo "0 0 2 0 0 -1" | "$BIN/rtrace" -h -ab 1 -ap lit.pm 50 lit.oct 2>&1 >/dev/null); rc=$?
echo "$err"
[ $rc -ne 0 ] && echo "$err" | grep -q "older than scene file .*grid.rtm" || { echo "FAIL: stale map not noticed"; fail=1; }
exit $fail
