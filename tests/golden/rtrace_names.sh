#!/bin/bash
# rtrace's names and normals as RADIANCE prints them (issue 43), byte for byte against
# tests/data/rtrace_names/radiance_omsMnN.txt, made by RADIANCE 5.4a with
#   oconv scene.rad > o.oct; rtrace -h -ab 0 -omsMnN o.oct < rays.txt
# - a ray exactly along the horizon reaches the 180 degree glow (it was black), and a ray
#   that leaves through a distant source names it (-om -os -oM printed "*"), n and N -d;
# - -on is the normal after the material turned the surface to the ray: flipped on the
#   back of plastic, as given for a mirror and a light; -oN as given.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/rtrace_names"
"$BIN/oconv" "$data/scene.rad" > "$tmp/o.oct" || exit 1
"$BIN/rtrace" -h -ab 0 -omsMnN "$tmp/o.oct" < "$data/rays.txt" > "$tmp/got.txt" || exit 1
diff "$data/radiance_omsMnN.txt" "$tmp/got.txt" || { echo "FAIL: differs from RADIANCE"; exit 1; }
printf '0 0 0 1 0 0\n' | "$BIN/rtrace" -h -ab 0 "$tmp/o.oct" > "$tmp/v.txt"
[ "$(awk '{print $1}' "$tmp/v.txt")" = "1.000000e+01" ] ||
    { echo "FAIL: horizon ray: $(cat "$tmp/v.txt"), RADIANCE 10"; exit 1; }
