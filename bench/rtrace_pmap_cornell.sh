#!/usr/bin/env bash
# rtrace -I with photon maps on ../shared/validation/cornell, the README's command (global
# 500k + caustic 1m, -ab 1 -ad 2048 -as 512 -aa 0.05 -ar 512, bandwidth 50 each) over the
# 103 sensor points, with 1 and 2 threads: wall time (median of 5, map load and index
# included), user+sys CPU, peak memory, and the ratio to RADIANCE 5.4a's 1.5 s (README,
# run without -n on a machine of the same kind). Usage: bench/rtrace_pmap_cornell.sh [build]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build}/tools
dir=$root/../shared/validation/cornell
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$bin/mkpmap" -apg "$tmp/g.pm" 500k -apc "$tmp/c.pm" 1m -apr 1 -n 2 "$dir/scene.rad" 2> /dev/null
for n in 1 2; do
    for run in 1 2 3 4 5; do
        /usr/bin/time -f "%e %U %S %M" -o "$tmp/t$run" "$bin/rtrace" -n $n -h -I -ov -ab 1 \
            -ad 2048 -as 512 -aa 0.05 -ar 512 -ap "$tmp/g.pm" 50 -ap "$tmp/c.pm" 50 \
            "$dir/scene.rad" < "$dir/points.txt" > /dev/null 2> /dev/null
    done
    cat "$tmp"/t[1-5] | sort -n | awk -v n=$n 'NR == 3 {
        printf "rtrace -I -ap, -n %d: median %.2f s wall (%.2f s user+sys, %.0f MB peak), %.1fx RADIANCE (1.5 s)\n",
            n, $1, $2 + $3, $4 / 1024, 1.5 / $1 }'
done
