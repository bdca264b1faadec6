#!/bin/bash
# End-to-end test of pmapdump on real maps (mkpmap on the Cornell example): sphere counts
# near the -n target, the three output forms, total flux of -f -a equal to the map's
# NumPhotons x AvgFlux (getinfo) within 1 %, identical output on repeated runs, one PLY
# with the vertices of both maps.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SCENE="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/examples/cornell/scene.rad"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

"$BIN/mkpmap" -apg g.pm 4k -apc c.pm 2k "$SCENE" 2> log || { echo "FAIL: mkpmap: $(cat log)"; exit 1; }
ng=$("$BIN/getinfo" g.pm | awk -F'= ' '/NumPhotons/ {print $2}')
nc=$("$BIN/getinfo" c.pm | awk -F'= ' '/NumPhotons/ {print $2}')

# Scene: one glow per map, spheres ~ Binomial(ng, 1000/ng) (sd < 32: 5 sigma = 160) for g,
# all photons for c (-n above its count).
"$BIN/pmapdump" -n 1000 g.pm -n 1M c.pm > scene.rad 2> err || bad "scene exit: $(cat err)"
[ "$(grep -c '^void glow mat.global$' scene.rad)" -eq 1 ] || bad "global material"
[ "$(grep -c '^void glow mat.caustic$' scene.rad)" -eq 1 ] || bad "caustic material"
sg=$(grep -c '^mat.global sphere obj.global$' scene.rad)
sc=$(grep -c '^mat.caustic sphere obj.caustic$' scene.rad)
[ "$sg" -ge 840 ] && [ "$sg" -le 1160 ] || bad "global spheres $sg not near 1000"
[ "$sc" -eq "$nc" ] || bad "caustic spheres $sc, map has $nc"
"$BIN/pmapdump" -n 1000 g.pm -n 1M c.pm | cmp -s - scene.rad || bad "output not reproducible"

# -f -a with every photon: flux summed over lines = NumPhotons x AvgFlux within 1 %.
"$BIN/pmapdump" -a -f -n "$ng" g.pm > g.txt || bad "ascii exit"
[ "$(wc -l < g.txt)" -eq "$ng" ] || bad "ascii lines $(wc -l < g.txt), want $ng"
awk -F'\t' 'NF != 6 { bad = 1 } END { exit bad }' g.txt || bad "ascii lines without 6 fields"
"$BIN/getinfo" g.pm | awk -F'[][,]' '/AvgFlux/ {print $2, $3, $4}' > avg
awk -v n="$ng" 'NR == FNR { a[1] = $1; a[2] = $2; a[3] = $3; next }
    { for (c = 1; c <= 3; c++) s[c] += $(c + 3) }
    END { for (c = 1; c <= 3; c++) { t = n * a[c]; d = s[c] - t; if (d < 0) d = -d;
          if (d > 0.01 * t) { print "channel " c ": " s[c] " vs " t; exit 1 } } }' avg g.txt \
    || bad "-f -a total flux"

# PLY with both maps: all vertices, 15 bytes each after the header.
"$BIN/pmapdump" -P -n 1M g.pm -P -f -n 1M c.pm > both.ply 2> err || bad "ply exit: $(cat err)"
grep -aq "^element vertex $((ng + nc))\$" both.ply || bad "ply vertex count"
hdr=$(grep -abo 'end_header' both.ply | head -n 1 | cut -d: -f1)
size=$(wc -c < both.ply)
[ "$size" -eq $((hdr + 11 + 15 * (ng + nc))) ] || bad "ply size $size"

exit $fail
