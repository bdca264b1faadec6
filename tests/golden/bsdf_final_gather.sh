#!/bin/bash
# A BSDF window seen by the final gather (issue 43): at a final-gather hit the BSDF's
# non-diffuse direct light is computed (RADIANCE ambRayInPmap: only rays below the first
# gather bounce, rlvl > 1, leave it to the photons), since the light a window sends
# straight to the gathering point is in no photon. The sunlit room of
# tests/data/cycles_blinds with the handcrafted tensor tree tests/data/bsdf/ttree4.xml as
# a film in the opening, either way round, a global map through an antimatter port:
# `rtrace -I -ab 1 -ap g.pm 100` against classic `-ab 16 -lr -20`, both -ad 8192 -lw 1e-5,
# at five points (three facing the window, two facing up): the mean within 5 %, each within
# 10 %. Over 10-15 runs with -u+ the gather spreads 0.3-1.2 %, the classic 0.5-1.9 %, and
# the mean differences per point are -1.9 to +1.0 %: 10 % is over 3.5 sigma; -u- keeps the
# run reproducible (at the default -lw the gather keeps only about 1250 rays and spread
# 1.3-2.7 %, which left a point 2.4 sigma from failing). Before the fix the
# photon map read 3 to 5 times too low, and sensors beside a Klems window in LBNL's
# tutorial room half of RADIANCE's.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/bsdf_window"
export RAYPATH="$SRC/tests/data/bsdf:$SRC/lib"
fail=0
for side in in out; do
    "$BIN/oconv" "$SRC/tests/data/cycles_blinds/room_open.rad" "$data/window_$side.rad" \
        "$data/port.rad" > "$tmp/o.oct" || exit 1
    "$BIN/mkpmap" -apg "$tmp/g.pm" 1m -apo port_mat -apr 1 -n 2 -fo "$tmp/o.oct" 2> "$tmp/err" ||
        { echo "FAIL $side: mkpmap: $(cat "$tmp/err")"; fail=1; continue; }
    "$BIN/rtrace" -h -u- -I -ab 1 -ad 8192 -lw 1e-5 -aa 0 -ap "$tmp/g.pm" 100 -n 2 "$tmp/o.oct" \
        < "$data/points.txt" | awk '{print $1}' > "$tmp/pm"
    "$BIN/rtrace" -h -u- -I -ab 16 -lr -20 -ad 8192 -aa 0 -lw 1e-5 -n 2 "$tmp/o.oct" \
        < "$data/points.txt" | awk '{print $1}' > "$tmp/cl"
    paste "$tmp/pm" "$tmp/cl" | awk -v side=$side '{
        d = $1 / $2 - 1; a += $1; b += $2
        printf "film normal %s: photon map %.2f, classic %.2f (%+.1f %%)\n", side, $1, $2, 100 * d
        if (d > 0.10 || d < -0.10) bad = 1
    } END {
        d = a / b - 1; printf "film normal %s: means %+.1f %%\n", side, 100 * d
        if (bad || d > 0.05 || d < -0.05) { print "FAIL"; exit 1 }
    }' || fail=1
done
exit $fail
