#!/usr/bin/env bash
# Scene files with !gensky, !genbox | xform, !genblinds, !genrev, !gensurf and !genworm
# lines compile with oconv on a machine where no RADIANCE generator is on PATH (ours run
# in-process), and give the same records as the generators' own output pasted in.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cat > inline.rad <<'RAD'
!gensky 3 21 12 -a 47 -o -8 -m -15 +s
skyfunc glow sky_mat
0
0
4 1 1 1 0
sky_mat source sky
0
0
4 0 0 1 180
void plastic wall
0
0
5 .5 .5 .5 0 0
!genbox wall room 4 5 3 -i | xform -t 1 2 0
!genblinds wall slats 0.1 1 1 5 30 -r 0.2 | xform -t 3 5 0.5
!genrev wall post 't' '0.1+0.05*t' 3 | xform -t 4 5.5 0
!genworm wall rope 2.5 '5+t' '0.5+t' 0.03 4
!gensurf wall tarp '2+s' '6+t' '2+0.2*s*t' 3 3
RAD
{
  "$RP_BIN/gensky" 3 21 12 -a 47 -o -8 -m -15 +s
  sed -n '2,13p' inline.rad
  "$RP_BIN/genbox" wall room 4 5 3 -i | "$RP_BIN/xform" -t 1 2 0
  "$RP_BIN/genblinds" wall slats 0.1 1 1 5 30 -r 0.2 | "$RP_BIN/xform" -t 3 5 0.5
  "$RP_BIN/genrev" wall post 't' '0.1+0.05*t' 3 | "$RP_BIN/xform" -t 4 5.5 0
  "$RP_BIN/genworm" wall rope 2.5 '5+t' '0.5+t' 0.03 4
  "$RP_BIN/gensurf" wall tarp '2+s' '6+t' '2+0.2*s*t' 3 3
} > pasted.rad
PATH=/nonexistent "$RP_BIN/oconv" inline.rad > inline.oct
"$RP_BIN/oconv" pasted.rad > pasted.oct
# Same geometry and materials: identical previews from inside the room (PNG holds no
# command line, unlike the pictures' headers).
for f in inline pasted; do
  "$RP_BIN/rpreview" -vp 3 3 1.5 -vd 0.3 1 -0.2 -vh 90 -vv 90 -x 48 -y 48 -o $f.hdr $f.oct 2>/dev/null
  "$RP_BIN/ra_png" -e 1 $f.hdr $f.png
done
cmp inline.png pasted.png
grep -q "^FORMAT=Radiance_octree" inline.oct
echo "builtin generators: ok"
