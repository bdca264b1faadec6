#!/usr/bin/env bash
# The workloads of issue 49 ("ten times RADIANCE on real work"), ours and, with
# RADIANCE=<dir of RADIANCE 5.4's binaries>, RADIANCE's on the same files, runs alternating
# (ours, RADIANCE, ours, ...), the median of RUNS (default 3) of each: wall time, user+sys
# CPU, peak memory (/usr/bin/time), and RADIANCE's wall time over ours.
#   office    examples/daylit_office (window port, blinds, gensky sun and sky):
#             mkpmap -apg 1m -apc 1m (-n 1, -n 2);
#             rtrace -I -ab 1 -ad 1024 -aa 0.1 -ap g 100 -ap c 100 at 400 work-plane points;
#             rtrace -I -ab -1 -ap g 100 at 100k points (bare lookups in the 1M map);
#             rpict 256 x 256 -ab 1 -aa 0.1 -ad 1024 -as 256 -ar 128, 500k + 500k maps
#             (ours also with -n 2: the speed-up from a second thread)
#   open      a spherical lamp over a mirror, a ceiling to catch its caustic, nothing else
#             (nearly every photon leaves): mkpmap -apc 200k (-n 1, -n 2)
#   lamps     bench/many_lamps_room.sh (100 sphere lamps, each its own modifier) at its
#             first SENSORS sensors (default 200), -n 2: rcontrib -I -ab 3 -M (classic) and
#             rcontrib -I -ap c.pm 200 -M on mkpmap -apC 1m
# Ours runs with its photon maps' search index already beside them (rtrace.1 -ap), as
# every run after the first does. RADIANCE's rtrace and rpict read our map files; its
# rcontrib reads the contribution map its own mkpmap made.
# Usage: [RADIANCE=/path/bin] [RUNS=3] [SENSORS=200] [ONLY="office open lamps"]
#        bench/speed_vs_radiance.sh [build]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$root/build}" && pwd)/tools
runs=${RUNS:-3}
sensors=${SENSORS:-200}
only=${ONLY:-"office open lamps"}
rad=${RADIANCE:-}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

# One run of the command (a shell string) with the environment of "ours" or "radiance";
# appends "wall cpu peakKB" to the file named by $1.
run() {
    local who=$1 out=$2 cmd=$3
    if [ "$who" = ours ]; then
        PATH="$bin:$PATH" RAYPATH=".:$root/lib" /usr/bin/time -f "%e %U %S %M" -a -o "$out" \
            sh -c "$cmd" > /dev/null 2>&1
    else
        PATH="$rad:$PATH" RAYPATH=".:${RADIANCE_LIB:-$rad/../lib}" \
            /usr/bin/time -f "%e %U %S %M" -a -o "$out" sh -c "$cmd" > /dev/null 2>&1
    fi
}
# The median run of a file of "wall user sys peakKB" lines as "wall cpu MB".
median() {
    grep -v '^Command' "$1" | sort -n |
        awk -v m=$(( (runs + 1) / 2 )) 'NR == m { printf "%.2f %.2f %.0f", $1, $2 + $3, $4 / 1024 }'
}
# NAME OURS_CMD [RADIANCE_CMD]: both RUNS times, alternating, then one table row.
bench() {
    local name=$1 ours=$2 theirs=${3:-}
    rm -f a.t b.t
    for r in $(seq "$runs"); do
        run ours a.t "$ours"
        if [ -n "$rad" ] && [ -n "$theirs" ]; then run radiance b.t "$theirs"; fi
    done
    read -r w c m <<< "$(median a.t)"
    if [ -f b.t ]; then
        read -r rw rc rm_ <<< "$(median b.t)"
        printf "| %s | %.2f s | %.2f s | %d MB | %.2f s | %.2f s | %d MB | %.1fx |\n" "$name" \
            "$w" "$c" "$m" "$rw" "$rc" "$rm_" "$(echo "$rw $w" | awk '{ print $1 / $2 }')"
    else
        printf "| %s | %.2f s | %.2f s | %d MB | | | | |\n" "$name" "$w" "$c" "$m"
    fi
}

echo "| workload | ours wall | ours cpu | ours peak | RADIANCE wall | cpu | peak | ratio |"
echo "|---|---|---|---|---|---|---|---|"

if [[ " $only " == *" office "* ]]; then
    cp "$root/examples/daylit_office/scene.rad" .
    PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/oconv" scene.rad > office.oct
    if [ -n "$rad" ]; then
        PATH="$rad:$PATH" RAYPATH=".:${RADIANCE_LIB:-$rad/../lib}" "$rad/oconv" scene.rad > r.oct
    fi
    awk 'BEGIN { for (i = 0; i < 20; i++) for (j = 0; j < 20; j++)
        printf "%.3f %.3f 0.8 0 0 1\n", 0.15 + i * 0.2975, 0.1 + j * 0.19 }' > pts400.txt
    awk 'BEGIN { srand(7); for (i = 0; i < 100000; i++)
        printf "%.4f %.4f 0.8 0 0 1\n", 0.05 + 5.9 * rand(), 0.05 + 3.9 * rand() }' > pts100k.txt
    mk="mkpmap -fo -apo window_glass -aps sensor_plane"
    bench "office mkpmap 1M + 1M, -n 1" "$mk -apg g.pm 1m -apc c.pm 1m -n 1 office.oct" \
        "$mk -apg rg.pm 1m -apc rc.pm 1m -n 1 r.oct"
    bench "office mkpmap 1M + 1M, -n 2" "$mk -apg g.pm 1m -apc c.pm 1m -n 2 office.oct" \
        "$mk -apg rg.pm 1m -apc rc.pm 1m -n 2 r.oct"
    PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/mkpmap" -fo -apo window_glass \
        -aps sensor_plane -apg g5.pm 500k -apc c5.pm 500k -n 2 office.oct 2> /dev/null
    # The index beside each map, as after any first run.
    for m in g c g5 c5; do
        PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/rtrace" -h -ap $m.pm 100 office.oct < /dev/null
    done
    rt="rtrace -u- -h -I -ab 1 -ad 1024 -aa 0.1 -ap g.pm 100 -ap c.pm 100"
    bench "office rtrace -I -ab 1 -aa 0.1, 400 points" "$rt office.oct < pts400.txt" \
        "$rt r.oct < pts400.txt"
    bench "office rtrace -ab -1, 100k lookups" \
        "rtrace -u- -h -I -ab -1 -ap g.pm 100 office.oct < pts100k.txt" \
        "rtrace -u- -h -I -ab -1 -ap g.pm 100 r.oct < pts100k.txt"
    rp="rpict -u- -x 256 -y 256 -vp 3 3.9 1.6 -vd 0 -1 -0.1 -vh 80 -vv 60 -ab 1 -aa 0.1 \
-ad 1024 -as 256 -ar 128 -ap g5.pm 100 -ap c5.pm 100"
    bench "office rpict 256^2, -n 1" "$rp office.oct" "$rp r.oct"
    bench "office rpict 256^2, ours -n 2" "$rp -n 2 office.oct"
fi

if [[ " $only " == *" open "* ]]; then
    cat > open.rad <<'RAD'
void light lamp 0 0 3 100 100 100
lamp sphere bulb 0 0 4 0 0 1 0.05
void mirror m 0 0 3 .9 .9 .9
m polygon mir 0 0 12 -1 -1 0  1 -1 0  1 1 0  -1 1 0
void plastic white 0 0 5 .5 .5 .5 0 0
white polygon ceil 0 0 12 -2 -2 3  -2 2 3  2 2 3  2 -2 3
RAD
    "$bin/oconv" open.rad > open.oct
    if [ -n "$rad" ]; then "$rad/oconv" open.rad > ropen.oct; fi
    bench "open scene mkpmap -apc 200k, -n 1" "mkpmap -fo -apc o.pm 200k -n 1 open.oct" \
        "mkpmap -fo -apc ro.pm 200k -n 1 ropen.oct"
    bench "open scene mkpmap -apc 200k, -n 2" "mkpmap -fo -apc o.pm 200k -n 2 open.oct" \
        "mkpmap -fo -apc ro.pm 200k -n 2 ropen.oct"
fi

if [[ " $only " == *" lamps "* ]]; then
    bash "$root/bench/many_lamps_room.sh"
    head -n "$sensors" sensors.txt > s.txt
    "$bin/oconv" room.rad > room.oct
    if [ -n "$rad" ]; then "$rad/oconv" room.rad > rroom.oct; fi
    PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/mkpmap" -apC l.pm 1m -n 2 room.oct 2> /dev/null
    PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/rcontrib" -h -I -ap l.pm 200 -M mods.txt \
        room.oct < /dev/null > /dev/null
    if [ -n "$rad" ]; then
        PATH="$rad:$PATH" RAYPATH=".:${RADIANCE_LIB:-$rad/../lib}" "$rad/mkpmap" -apC rl.pm 1m \
            -n 2 rroom.oct > /dev/null 2>&1
    fi
    bench "100 lamps rcontrib classic, $sensors sensors, -n 2" \
        "rcontrib -n 2 -h -I -ab 3 -M mods.txt room.oct < s.txt" \
        "rcontrib -n 2 -h -I -ab 3 -M mods.txt rroom.oct < s.txt"
    bench "100 lamps rcontrib -ap 1M, $sensors sensors, -n 2" \
        "rcontrib -n 2 -h -I -ap l.pm 200 -M mods.txt room.oct < s.txt" \
        "rcontrib -n 2 -h -I -ap rl.pm 200 -M mods.txt rroom.oct < s.txt"
fi
