#!/bin/bash
# Octree instances against RADIANCE: the inst model of ../shared/radiance-tests (RADIANCE's
# frozen porsche.octf placed twice, once keeping its own materials, once overridden by the
# instance's modifier) with a plastic in place of the ashik2 (radiance_scenes.sh runs the
# model with ashik2; tests/data/instance/README.md). Each view must match RADIANCE 5.4's answer by the
# README rule; a missing instance file must stop oconv or rtrace with one line.
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared radiance-tests
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
TESTS="${RP_SHARED_DIR:?RP_SHARED_DIR not set}/radiance-tests"
DATA="$SRC/tests/data/instance"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
cd "$TESTS/renders" || exit 1
export RAYPATH=".:$TESTS/lib"
files=(basic.mat diorama_walls.rad closed_end.rad front_cap.rad "$DATA/shiny.mat"
       "$DATA/porsches_plastic.rad" spotlights.rad rect_fixture.rad glowbulb.rad)
PATH="$BIN:$PATH" "$BIN/oconv" "${files[@]}" > "$tmp/inst.oct" || exit 1
for v in 0 1; do
    "$BIN/rtrace" $(cat "$TESTS/cases/inst.opts") "$tmp/inst.oct" < "$TESTS/cases/inst.v$v.rays" > "$tmp/v$v" || exit 1
    share=$(paste "$tmp/v$v" "$DATA/inst.v$v.ref" | awk '
        { n++; s += ($4 + $5 + $6) / 3; for (k = 1; k <= 6; k++) x[n, k] = $k }
        END { m = s / n; bad = 0
              for (i = 1; i <= n; i++) { d = 0
                  for (k = 1; k <= 3; k++) { e = x[i, k] - x[i, k + 3]; if (e < 0) e = -e
                                             if (e > 0.02 * x[i, k + 3] + 0.01 * m) d = 1 }
                  bad += d }
              printf "%.3f", 1 - bad / n }')
    echo "inst.v$v (plastic for ashik2): $share of rays match RADIANCE"
    awk -v s="$share" 'BEGIN { exit !(s >= 0.98) }' || { echo "FAIL: inst.v$v below 98 %"; fail=1; }
done
# RADIANCE's own octrees as instances, non-frozen (it names its scene file, read relative
# to the current folder as RADIANCE's readoct reads it) and frozen: the same answers as
# RADIANCE gave (distance, normal, material, value).
cd "$DATA" || exit 1
"$BIN/oconv" placed.rad > "$tmp/placed.oct" || fail=1
"$BIN/rtrace" -h -ab 0 -oLnMv "$tmp/placed.oct" < placed.rays > "$tmp/placed.out" || fail=1
if cmp -s "$tmp/placed.out" placed.ref; then
    echo "RADIANCE octrees (frozen and not) as instances: $(wc -l < placed.ref) rays as RADIANCE"
else
    echo "FAIL: RADIANCE octrees as instances differ from RADIANCE"; diff "$tmp/placed.out" placed.ref; fail=1
fi
cd "$TESTS/renders" || exit 1
# A missing instanced octree stops oconv, as RADIANCE's: one line naming the scene file,
# line and octree.
printf 'void instance gone 1 nowhere.oct\n0\n0\n' > "$tmp/gone.rad"
err=$("$BIN/oconv" "$tmp/gone.rad" 2>&1 > "$tmp/gone.oct"); rc=$?
echo "$err"
[ $rc -ne 0 ] || { echo "FAIL: oconv accepted a missing instance file"; fail=1; }
[ "$(echo "$err" | wc -l)" -eq 1 ] || { echo "FAIL: more than one line"; fail=1; }
echo "$err" | grep -q "gone.rad:1: instance 'gone': cannot find octree file 'nowhere.oct'" || { echo "FAIL: message"; fail=1; }
exit $fail
