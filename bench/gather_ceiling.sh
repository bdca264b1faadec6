#!/usr/bin/env bash
# How close the final gather comes to Embree's own ray rate (issue 49). In the daylit
# office (examples/daylit_office), one thread:
#   1. bench_gather: the gather rays of rtrace -I -ab 1 -ad 1024 at 400 work-plane sensors
#      traced by Embree alone (rtcIntersect1, and rtcIntersect16 packets), and by our
#      SceneGeometry::closestHit (rays/s);
#   2. rtrace -h -I -ab 1 -ad 1024 -as 0 -aa 0 at 100 and 400 sensors, with the photon maps
#      (-ap g.pm 100 -ap c.pm 100, 1M photons each) and classic: each sensor sends one
#      hemisphere of 18 x 57 = 1026 gather rays, so 300 sensors' difference over the time
#      difference is the gather's rate, fixed costs removed (median of RUNS runs each).
# Usage: [RUNS=3] bench/gather_ceiling.sh [build]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
bin=$build/tools
runs=${RUNS:-3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
export PATH="$bin:$PATH" RAYPATH=".:$root/lib"
cp "$root/examples/daylit_office/scene.rad" .
oconv scene.rad > office.oct
mkpmap -fo -apg g.pm 1m -apc c.pm 1m -apo window_glass -aps sensor_plane -n 2 office.oct \
    2> /dev/null
rtrace -h -ap g.pm 100 -ap c.pm 100 office.oct < /dev/null  # the index beside each map

RP_GATHER_OCTREE=office.oct "$build/bench/bench_gather" --benchmark_repetitions="$runs" \
    --benchmark_report_aggregates_only=true 2> /dev/null | grep median | tee embree.txt
own=$(awk '/BM_EmbreeOwn\/1_median/ { for (i = 1; i <= NF; i++) if ($i ~ /^rays\/s=/) {
    v = substr($i, 8); m = v ~ /M\/s$/ ? 1e6 : (v ~ /k\/s$/ ? 1e3 : 1); print v * m } }' embree.txt)

awk 'BEGIN { for (i = 0; i < 20; i++) for (j = 0; j < 20; j++)
    printf "%.3f %.3f 0.8 0 0 1\n", 0.15 + i * 0.2975, 0.1 + j * 0.19 }' > p400.txt
head -100 p400.txt > p100.txt
# Median wall time of RUNS runs of rtrace with options $1 on the points in $2.
wall() {
    for _ in $(seq "$runs"); do
        /usr/bin/time -f "%e" -a -o t.txt rtrace -h -I -ab 1 -ad 1024 -as 0 -aa 0 $1 \
            office.oct < "$2" > /dev/null
    done
    sort -n t.txt | awk -v m=$(( (runs + 1) / 2 )) 'NR == m'
    rm -f t.txt
}
echo
echo "| gather | 100 sensors | 400 sensors | gather rays/s | of Embree's own rate |"
echo "|---|---|---|---|---|"
for mode in photon classic; do
    opts=""
    [ "$mode" = photon ] && opts="-ap g.pm 100 -ap c.pm 100"
    a=$(wall "$opts" p100.txt)
    b=$(wall "$opts" p400.txt)
    awk -v m="$mode" -v a="$a" -v b="$b" -v own="$own" 'BEGIN {
        rate = 300 * 1026 / (b - a)
        printf "| %s | %.2f s | %.2f s | %.3g M/s | %.1f %% |\n", m, a, b, rate / 1e6,
               100 * rate / own }'
done
