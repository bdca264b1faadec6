#!/bin/bash
# Golden test for mkpmap -app/-apP (precomputed global map) and -apC (contribution map):
# the header lines getinfo shows (FORMAT, VERSION, NumPhotons = -apP x target within 5 %,
# "<k> primary rays" for contribution maps), identical files for -n 1 and -n 2, the
# "N precomputed" progress line, and -apC ignoring other maps with a warning.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
. "$(dirname "$0")/lib/shared.sh"
require_shared validation/contrib/scene.rad
FURNACE="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/furnace/scene.rad"
CONTRIB="$RP_SHARED_DIR/validation/contrib/scene.rad"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }
strip() { awk 'f {print} /^$/ && !f {f=1}' "$1" | od -An -tx1; }
count() { awk -F'= ' '/NumPhotons/ {print $2}' "$1"; }

# Precomputed: 40k global photons, -apP 0.5 -> ~20k precomputed.
"$BIN/mkpmap" -app p.pm 40k 50 -apP 0.5 -apr 1 -t 1 "$FURNACE" 2> log || bad "mkpmap -app exit $?: $(cat log)"
"$BIN/getinfo" p.pm > info_p || bad "getinfo p.pm"
grep -q "FORMAT=Radiance_PreComp_kdT_Photon_Map" info_p || bad "precomp FORMAT line"
grep -q "VERSION=3.1k" info_p || bad "precomp VERSION line"
grep -q "mkpmap -app p.pm 40k 50 -apP 0.5 -apr 1" info_p || bad "command line in header"
n=$(count info_p)
[ -n "$n" ] && [ "$n" -ge 19000 ] && [ "$n" -le 21000 ] || bad "precomp NumPhotons $n not within 5 % of 20000"
grep -q "primary rays" info_p && bad "primary rays in a precomputed map"
grep -Eq "^[0-9]+ precomputed, [0-9.]+% after [0-9.]+ hours" log || bad "no precomputed progress line: $(cat log)"
"$BIN/mkpmap" -app p2.pm 40k 50 -apP 0.5 -apr 1 -n 2 "$FURNACE" 2> /dev/null || bad "mkpmap -app -n 2"
[ "$(strip p.pm)" = "$(strip p2.pm)" ] || bad "-n 1 and -n 2 precomputed maps differ"

# Contribution map: 3 lamps, ~30k photons, primaries line; other maps ignored.
"$BIN/mkpmap" -apC c.pm 30k -apg ig.pm 10k -apr 1 "$CONTRIB" 2> log || bad "mkpmap -apC exit $?: $(cat log)"
[ -e ig.pm ] && bad "ig.pm written although -apC ignores other maps"
grep -q "warning: ignoring Global photon map ig.pm" log || bad "no ignore warning: $(cat log)"
"$BIN/getinfo" c.pm > info_c || bad "getinfo c.pm"
grep -q "FORMAT=Radiance_Contrib_kdT_Photon_Map" info_c || bad "contrib FORMAT line"
grep -q "VERSION=3.1k" info_c || bad "contrib VERSION line"
n=$(count info_c)
[ -n "$n" ] && [ "$n" -ge 28500 ] && [ "$n" -le 31500 ] || bad "contrib NumPhotons $n not within 5 % of 30000"
k=$(awk '/ primary rays$/ {print $1}' info_c)
[ -n "$k" ] && [ "$k" -gt 0 ] && [ "$k" -lt "$n" ] || bad "primary rays line: '$k'"
"$BIN/mkpmap" -apC c2.pm 30k -apr 1 -n 2 "$CONTRIB" 2> /dev/null || bad "mkpmap -apC -n 2"
[ "$(strip c.pm)" = "$(strip c2.pm)" ] || bad "-n 1 and -n 2 contribution maps differ"
exit $fail
