#!/bin/bash
# Golden test for mkpmap: small global + caustic maps of the Cornell example, the header
# lines getinfo shows (FORMAT, VERSION, NumPhotons within 5 % of the target), identical
# files for -n 1 and -n 2, refusal to overwrite without -fo, and error exits.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SCENE="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/examples/cornell/scene.rad"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

"$BIN/mkpmap" -apg g.pm 20k -apc c.pm 20k -apr 1 "$SCENE" 2> log || bad "mkpmap exit $?: $(cat log)"
for f in g c; do
    [ -s $f.pm ] || bad "$f.pm missing"
done
"$BIN/getinfo" g.pm > info_g || bad "getinfo g.pm"
"$BIN/getinfo" c.pm > info_c || bad "getinfo c.pm"
grep -q "FORMAT=Radiance_Global_kdT_Photon_Map" info_g || bad "global FORMAT line"
grep -q "FORMAT=Radiance_Caustic_kdT_Photon_Map" info_c || bad "caustic FORMAT line"
grep -q "VERSION=3.1k" info_g || bad "VERSION line"
grep -q "mkpmap -apg g.pm 20k -apc c.pm 20k -apr 1" info_g || bad "command line in header"
for f in info_g info_c; do
    n=$(awk -F'= ' '/NumPhotons/ {print $2}' $f)
    [ -n "$n" ] && [ "$n" -ge 19000 ] && [ "$n" -le 21000 ] || bad "$f: NumPhotons $n not within 5 % of 20000"
done
grep -q "AvgFlux" info_g && grep -q "Bbox" info_g && grep -q "CoG" info_g && grep -q "MaxDist^2" info_g \
    || bad "statistics lines"

# Same seed, two threads: bit-identical files.
"$BIN/mkpmap" -apg g2.pm 20k -apc c2.pm 20k -apr 1 -n 2 "$SCENE" 2> /dev/null || bad "mkpmap -n 2"
# Headers differ by the command line only; compare the binary parts.
strip() { awk 'f {print} /^$/ && !f {f=1}' "$1" | od -An -tx1; }
[ "$(strip g.pm)" = "$(strip g2.pm)" ] || bad "-n 1 and -n 2 global maps differ"
[ "$(strip c.pm)" = "$(strip c2.pm)" ] || bad "-n 1 and -n 2 caustic maps differ"

# Existing output without -fo: exit 1, one line, file kept.
cp g.pm keep.pm
"$BIN/mkpmap" -apg g.pm 1k "$SCENE" 2> err; st=$?
[ $st -eq 1 ] || bad "overwrite refusal exit $st"
grep -qx "mkpmap: photon map file g.pm exists, not overwritten" err || bad "overwrite message: $(cat err)"
cmp -s g.pm keep.pm || bad "g.pm changed"
"$BIN/mkpmap" -fo -apg g.pm 1k "$SCENE" 2> /dev/null || bad "-fo overwrite"

# Error exits: one line "mkpmap: ...", status 1.
expect_error() {  # pattern args...
    local pat="$1"; shift
    "$BIN/mkpmap" "$@" > out 2> err; local st=$?
    [ $st -eq 1 ] || bad "exit $st for: $*"
    [ "$(wc -l < err)" -eq 1 ] || bad "not one line for: $* -> $(cat err)"
    grep -q "^mkpmap: .*$pat" err || bad "message for: $* -> $(cat err)"
}
expect_error "unknown option '-apx'" -apx x.pm 1k "$SCENE"
expect_error "missing value" -apg
expect_error "no photon maps specified" -n 2 "$SCENE"
expect_error "no scattering medium in the scene" -apv v.pm 1k "$SCENE"
expect_error "mutually exclusive" -ai a -ae b -apg n.pm 1k "$SCENE"
expect_error "not antimatter" -apg n.pm 1k -aps white "$SCENE"
[ -e n.pm ] && bad "n.pm written despite errors"
exit $fail
