#!/usr/bin/env bash
# Daylight autonomy and useful daylight illuminance per sensor, with RADIANCE's tools, from
# hourly work-plane illuminance (a matrix of one row per sensor and one column per hour,
# as dctimestep | rmtxop -c give it) and the weather tape its hours come from. Occupied
# hours: 8 to 18 h. Prints "x y DA300 UDI<100 UDI100-2000 UDI>2000" (percent) per sensor.
# Usage: ./metrics.sh illuminance.mtx weather.wea [sensors.txt]   (tools on PATH)
set -euo pipefail
ill=$1 wea=$2 sensors=${3:-sensors.txt}
n=$(wc -l < "$sensors")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# One line per hour: 1 when occupied (the tape's hour is the middle of the hour).
tail -n +7 "$wea" | rcalc -e '$1=if($3-8,if(18-$3,1,0),0)' > "$tmp/occ"
occupied=$(total "$tmp/occ")
# Per hour and sensor k: DA, UDI below, within, above (4 columns a sensor).
expr=""
for ((k = 1; k <= n; k++)); do
    e="\$$((k + 1))"
    o=$(((k - 1) * 4))
    expr+="\$$((o + 1))=\$1*if($e-300+1e-9,1,0);"
    expr+="\$$((o + 2))=\$1*if(100-$e-1e-9,1,0);"
    expr+="\$$((o + 3))=\$1*if($e-100+1e-9,if(2000-$e+1e-9,1,0),0);"
    expr+="\$$((o + 4))=\$1*if($e-2000-1e-9,1,0);"
done
rcollate -ho -t "$ill" > "$tmp/hours"
rlam "$tmp/occ" "$tmp/hours" | rcalc -e "$expr" | total |
    rcollate -h -fa1 -ic $((4 * n)) -oc 4 |
    rcalc -e "s=100/$occupied;\$1=\$1*s;\$2=\$2*s;\$3=\$3*s;\$4=\$4*s" > "$tmp/pct"
rlam "$sensors" "$tmp/pct" | rcalc -e '$1=$1;$2=$2;$3=$7;$4=$8;$5=$9;$6=$10'
