#!/usr/bin/env bash
# A false-colour plan of one column of a metrics file (metrics.sh: x y DA300 UDI...),
# made the way RADIANCE users make one: the sensor values as a picture (pvalue -r), false
# colour with a legend (falsecolor), PNG (ra_png). Sensors lie on a 0.5 m grid; each
# becomes a square of CELL pixels.
# Usage: ./plan.sh metrics.txt [column] [label] [out.png]   (default: 3, "DA300 %",
# da300.png; tools on PATH)
set -euo pipefail
cd "$(dirname "$0")"
metrics=$1 col=${2:-3} label=${3:-DA300 %} out=${4:-da300.png} cell=${CELL:-40}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# Top scanline first: the grid's rows from the largest y down, each repeated cell times.
awk -v k="$cell" -v col="$col" '!/^#/ { c = int($1 / 0.5); r = int($2 / 0.5); v[r "," c] = $col
        if (c > nc) nc = c; if (r > nr) nr = r }
    END { for (r = nr; r >= 0; r--) for (y = 0; y < k; y++) for (c = 0; c <= nc; c++)
              for (x = 0; x < k; x++) print v[r "," c]
          print (nr + 1) * k, (nc + 1) * k > "/dev/stderr" }' "$metrics" > "$tmp/v.txt" 2> "$tmp/size"
read -r h w < "$tmp/size"
pvalue -r -h -H -b -d -y "$h" +x "$w" "$tmp/v.txt" > "$tmp/plan.hdr"
falsecolor -i "$tmp/plan.hdr" -s 100 -n 10 -m 1 -l "$label" > "$tmp/fc.hdr"
ra_png "$tmp/fc.hdr" "$out"
