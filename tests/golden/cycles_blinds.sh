#!/bin/bash
# Against an independent path tracer (issue 42): Blender Cycles' converged irradiance
# (tests/data/cycles_blinds, 0.18 % standard error at worst) on a room lit by the sun
# alone through an open window, without and with 45 Lambertian slats. 80 work-plane
# sensors and a ceiling point facing down; means and per-sensor mean absolute relative
# errors (MARE):
# - direct light, -dj 1 with 16384 rays per sensor (the sun disk sampled, penumbrae through
#   the slats): mean within 1 %, MARE of the sunlit sensors within 1.5 % (measured -0.1 %,
#   0.3 %; the binomial noise of 16384 rays alone makes about 0.5 %). The sensors are
#   moved 1e-4 back along their normals: rtrace -I evaluates 1e-4 in front of the point,
#   as RADIANCE does, and behind the slats the light changes by 5 % per mm.
# - indirect light (total - direct, both -dj 0 so the direct parts cancel), classic with
#   every bounce (-ab 16 -lr -20; RADIANCE's default -lr -10 stops ten reflections deep and
#   reads 1.6 % low here): within 2 % (measured -0.1 %, -0.3 %);
# - the same from a global photon map through an antimatter port, 2M photons at bandwidth
#   100: in the open room (measured -0.2 %) within 2.5 %; with the slats RADIANCE's
#   estimate reads -5.7 % (MARE 4.3 %: the search discs reach past the 2.5 cm slats'
#   edges), which must be below -4 %, and -ape's -0.6 % (MARE 1.8 %), within 2.5 %
#   (10M photons at bandwidth 40: -0.65 % and +0.9 %).
# Over 8 runs with -u+ the means spread (standard deviation) 0.2 % (direct), 0.6 %
# (classic) and 0.15 % (photon map): the classic's 2 % is 3 sigma past its worst mean;
# -u- keeps the run reproducible.
# Before the fixes of issue 42 the lit sensors behind the slats read 435 and 387 for 514
# and 297, and a global map through an antimatter port counted the sun twice.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
ref="$SRC/tests/data/cycles_blinds"
pts="$SRC/tests/data/cycles_blinds/points.txt"
fail=0
printf 'void antimatter port_mat 1 void 0 0\nport_mat polygon port 0 0 12 .5 0 1  .5 0 2  3.5 0 2  3.5 0 1\n' \
    > "$tmp/port.rad"
awk '{printf "%.4f %.4f %.4f %s %s %s\n", $1 - 1e-4 * $4, $2 - 1e-4 * $5, $3 - 1e-4 * $6, $4, $5, $6}' \
    "$pts" > "$tmp/low.txt"
# compare LABEL OURS REF_TOTAL REF_DIRECT KIND TOL [MARE_TOL]: KIND direct or indirect;
# for indirect OURS holds "total direct" per sensor.
compare() {
    paste "$2" "$3" "$4" | awk -v label="$1" -v kind="$5" -v tol="$6" -v mtol="${7:-1}" '{
        if (kind == "direct") { o = $1; c = $4 } else { o = $1 - $2; c = $3 - $5 }
        so += o; sc += c
        if (c > 0.5) { d = (o - c) / c; m += d < 0 ? -d : d; k++ }
    } END {
        e = so / sc - 1
        printf "%-28s ours %8.3f  Cycles %8.3f  (%+.2f %%, MARE %.2f %%)\n", label, so / NR, sc / NR, 100 * e, 100 * m / k
        if (e > tol || e < -tol || m / k > mtol) { print "FAIL"; exit 1 }
    }'
}
for v in open blinds; do
    files="$ref/room_open.rad"
    [ $v = blinds ] && files="$files $ref/slats_lambertian.rad"
    "$BIN/oconv" $files "$tmp/port.rad" > "$tmp/$v.oct" || exit 1
    awk '{for (i = 0; i < 16384; i++) print}' "$tmp/low.txt" |
        "$BIN/rtrace" -h -u- -I -ab 0 -dj 1 -n 2 "$tmp/$v.oct" |
        awk '{s += $1; if (NR % 16384 == 0) {printf "%.6f\n", s / 16384; s = 0}}' > "$tmp/dj1"
    compare "$v: direct -dj 1" "$tmp/dj1" "$ref/${v}_total.txt" "$ref/${v}_direct.txt" direct 0.01 0.015 || fail=1
    "$BIN/rtrace" -h -I -ab 0 "$tmp/$v.oct" < "$pts" | awk '{print $1}' > "$tmp/d0"
    "$BIN/rtrace" -h -u- -I -ab 16 -lr -20 -ad 1024 -aa 0 -lw 1e-5 -n 2 "$tmp/$v.oct" < "$pts" |
        awk '{print $1}' | paste - "$tmp/d0" > "$tmp/cl"
    compare "$v: indirect, classic" "$tmp/cl" "$ref/${v}_total.txt" "$ref/${v}_direct.txt" indirect 0.02 || fail=1
    "$BIN/mkpmap" -apg "$tmp/g.pm" 2m -apo port_mat -apr 1 -n 2 -fo "$tmp/$v.oct" 2> "$tmp/err" ||
        { echo "FAIL $v: mkpmap: $(cat "$tmp/err")"; fail=1; continue; }
    for e in "" -ape; do
        "$BIN/rtrace" -h -u- -I -ab 1 -ad 2048 -aa 0 -ap "$tmp/g.pm" 100 $e -n 2 "$tmp/$v.oct" \
            < "$pts" | awk '{print $1}' | paste - "$tmp/d0" > "$tmp/pm"
        if [ $v = blinds ] && [ -z "$e" ]; then
            # RADIANCE's estimate: the boundary bias must be there (below -4 %).
            compare "$v: indirect, photon map" "$tmp/pm" "$ref/${v}_total.txt" \
                "$ref/${v}_direct.txt" indirect 1
            paste "$tmp/pm" "$ref/${v}_total.txt" "$ref/${v}_direct.txt" |
                awk '{ so += $1 - $2; sc += $3 - $5 } END { exit !(so / sc - 1 < -0.04) }' ||
                { echo "FAIL: expected RADIANCE's estimate below -4 %"; fail=1; }
            continue
        fi
        compare "$v: indirect, photon map $e" "$tmp/pm" "$ref/${v}_total.txt" \
            "$ref/${v}_direct.txt" indirect 0.025 || fail=1
    done
done
exit $fail
