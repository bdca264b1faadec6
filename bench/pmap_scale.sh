#!/usr/bin/env bash
# How photon maps scale from 10^6 to 2 x 10^8 photons (issue: maps larger than memory).
# The daylit office (examples/daylit_office: window, blinds, sun and sky), global photons
# only (-apg, port on the window, stored on the work plane too), for each size in SIZES:
#   mkpmap -apg g.pm N -n 2                        (sizes above 5e7 with MKPMAP_LARGE, by
#                                                   default -aC 100M: under 4 GiB)
#   rtrace -h -I -ab -1 -ap g.pm 50 -n 2 < 100k work-plane points    (in core)
#   the same with -aC OOC_CACHE (default 14M: resident top of the tree plus one cache per
#   thread, 3 x 14M x 24 bytes = 1 GiB), for sizes of at least OOC_FROM photons (2e7)
# and prints wall time, peak memory (/usr/bin/time) and bytes per photon (peak less the
# same run's peak without photons, over N), the map's size on disk, and whether the
# out-of-core output equals the in-core one. With RADIANCE=<dir of RADIANCE's binaries> it
# runs RADIANCE's rtrace on the same maps up to RADIANCE_MAX photons (default 2e7; its
# memory is the yardstick).
# Needs about 6 GB of disk per 2e8 photons in TMPDIR.
# Usage: [SIZES="1m 20m 200m"] [RADIANCE=/path/bin] bench/pmap_scale.sh [build]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$root/build}" && pwd)/tools
sizes=${SIZES:-"1m 20m 200m"}
ooc_cache=${OOC_CACHE:-14M}
ooc_from=${OOC_FROM:-20000000}
radiance_max=${RADIANCE_MAX:-20000000}
mk_large=${MKPMAP_LARGE:-"-aC 100M"}
export RAYPATH=.:$root/lib
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cp "$root/examples/daylit_office/scene.rad" .
"$bin/oconv" scene.rad > office.oct
awk 'BEGIN { srand(7); for (i = 0; i < 100000; i++)
    printf "%.4f %.4f 0.8 0 0 1\n", 0.02 + 5.96 * rand(), 0.02 + 3.96 * rand() }' > points.txt

count() {  # 1m -> 1000000
    awk -v s="$1" 'BEGIN { m = 1; u = substr(s, length(s)); v = s
        if (u == "k" || u == "K") { m = 1e3; v = substr(s, 1, length(s) - 1) }
        if (u == "m" || u == "M") { m = 1e6; v = substr(s, 1, length(s) - 1) }
        printf "%.0f", v * m }'
}
# run CMD...: wall and peak KB of one run into $wall $peak (input points.txt, output out.txt)
run() {
    /usr/bin/time -f "%e %M" -o time.txt "$@" < points.txt > out.txt 2> err.txt ||
        { cat err.txt >&2; exit 1; }
    read -r wall peak < time.txt
}
perphoton() { awk -v p="$1" -v b="$2" -v n="$3" 'BEGIN { printf "%.1f", (p - b) * 1024 / n }'; }
mb() { awk -v k="$1" 'BEGIN { printf "%.0f", k / 1024 }'; }

lookup="-h -I -ab -1 -ap g.pm 50 -n 2 -u-"
# Peak of an rtrace run without photons (the scene, the rays), the base of bytes/photon.
run "$bin/rtrace" -h -I -ab 0 -n 2 -u- office.oct; base=$peak
if [ -n "${RADIANCE:-}" ]; then  # its own octree (needs its gensky, genblinds, xform)
    PATH="$RADIANCE:$PATH" RAYPATH=".:$RADIANCE/../lib" "$RADIANCE/oconv" -f scene.rad > radiance.oct
    run "$RADIANCE/rtrace" -h -I -ab 0 -n 2 -u- radiance.oct; radbase=$peak
fi

printf "%-8s %-28s %8s %9s %8s\n" photons step "wall s" "peak MB" "B/photon"
for s in $sizes; do
    n=$(count "$s")
    extra=""; [ "$n" -gt 50000000 ] && extra=$mk_large
    rm -f g.pm
    # shellcheck disable=SC2086
    run "$bin/mkpmap" -apg g.pm "$n" -apo window_glass -aps sensor_plane -n 2 $extra office.oct
    stored=$(awk '/Global photons stored/ { print $1 }' err.txt)
    printf "%-8s %-28s %8.1f %9s %8s   %s photons, %s GB file\n" "$s" "mkpmap $extra" "$wall" \
        "$(mb "$peak")" "$(perphoton "$peak" 0 "$stored")" "$stored" \
        "$(awk -v b="$(stat -c %s g.pm)" 'BEGIN { printf "%.2f", b / 1e9 }')"
    # shellcheck disable=SC2086
    run "$bin/rtrace" $lookup office.oct
    cp out.txt incore.txt
    printf "%-8s %-28s %8.1f %9s %8s\n" "$s" "rtrace in core" "$wall" \
        "$(mb "$peak")" "$(perphoton "$peak" "$base" "$stored")"
    if [ "$n" -ge "$ooc_from" ]; then
        # shellcheck disable=SC2086
        run "$bin/rtrace" $lookup -aC "$ooc_cache" office.oct
        same=differs; cmp -s out.txt incore.txt && same="same as in core"
        printf "%-8s %-28s %8.1f %9s %8s   %s\n" "$s" "rtrace -aC $ooc_cache" "$wall" \
            "$(mb "$peak")" "$(perphoton "$peak" "$base" "$stored")" "$same"
    fi
    if [ -n "${RADIANCE:-}" ] && [ "$n" -le "$radiance_max" ]; then
        # shellcheck disable=SC2086
        run "$RADIANCE/rtrace" $lookup radiance.oct
        printf "%-8s %-28s %8.1f %9s %8s\n" "$s" "RADIANCE rtrace" "$wall" \
            "$(mb "$peak")" "$(perphoton "$peak" "$radbase" "$stored")"
    fi
done
