#!/usr/bin/env bash
# How the office's photon-map rtrace grows with sensors and with the maps (issue 49):
# examples/daylit_office, mkpmap -apg N -apc N through the window port (N in MAPS,
# default "1m 20m"), then for each map size and each sensor count in SENSORS (default
# "100 1000 10000 100000"; points on a jittered work-plane grid)
#   rtrace -h -I -ab 1 -ad 1024 -aa 0.1 -ap g.pm 100 -ap c.pm 100     (one thread)
# printing wall time, user+sys CPU and peak memory (/usr/bin/time), ours with the maps'
# search index beside them. With RADIANCE=<RADIANCE 5.4's bin> RADIANCE's rtrace runs the
# same maps and points up to RADIANCE_MAX sensors (default 10000; a million would take it
# hours). MKPMAP_OPTS are added to mkpmap's options and RTRACE_OPTS to our rtrace's (e.g.
# "-aC 100m" and "-aC 14m" for maps searched out of core; RADIANCE 5.4 has no -aC and
# holds every map in memory).
# Usage: [RADIANCE=/path/bin] [MAPS="1m 20m"] [SENSORS="..."] [MKPMAP_OPTS=] [RTRACE_OPTS=]
#        bench/office_growth.sh [build]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$root/build}" && pwd)/tools
maps=${MAPS:-"1m 20m"}
sensors=${SENSORS:-"100 1000 10000 100000"}
rad=${RADIANCE:-}
radiance_max=${RADIANCE_MAX:-10000}
mkpmap_opts=${MKPMAP_OPTS:-}
rtrace_opts=${RTRACE_OPTS:-}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cp "$root/examples/daylit_office/scene.rad" .
PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/oconv" scene.rad > office.oct
if [ -n "$rad" ]; then
    PATH="$rad:$PATH" RAYPATH=".:${RADIANCE_LIB:-$rad/../lib}" "$rad/oconv" scene.rad > r.oct
fi
# "wall cpu MB" of one run of the shell command $2 with the tools of $1 (ours/radiance).
timed() {
    if [ "$1" = ours ]; then
        PATH="$bin:$PATH" RAYPATH=".:$root/lib" /usr/bin/time -f "%e %U %S %M" -o t.txt \
            sh -c "$2" > /dev/null 2>&1
    else
        PATH="$rad:$PATH" RAYPATH=".:${RADIANCE_LIB:-$rad/../lib}" /usr/bin/time \
            -f "%e %U %S %M" -o t.txt sh -c "$2" > /dev/null 2>&1
    fi
    awk '!/^Command/ { printf "%.2f %.2f %.0f", $1, $2 + $3, $4 / 1024 }' t.txt
}
echo "| map photons | sensors | ours wall | ours cpu | ours peak | RADIANCE wall | cpu | peak | ratio |"
echo "|---|---|---|---|---|---|---|---|---|"
for m in $maps; do
    PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/mkpmap" -fo -apg g.pm "$m" -apc c.pm "$m" \
        -apo window_glass -aps sensor_plane -n 2 $mkpmap_opts office.oct 2> /dev/null
    PATH="$bin:$PATH" RAYPATH=".:$root/lib" "$bin/rtrace" -h $rtrace_opts -ap g.pm 100 \
        -ap c.pm 100 office.oct < /dev/null  # the index beside each map (in core)
    for n in $sensors; do
        awk -v n="$n" 'BEGIN { srand(11); k = int(sqrt(1.5 * n)); if (k < 1) k = 1
            rows = int((n + k - 1) / k)
            for (i = 0; i < n; i++)
                printf "%.4f %.4f 0.8 0 0 1\n", 0.05 + 5.9 * (i % k + rand()) / k,
                       0.05 + 3.9 * (int(i / k) + rand()) / rows }' > pts.txt
        cmd="rtrace -h -I -ab 1 -ad 1024 -aa 0.1 -ap g.pm 100 -ap c.pm 100"
        read -r w c p <<< "$(timed ours "$cmd $rtrace_opts office.oct < pts.txt")"
        if [ -n "$rad" ] && [ "$n" -le "$radiance_max" ]; then
            read -r rw rc rp <<< "$(timed radiance "$cmd r.oct < pts.txt")"
            printf "| %s | %s | %.2f s | %.2f s | %d MB | %.2f s | %.2f s | %d MB | %.1fx |\n" \
                "$m" "$n" "$w" "$c" "$p" "$rw" "$rc" "$rp" "$(echo "$rw $w" | awk '{ print $1 / $2 }')"
        else
            printf "| %s | %s | %.2f s | %.2f s | %d MB | | | | |\n" "$m" "$n" "$w" "$c" "$p"
        fi
    done
done
