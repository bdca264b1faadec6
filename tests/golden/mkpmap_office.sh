#!/bin/bash
# examples/daylit_office (seam-cut window wall as photon port, genblinds metal slats,
# gensky sun and sky, antimatter sensor plane), the README's recipe at 100k + 100k photons:
# mkpmap stores its targets (within 2 %), and rtrace -I with both maps gives the 24 work-
# plane points a mean within 8 % of RADIANCE 5.4's on the same scene and photon counts:
# 42.87 W/m2, from
#   oconv -f scene.rad > r.oct
#   mkpmap -apg g.pm 100k -apc c.pm 100k -apo window_glass -aps sensor_plane -n 2 r.oct
#   rtrace -h -I -ab 1 -ad 1024 -as 0 -aa 0 -lw 1e-4 -ap g.pm 200 -ap c.pm 200 r.oct < points.txt
# Each mean carries ~2 % noise (200-photon estimates; the four points lit through the
# slats make half the mean), so 8 % is about 3 standard deviations of the difference.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
cd "$SRC/examples/daylit_office" || exit 1
"$BIN/oconv" scene.rad > "$tmp/o.oct" || exit 1
"$BIN/mkpmap" -apg "$tmp/g.pm" 100k -apc "$tmp/c.pm" 100k -apo window_glass -aps sensor_plane \
    -n 2 "$tmp/o.oct" > "$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }
for kind in Global Caustic; do
    n=$(awk -v k=$kind '$2 == k && $3 == "photons" {print $1}' "$tmp/log")
    awk -v n="${n:-0}" 'BEGIN { exit (n > 98000 && n < 102000) ? 0 : 1 }' || bad "$kind photons: ${n:-none}"
done
mean=$("$BIN/rtrace" -h -I -ab 1 -ad 1024 -as 0 -aa 0 -lw 1e-4 -ap "$tmp/g.pm" 200 -ap "$tmp/c.pm" 200 \
    -n 2 "$tmp/o.oct" < points.txt | awk '{s += 0.265 * $1 + 0.670 * $2 + 0.065 * $3} END {print s / NR}')
echo "mean work-plane irradiance: $mean W/m2 (RADIANCE 42.87)"
awk -v m="$mean" 'BEGIN { exit (m > 42.87 * 0.92 && m < 42.87 * 1.08) ? 0 : 1 }' || bad "mean $mean"
exit $fail
