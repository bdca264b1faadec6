#!/usr/bin/env bash
# What spectral rendering costs against RGB (issue 50): mkpmap and rtrace -ap at -cs 3
# (RGB), 9, 18, 24 and 36 (RADIANCE 6 caps -cs at 24) on a 4 x 4 x 3 m room with a teal
# spectral wall, a red floor and a ceiling lamp: per run the wall time, peak RSS
# (/usr/bin/time) and the map set's bytes per photon position (a pass's photon count:
# each pass stores its own photons, 27 bytes each). Each pass of three bands is traced
# and stored separately (util/spectrum.h Pass), so time and bytes grow as ceil(n / 3);
# mkpmap's peak memory does not, as the passes run one after another.
# Usage: [PHOTONS=500k] [POINTS=200] [N=1] bench/spectral_cost.sh [build dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build}/tools
photons=${PHOTONS:-500k}
points=${POINTS:-200}
threads=${N:-1}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cd "$out"
cat > room.rad <<'RAD'
void spectrum teal 0 0 7 380 780 .1 .6 .7 .3 .1
void plastic white 0 0 5 .7 .7 .7 0 0
teal plastic tealwall 0 0 5 .9 .9 .9 0 0
void plastic redfloor 0 0 5 .6 .2 .1 0 0
!genbox white room 4 4 3 -i
redfloor polygon floor 0 0 12 0 0 0.001  4 0 0.001  4 4 0.001  0 4 0.001
tealwall polygon tw 0 0 12 0.001 0 0  0.001 4 0  0.001 4 3  0.001 0 3
void light bright 0 0 3 30 30 25
bright polygon lamp 0 0 12 1.5 1.5 2.99  1.5 2.5 2.99  2.5 2.5 2.99  2.5 1.5 2.99
RAD
export RAYPATH=".:$root/lib"
"$bin/oconv" room.rad > r.oct
awk -v n="$points" 'BEGIN { srand(1); for (i = 0; i < n; ++i)
    printf "%.4f %.4f 0.8 0 0 1\n", 0.2 + 3.6 * rand(), 0.2 + 3.6 * rand() }' > points.txt
printf "%-6s %12s %12s %14s %12s %12s\n" "-cs" "mkpmap s" "mkpmap MB" "bytes/photon" "rtrace s" "rtrace MB"
for n in 3 9 18 24 36; do
    /usr/bin/time -f "%e %M" -o mk.time "$bin/mkpmap" -n "$threads" -cs "$n" -apg g$n.pm "$photons" \
        r.oct 2> mk.err
    stored=$(awk '/photons stored/ { print $1 }' mk.err)
    bytes=$(cat g$n.pm* | wc -c)
    passes=$(( ( (n < 24 ? n : 24) + 2) / 3 ))
    stored=$((stored / passes))
    /usr/bin/time -f "%e %M" -o rt.time "$bin/rtrace" -n "$threads" -h -I -cs "$n" -co -ab 1 \
        -ad 512 -aa 0 -ap g$n.pm 100 r.oct < points.txt > /dev/null
    read -r mks mkk < mk.time
    read -r rts rtk < rt.time
    printf "%-6s %12s %12.1f %14.1f %12s %12.1f\n" "$n" "$mks" "$(echo "$mkk / 1024" | bc -l)" \
        "$(echo "$bytes / $stored" | bc -l)" "$rts" "$(echo "$rtk / 1024" | bc -l)"
done
