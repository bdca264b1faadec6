#!/usr/bin/env bash
# MPI scaling of mkpmap and rcontrib (the tools in tools/mpi/, cmake -DRP_MPI=ON), RANKS
# ranks of one thread each, beside the tools without MPI at -n 1 and -n 2:
#   mkpmap:   the daylit office, mkpmap -apg g.pm PHOTONS -apo window_glass -aps sensor_plane
#   rcontrib: 100 lamps as 100 modifiers (bench/rcontrib_bench.sh's room), 1,000 sensors,
#             classic rcontrib -I -ab AB -M mods.txt (AB: default 1)
# For each: wall time, the sum of user+sys CPU, the root's peak memory (mpirun's children
# together, /usr/bin/time), whether the output equals the one-process output, and the
# bytes the ranks sent (RADPHOTON_STATS), per photon emitted or per ray answered: the
# communication volume the cluster model in bench/README_mpi.md starts from.
# On a machine with fewer cores than ranks the ranks share cores (--oversubscribe): the
# times then show the overhead of the split, not its speed-up.
# Usage: [RANKS="1 2 3 4"] [PHOTONS=4m] [RUNS=3] [AB=1] bench/mpi_scaling.sh [build]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$root/build}" && pwd)/tools
ranks=${RANKS:-"1 2 3 4"}
photons=${PHOTONS:-4m}
runs=${RUNS:-3}
ab=${AB:-1}
[ -x "$bin/mpi/mkpmap" ] || { echo "no MPI tools in $bin/mpi (cmake -DRP_MPI=ON)"; exit 1; }
export RAYPATH=.:$root/lib RADPHOTON_STATS=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
runas=()
[ "$(id -u)" -eq 0 ] && runas=(--allow-run-as-root)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cp "$root/examples/daylit_office/scene.rad" .
"$bin/oconv" scene.rad > office.oct
bash "$root/bench/many_lamps_room.sh"
"$bin/oconv" room.rad > room.oct

# median of RUNS runs of CMD... (stdin sensors.txt, stdout out, stderr err):
# "wall cpu peakMB sentBytes"
timeit() {
    for r in $(seq "$runs"); do
        /usr/bin/time -f "%e %U %S %M" -o time.txt "$@" < sensors.txt > out 2> err
        echo "$(tail -1 time.txt) $(awk '/^mpi rank [0-9]+: sent/ { s += $5 } END { printf "%.0f", s }' err)" > "t$r"
    done
    cat t[0-9]* | sort -n | awk -v m=$(( (runs + 1) / 2 )) \
        'NR == m { printf "%.2f %.2f %.0f %.0f", $1, $2 + $3, $4 / 1024, $5 }'
    rm -f t[0-9]*
}
line() {  # NAME "wall cpu MB sent" SAME UNIT COUNT: one row, with mkpmap's own split of
    read -r w c m s <<< "$2"  # its time (last run) after it
    printf "%-16s %6.2f s %6.2f s cpu %5d MB  %-7s %6.1f B/%s  %s\n" "$1" "$w" "$c" "$m" "$3" \
        "$(awk -v s="$s" -v u="$5" 'BEGIN { print (u > 0 ? s / u : 0) }')" "$4" \
        "$(awk '/photons emitted/ { print $(NF-5), "s tracing,", $(NF-2), "s kd-tree" }' err)"
}
strip() { sed '1,/^$/d' "$1" | md5sum; }
# --bind-to none: Open MPI binds a rank to one core by default when there are at most two,
# which would put all of a rank's -n threads on that core.
mpi=(mpirun "${runas[@]}" --oversubscribe --bind-to none -n)

echo "mkpmap -apg $photons, daylit office"
MK=(-apg g.pm "$photons" -apo window_glass -aps sensor_plane -apr 1 -fo office.oct)
r=$(timeit "$bin/mkpmap" -n 1 "${MK[@]}"); ref=$(strip g.pm)
emitted=$(awk '/photons emitted/ { print $1 }' err)
line "no MPI, -n 1" "$r" "" photon "$emitted"
r=$(timeit "$bin/mkpmap" -n 2 "${MK[@]}")
line "no MPI, -n 2" "$r" "$([ "$(strip g.pm)" = "$ref" ] && echo same || echo DIFFERS)" photon "$emitted"
for n in $ranks; do
    r=$(timeit "${mpi[@]}" "$n" "$bin/mpi/mkpmap" -n 1 "${MK[@]}")
    line "mpirun -n $n" "$r" "$([ "$(strip g.pm)" = "$ref" ] && echo same || echo DIFFERS)" photon "$emitted"
done

echo "rcontrib -I -ab $ab -M mods.txt (100 modifiers), 1,000 sensors"
RC=(-h -I -u- -ab "$ab" -M mods.txt room.oct)
r=$(timeit "$bin/rcontrib" -n 1 "${RC[@]}"); cp out rc.ref
line "no MPI, -n 1" "$r" "" ray 1000
r=$(timeit "$bin/rcontrib" -n 2 "${RC[@]}")
line "no MPI, -n 2" "$r" "$(cmp -s out rc.ref && echo same || echo DIFFERS)" ray 1000
for n in $ranks; do
    r=$(timeit "${mpi[@]}" "$n" "$bin/mpi/rcontrib" -n 1 "${RC[@]}")
    line "mpirun -n $n" "$r" "$(cmp -s out rc.ref && echo same || echo DIFFERS)" ray 1000
done
