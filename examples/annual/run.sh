#!/usr/bin/env bash
# Annual daylight metrics for the office with blinds (README.md): sources and sensors,
# one contribution photon map, rcontrib -ap on the sensor grid, then the weighting by an
# hourly weather series. Usage: ./run.sh [weather.epw]   (tools on PATH, python3)
set -euo pipefail
cd "$(dirname "$0")"
python3 annual.py sources > sources.rad      # also writes mods.txt
python3 annual.py sensors > sensors.txt
oconv room.rad sources.rad > annual.oct
mkpmap -fo -apC contrib.pm 2m -apo window_glass -aps sensor_plane -n 2 annual.oct
rcontrib -fo -I -h -V- -ap contrib.pm 250 -M mods.txt -n 2 annual.oct < sensors.txt > coef.txt
python3 annual.py metrics coef.txt "$@"
./plan.sh 3 "DA300 %" da300_falsecolor.png   # the same plan through pvalue -r and falsecolor
