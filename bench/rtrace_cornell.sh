#!/usr/bin/env bash
# rtrace throughput on the Cornell box (../shared/validation/cornell): primary rays from
# an eye point near the front wall through a 2-D grid of directions, traced with -ab 0
# (direct only) and -ab 2 (ambient cache), with 1 and 2 threads. Prints rays/s.
# Usage: bench/rtrace_cornell.sh [build dir]   (RADIANCE's rtrace, if on PATH as
# RADIANCE_RTRACE=/path/to/rtrace, is timed on the same input for the ratio.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build}/tools
scene=$root/../shared/validation/cornell/scene.rad
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# n x n primary rays from (2.75, 0.3, 2.75) spread over a 60-degree square field.
rays() {
    awk -v n="$1" 'BEGIN {
        for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
            x = (i + 0.5) / n - 0.5; z = (j + 0.5) / n - 0.5;
            printf "2.75 0.3 2.75 %.6f 1 %.6f\n", 1.1547 * x, 1.1547 * z }
    }'
}
rays 400 > "$tmp/ab0.txt"   # 160,000 rays
rays 60 > "$tmp/ab2.txt"    # 3,600 rays

time_run() {  # label nrays rtrace-args...
    local label=$1 n=$2; shift 2
    local t0=$(date +%s.%N)
    "$@" > /dev/null
    local t1=$(date +%s.%N)
    awk -v l="$label" -v n="$n" -v a="$t0" -v b="$t1" \
        'BEGIN {printf "%-40s %8.2f s %12.0f rays/s\n", l, b - a, n / (b - a)}'
}
for n in 1 2; do
    time_run "rtrace -ab 0 -n $n (160k rays)" 160000 \
        "$bin/rtrace" -h -ab 0 -n $n "$scene" < "$tmp/ab0.txt"
    time_run "rtrace -ab 2 -n $n (3.6k rays)" 3600 \
        "$bin/rtrace" -h -ab 2 -n $n "$scene" < "$tmp/ab2.txt"
done
if [ -n "${RADIANCE_RTRACE:-}" ]; then
    "${RADIANCE_OCONV:-oconv}" "$scene" > "$tmp/c.oct"
    time_run "RADIANCE rtrace -ab 0" 160000 "$RADIANCE_RTRACE" -h -ab 0 "$tmp/c.oct" < "$tmp/ab0.txt"
    time_run "RADIANCE rtrace -ab 2" 3600 "$RADIANCE_RTRACE" -h -ab 2 "$tmp/c.oct" < "$tmp/ab2.txt"
fi
