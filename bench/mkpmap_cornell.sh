#!/usr/bin/env bash
# mkpmap on ../shared/validation/cornell with the README's targets (global 500k +
# caustic 1m), -n 1 and -n 2: emitted and stored photons/s, kd-tree build time, bytes
# per photon on disk, peak memory. RADIANCE 5.4a took 9.2 s (-n 1) and 6.2 s (-n 2) on
# a machine of the same kind (README). CPU time (user+sys) is printed too: on a shared
# machine it varies far less than wall time. Usage: [RUNS=5] bench/mkpmap_cornell.sh
# [build dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build}/tools
runs=${RUNS:-5}
scene=$root/../shared/validation/cornell/scene.rad
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for n in 1 2; do
    # RUNS runs (default 5); the run with the median wall time is reported, with the
    # fastest and slowest beside it: on a shared machine one run can be 10-25 % off.
    for r in $(seq "$runs"); do
        /usr/bin/time -f "%e s wall, %U+%S s user+sys, %M kB peak" -o "$tmp/time$r" \
            "$bin/mkpmap" -fo -apg "$tmp/g.pm" 500k -apc "$tmp/c.pm" 1m -apr 1 -n $n "$scene" \
            > "$tmp/log$r" 2>&1
    done
    med=$(for r in $(seq "$runs"); do echo "$(cut -d' ' -f1 "$tmp/time$r") $r"; done | sort -n |
          awk -v k=$(( (runs + 1) / 2 )) 'NR == k {print $2}')
    range=$(cat "$tmp"/time* | sort -n | awk 'NR == 1 {lo = $1} {hi = $1} END {print lo "-" hi}')
    emitted=$(awk '/photons emitted/ {print $1}' "$tmp/log$med")
    dist=$(sed -n 's/.*prepass)*, \([0-9.]*\) s distribution.*/\1/p' "$tmp/log$med")
    tree=$(sed -n 's/.* \([0-9.]*\) s kd-tree.*/\1/p' "$tmp/log$med")
    ng=$("$bin/getinfo" "$tmp/g.pm" | awk -F'= ' '/NumPhotons/ {print $2}')
    nc=$("$bin/getinfo" "$tmp/c.pm" | awk -F'= ' '/NumPhotons/ {print $2}')
    bytes=$(( $(stat -c %s "$tmp/g.pm") + $(stat -c %s "$tmp/c.pm") ))
    awk -v n=$n -v e="$emitted" -v d="$dist" -v t="$tree" -v g="$ng" -v c="$nc" -v b="$bytes" \
        -v tm="$(cat "$tmp/time$med")" -v range="$range" -v runs="$runs" 'BEGIN {
        printf "-n %d: %d emitted, %d global + %d caustic stored; distribution %.2f s = %.2f M emitted/s, %.0f k stored/s; kd-trees %.2f s; %.1f bytes/photon on disk; median of %d runs: %s (wall %s s)\n",
            n, e, g, c, d, e / d / 1e6, (g + c) / d / 1e3, t, b / (g + c), runs, tm, range }'
done
