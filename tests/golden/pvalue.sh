#!/usr/bin/env bash
# pvalue -r turns a sensor grid (rtrace -h -I -ov output: one "r g b" line per sensor,
# top row first) into a picture falsecolor reads; pvalue forward reads it back with
# RADIANCE's coordinates (y from the bottom). Errors are one line naming the input.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

# 4 x 3 grid: irradiance i in sensor i (1..12), tab-separated as rtrace writes it.
for i in $(seq 1 12); do printf '%s\t%s\t%s\t\n' "$i" "$i" "$i"; done > grid.txt
"$RP_BIN/pvalue" -r -h -H -d -y 3 +x 4 < grid.txt > grid.hdr
[ "$("$RP_BIN/getinfo" -d grid.hdr)" = "grid.hdr: -Y 3 +X 4" ]
"$RP_BIN/getinfo" grid.hdr | grep -q "pvalue -r -h -H -d -y 3 +x 4$"
"$RP_BIN/falsecolor" -i grid.hdr > grid_fc.hdr
"$RP_BIN/getinfo" -d grid_fc.hdr | grep -q "+X 104$"

# Sensor 4 is the top row's right end: x 3, y 2 from the bottom; RGBE keeps 4.0 exactly
# in the mantissa and RADIANCE decodes the byte's middle (4 * 128.5/128).
"$RP_BIN/pvalue" -h -H grid.hdr > values
[ "$(wc -l < values)" -eq 12 ]
line=$(sed -n 4p values | tr -s ' ' | sed 's/^ //')
[ "$line" = "3 2 4.016e+00 4.016e+00 4.016e+00" ] || { echo "pixel 4: $line"; exit 1; }
# Brightness only, data only: the last sensor (bottom right), 12 * 192.5/192.
[ "$("$RP_BIN/pvalue" -h -H -d -b grid.hdr | tail -1 | tr -d ' ')" = "1.203e+01" ] ||
    { "$RP_BIN/pvalue" -h -H -d -b grid.hdr | tail -1; exit 1; }
# Values -> picture -> values again keeps the header and resolution string.
"$RP_BIN/pvalue" grid.hdr | "$RP_BIN/pvalue" -r > again.hdr
[ "$("$RP_BIN/pvalue" -h -H again.hdr)" = "$(cat values)" ]

expect_error() {  # pattern, then the arguments (input on stdin from $input)
    local pattern=$1; shift
    if "$RP_BIN/pvalue" "$@" < "$input" > out 2> err; then echo "pvalue $* should fail"; exit 1; fi
    [ "$(wc -l < err)" -eq 1 ] || { cat err; exit 1; }
    grep -q "$pattern" err || { cat err; exit 1; }
}
input=grid.txt
expect_error "^pvalue: standard input:12: input ends after 12 of 15 pixels" -r -h -H -d -y 3 +x 5
expect_error "^pvalue: bad option '-q'" -q
expect_error "^pvalue: missing.txt: cannot open" -r missing.txt
sed '5s/5/x5/' grid.txt > bad.txt; input=bad.txt
expect_error "^pvalue: standard input:5: 'x5' is not a number" -r -h -H -d -y 3 +x 4
echo ok
