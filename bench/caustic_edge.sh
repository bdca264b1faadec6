#!/usr/bin/env bash
# The caustic edge table of issue 48 item 3 (rtrace -ape): tests/data/caustic_edge's
# mirror caustic, whose lit rectangle has a closed form, read by rtrace -I at sensors
# 0.25 .. 4 cm either side of its long edges (31 points along each of the two edges) and
# at 155 interior points, with several mkpmap -apr seeds. Columns: mean error over the
# points and seeds at each distance, as a fraction of the interior irradiance E0 (the
# truth outside is 0); "rsd": relative standard deviation over the interior points.
# Rows: (a) -ap c.pm 50, (b) -ap c.pm 50 500 (bias compensation), (c) -ap c.pm 50 -ape,
# and RADIANCE 5.4's (a) and (b) from its own maps when RADIANCE_BIN names its bin folder
# (RAYPATH set for it), e.g. RADIANCE_BIN=/tmp/rad/build/bin RAYPATH=/tmp/rad/build/lib.
# Also the lookup time with and without -ape over a larger sensor set.
#   bench/caustic_edge.sh [build [seeds [photons]]]   defaults: build, 8, 50k
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build}/tools
seeds=${2:-8}
photons=${3:-50k}
data=$root/tests/data/caustic_edge
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
"$data/sensors.sh" | cut -d' ' -f1 > lab1
"$data/sensors.sh" | cut -d' ' -f2- > pts
: > lab; for k in a b c ra rb; do : > "$k"; done
rad=${RADIANCE_BIN:-}
[ -n "$rad" ] && "$rad/oconv" "$data/scene.rad" > r.oct
for s in $(seq 1 "$seeds"); do
    cat lab1 >> lab
    "$bin/mkpmap" -apc c.pm "$photons" -apr "$s" -fo "$data/scene.rad" > /dev/null 2>&1
    "$bin/rtrace" -h -I -ap c.pm 50 "$data/scene.rad" < pts >> a 2> /dev/null
    "$bin/rtrace" -h -I -ap c.pm 50 500 "$data/scene.rad" < pts >> b 2> /dev/null
    "$bin/rtrace" -h -I -ap c.pm 50 -ape "$data/scene.rad" < pts >> c 2> /dev/null
    if [ -n "$rad" ]; then
        rm -f rc.pm
        "$rad/mkpmap" -apc rc.pm "$photons" -apr "$s" r.oct > /dev/null 2>&1
        "$rad/rtrace" -h -I -ap rc.pm 50 r.oct < pts >> ra 2> /dev/null
        "$rad/rtrace" -h -I -ap rc.pm 50 500 r.oct < pts >> rb 2> /dev/null
    fi
done
row() {  # NAME FILE
    [ -s "$2" ] || return 0
    "$data/analyse.sh" lab "$2" | awk -v name="$1" '
        $1 == "in" { rsd = $3; next } { t[++n] = $1; e[n] = $2 }
        END { if (name == "") { printf "%-30s", "distance from edge (cm, >0 in)"
                  for (i = 1; i <= n; i++) printf " %6s", t[i]; printf "    rsd\n"; exit }
              printf "%-30s", name; for (i = 1; i <= n; i++) printf " %+6.3f", e[i]
              printf "  %.3f\n", rsd }'
}
echo "caustic edge, $photons photons, $seeds seeds, bandwidth 50; mean error / E0"
row "" a
row "(a) -ap c.pm 50" a
row "(b) -ap c.pm 50 500" b
row "(c) -ap c.pm 50 -ape" c
row "RADIANCE 5.4 (a)" ra
row "RADIANCE 5.4 (b)" rb
# Lookup cost: 10x denser sensors along the edges, best of 3 (one thread).
"$data/sensors.sh" "-4 -2 -1 -0.5 -0.25 0 0.25 0.5 1 2 4" 0.001 | cut -d' ' -f2- > many
for opt in "" "-ape"; do
    best=
    for run in 1 2 3; do
        /usr/bin/time -f "%e" -o t "$bin/rtrace" -h -I -ap c.pm 50 $opt "$data/scene.rad" \
            < many > /dev/null 2> /dev/null
        t=$(cat t); best=$(awk -v a="$best" -v b="$t" 'BEGIN { print (a == "" || b < a) ? b : a }')
    done
    echo "rtrace -I, $(wc -l < many) points, -ap c.pm 50 ${opt:-(no -ape)}: $best s"
done
