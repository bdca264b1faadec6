#!/usr/bin/env bash
# rcontrib with many sources: a 20 x 10 x 3 m room lit by 100 small sphere lamps, each its
# own modifier, 1,000 sensors on a work plane (0.8 m) facing up. Runs
#   classic:  rcontrib -I -ab 3 -M mods.txt           (RADIANCE's other defaults: -ad 350, -lw 2e-3)
#   photons:  mkpmap -apC c.pm 1m, rcontrib -I -ap c.pm 200 -M mods.txt
# with -n 2 and prints wall time, user+sys CPU and peak memory (/usr/bin/time), median of
# RUNS runs (default 3). With RADIANCE=<dir of RADIANCE's binaries> it times RADIANCE's
# rcontrib (and mkpmap) on the same files too and prints the ratios; its library (for
# rayinit.cal) is taken from RADIANCE_LIB (default <dir>/../lib).
# Usage: [RADIANCE=/path/bin] bench/rcontrib_bench.sh [build] [runs]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$root/build}" && pwd)/tools
runs=${2:-3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

bash "$root/bench/many_lamps_room.sh"

# median of the runs: wall user+sys peakKB
timeit() {
    for r in $(seq "$runs"); do
        /usr/bin/time -f "%e %U %S %M" -o "t$r" "$@" > out.txt 2> err.txt
    done
    cat t[0-9]* | sort -n | awk -v m=$(( (runs + 1) / 2 )) 'NR == m { printf "%.2f %.2f %.0f", $1, $2 + $3, $4 / 1024 }'
    rm -f t[0-9]*
}
report() {  # NAME "wall cpu MB" [RADIANCE "wall cpu MB"]
    read -r w c m <<< "$2"
    if [ -n "${3:-}" ]; then
        read -r rw rc rm <<< "$3"
        printf "%-34s %7.2f s %7.2f s cpu %5d MB | RADIANCE %7.2f s %7.2f s cpu %5d MB | %5.1fx\n" \
            "$1" "$w" "$c" "$m" "$rw" "$rc" "$rm" "$(echo "$rw $w" | awk '{print $1 / $2}')"
    else
        printf "%-34s %7.2f s %7.2f s cpu %5d MB\n" "$1" "$w" "$c" "$m"
    fi
}

"$bin/oconv" room.rad > room.oct
"$bin/mkpmap" -apC c.pm 1m -n 2 room.oct 2> /dev/null
ours_map=$(timeit "$bin/mkpmap" -fo -apC c.pm 1m -n 2 room.oct)
ours_cl=$(timeit sh -c "exec '$bin/rcontrib' -n 2 -h -I -ab 3 -M mods.txt room.oct < sensors.txt")
ours_pm=$(timeit sh -c "exec '$bin/rcontrib' -n 2 -h -I -ap c.pm 200 -M mods.txt room.oct < sensors.txt")
if [ -n "${RADIANCE:-}" ]; then
    export RAYPATH=.:${RADIANCE_LIB:-$RADIANCE/../lib}
    "$RADIANCE/oconv" room.rad > rroom.oct
    rad_map=$(timeit "$RADIANCE/mkpmap" -fo -apC rc.pm 1m -n 2 rroom.oct)
    rad_cl=$(timeit sh -c "exec '$RADIANCE/rcontrib' -n 2 -h -I -ab 3 -M mods.txt rroom.oct < sensors.txt")
    rad_pm=$(timeit sh -c "exec '$RADIANCE/rcontrib' -n 2 -h -I -ap rc.pm 200 -M mods.txt rroom.oct < sensors.txt")
fi
echo "1,000 sensors x 100 sources, -n 2 (median of $runs; wall, user+sys, peak memory)"
report "mkpmap -apC 1m" "$ours_map" "${rad_map:-}"
report "rcontrib -I -ab 3 (classic)" "$ours_cl" "${rad_cl:-}"
report "rcontrib -I -ap c.pm 200" "$ours_pm" "${rad_pm:-}"
