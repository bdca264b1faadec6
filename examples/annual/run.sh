#!/usr/bin/env bash
# A year of daylight in the office with blinds, with RADIANCE's own commands (README.md):
# weather tape, sky matrix, daylight coefficients from a precomputed contribution photon
# map and from the classic two-phase rcontrib, hourly illuminance, daylight autonomy and
# useful daylight illuminance, and a false-colour plan of each.
# Usage: ./run.sh [weather.epw]   (tools on PATH; without a file, a synthetic Zurich year)
set -euo pipefail
cd "$(dirname "$0")"
if [ $# -ge 1 ]; then cp "$1" weather.epw; else python3 synthetic_epw.py > weather.epw; fi
epw2wea weather.epw weather.wea > /dev/null
gendaymtx -m 1 weather.wea > sky.smx                 # 146 patches x 8760 hours
cnt 8 12 | rcalc -e '$1=.25+.5*$2;$2=.25+.5*$1;$3=.8;$4=0;$5=0;$6=1' > sensors.txt
oconv room.rad sky.rad > annual.oct
BINS=(-e MF:1 -f reinhart.cal -b rbin -bn Nrbins -m skyglow)

# Photon map: 8 million photons through the window, 0.5 % of them precomputed from their
# 1200 nearest neighbours into the 146 sky patches, wavelet-compressed to a sixth.
mkpmap -fo -apC annual.pm 8m 1200 0.7 -apP 0.005 -apo window_glass -aps sensor_plane "${BINS[@]}" \
    -n 2 annual.oct
rcontrib -fo -I -ab 1 -ad 1024 -lw 1e-4 -n 2 -ap annual.pm @annual.pm.opt annual.oct \
    < sensors.txt > dc_pmap.mtx

# Classic two-phase daylight coefficients.
rcontrib -fo -I -ab 6 -ad 4096 -lw 1e-5 -n 2 "${BINS[@]}" annual.oct < sensors.txt > dc_classic.mtx

for m in pmap classic; do
    # Hourly work-plane illuminance: coefficients times sky, RGB to lux.
    dctimestep dc_$m.mtx sky.smx | rmtxop -fa -c 47.435 119.93 11.635 - > ill_$m.mtx
    ./metrics.sh ill_$m.mtx weather.wea > metrics_$m.txt
    png=da300_$m.png
    [ $m = pmap ] && png=da300.png   # the README's picture
    ./plan.sh metrics_$m.txt 3 "DA300 %" $png
    awk -v m=$m '{ da += $3; udi += $5 } END {
        printf "%s: mean DA300 %.1f %%, mean UDI 100-2000 lx %.1f %%\n", m, da / NR, udi / NR }' \
        metrics_$m.txt
done
