#!/usr/bin/env bash
# The daylight reference scene (gensky sun + skyfunc sky, window port, antimatter sensor)
# through mkpmap with the README's command: photon count within 5 % of the target and
# AvgFlux within 3 % of RADIANCE 5.4's 1.84e-02 (../shared/validation/daylight/README.md),
# i.e. the same total flux reaches the room through the port.
set -euo pipefail
. "$(dirname "$0")/lib/shared.sh"
require_shared validation/daylight
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$RP_BIN/mkpmap" -apg "$tmp/g.pm" 200k -apo window_glass -aps sensor_plane -apr 1 -n 2 \
    "$RP_SHARED_DIR/validation/daylight/scene.rad" > "$tmp/log" 2>&1
info=$("$RP_BIN/getinfo" "$tmp/g.pm")
n=$(echo "$info" | awk -F'= ' '/NumPhotons/ {print $2}')
g=$(echo "$info" | sed -n 's/.*AvgFlux.*= \[\([^,]*\), \([^,]*\),.*/\2/p')
echo "NumPhotons $n (target 200000), AvgFlux green $g (RADIANCE 1.84e-02)"
awk -v n="$n" -v g="$g" 'BEGIN {
    if (n < 190000 || n > 210000) { print "photon count off target"; exit 1 }
    if (g < 1.84e-2 * 0.97 || g > 1.84e-2 * 1.03) { print "AvgFlux differs from RADIANCE"; exit 1 }
}'
