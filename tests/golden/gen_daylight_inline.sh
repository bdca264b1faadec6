#!/usr/bin/env bash
# ../shared/validation/daylight rebuilt with a `!gensky` line in place of the pasted
# gensky output (lines 6-24) gives the same photon map, byte for byte after the header
# (same seed), as the pasted scene: our gensky writes what RADIANCE's wrote, and scene
# files run it in-process.
set -euo pipefail
. "$(dirname "$0")/lib/shared.sh"
require_shared validation/daylight
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
src="$RP_SHARED_DIR/validation/daylight/scene.rad"
{ sed -n '1,5p' "$src"; echo '!gensky 3 21 12 -a 47 -o -8 -m -15 +s'; sed -n '25,$p' "$src"; } \
    > "$tmp/inline.rad"
grep -q '^void brightfunc skyfunc' "$tmp/inline.rad" && { echo "gensky block not removed"; exit 1; }
for s in pasted inline; do
    f=$src; [ $s = inline ] && f=$tmp/inline.rad
    PATH=/nonexistent "$RP_BIN/mkpmap" -apg "$tmp/$s.pm" 20k -apo window_glass -aps sensor_plane \
        -apr 5 -n 2 "$f" > /dev/null 2>&1
done
skip() { head -n "$(awk '/^$/ {print NR; exit}' "$1")" "$1" | wc -c; }
cmp -i "$(skip "$tmp/pasted.pm"):$(skip "$tmp/inline.pm")" "$tmp/pasted.pm" "$tmp/inline.pm"
echo "daylight with !gensky: identical photon map"
