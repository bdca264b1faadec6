#!/usr/bin/env bash
# rad end to end with our own tools (tests/data/rad/run: a small lit room, a global
# photon map, two views, an ambient file): the first run makes the octree, the map, both
# pictures (supersampled by rpict, reduced by pfilt, raw files removed); a second run
# finds everything up to date and runs nothing; a changed scene file makes it all again
# and drops the ambient file; -t only updates dates; a missing map is made alone; -N 2
# renders both views in parallel into the same pictures.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cp "$RP_SOURCE_DIR"/tests/data/rad/run/* "$tmp/"
cd "$tmp"
export PATH="$RP_BIN:$PATH"
fail=0
check() { eval "$1" || { echo "FAIL: $2"; fail=1; }; }

rad room.rif > first.txt 2> first.err
check '[ "$(grep -c "^	" first.txt)" -eq 10 ]' "first run (oconv, mkpmap, overture, rpict, pfilt, rm per view): $(cat first.txt)"
for v in in up; do
    check '[ -f room_$v.hdr ] && [ ! -f room_$v.unf ]' "picture room_$v.hdr"
done
check '[ "$(getinfo -d < room_in.hdr)" = "-Y 16 +X 24" ]' "room_in.hdr size $(getinfo -d < room_in.hdr)"
check 'getinfo room_in.hdr | grep -q "^	pfilt -r .6 -x /2 -y /2"' "pfilt in the picture's header"
check '[ -f room.amb ] && [ -f room.gpm ] && [ -f room.oct ]' "octree, map and ambient file"

rad room.rif > second.txt
check '[ ! -s second.txt ]' "second run should do nothing: $(cat second.txt)"

sleep 0.05; touch room.rad
rad room.rif > third.txt 2> /dev/null
check 'grep -q "^	oconv room.rad > room.oct" third.txt' "oconv after a scene change"
check 'grep -q "^	mkpmap -fo+ -apg room.gpm 5k room.oct" third.txt' "mkpmap after a scene change"
check 'grep -q "^	rm -f room.amb" third.txt' "ambient file dropped: $(cat third.txt)"
check '[ "$(grep -c "> room_.*.unf" third.txt)" -eq 2 ]' "both views again"

sleep 0.05; touch room.rad
rad -t room.rif > touch.txt
check '[ "$(grep -c "^	touch" touch.txt)" -ge 3 ] && ! grep -q "rpict\|oconv" touch.txt' \
    "-t: $(cat touch.txt)"
rad room.rif > after_touch.txt
check '[ ! -s after_touch.txt ]' "after -t nothing is stale: $(cat after_touch.txt)"

rm room.gpm
rad room.rif > map.txt 2> /dev/null
check 'head -1 map.txt | grep -q "^	mkpmap -fo+ -apg room.gpm 5k room.oct"' "missing map: $(cat map.txt)"
check '[ "$(grep -c "> room_.*.unf" map.txt)" -eq 2 ]' "pictures again with the new map"

rm room_in.hdr room_up.hdr
rad -N 2 room.rif > par.txt 2> /dev/null
check '[ -f room_in.hdr ] && [ -f room_up.hdr ]' "-N 2 pictures"
check '[ "$(getinfo -d < room_up.hdr)" = "-Y 16 +X 16" ]' "room_up.hdr size"
rm room_up.hdr
rad -N 2 -v up room.rif > one.txt 2> /dev/null
check 'grep -q "^	rpict -n 2 -vp 2 1.5 1" one.txt' "one view with -N: rpict -n: $(cat one.txt)"
exit $fail
