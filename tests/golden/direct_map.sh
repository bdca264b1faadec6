#!/bin/bash
# Direct photon maps replace the direct calculation (manual 5.4, issue 42): for each kind
# of source in tests/data/direct_map (light polygon, sphere, ring, cylinder, spotlight,
# spotlight with its focus 1 m behind it, glow with a radius, the sun through an
# antimatter port), `rtrace -I -ab 0 -ap d.pm 500`
# on nine floor points against the classic `-ab 0` (-ds .01). Tolerance 6 % on the mean: 4 sigma
# of a density estimate of 500 photons over 9 points (4.5 % each, 1.5 % for the mean),
# the kernel's curvature bias is under 2 %. The map must be used: bandwidths 5 and 500
# give different numbers (before the fix both printed the classic value), and -apd with
# an antimatter port stores photons (before: "too many prepasses").
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/direct_map"
fail=0
mean() { awk '{s += 0.265 * $1 + 0.670 * $2 + 0.065 * $3} END {printf "%.4f", s / NR}'; }
for src in panel sphere ring tube spot spot_focus glow sun_port; do
    "$BIN/oconv" "$data/floor.rad" "$data/$src.rad" > "$tmp/$src.oct" || exit 1
    ports=()
    [ "$src" = sun_port ] && ports=(-apo portmat)
    "$BIN/mkpmap" -apd "$tmp/$src.pm" 300k "${ports[@]}" -apr 7 -n 2 "$tmp/$src.oct" 2> "$tmp/err" ||
        { echo "FAIL $src: mkpmap: $(cat "$tmp/err")"; fail=1; continue; }
    classic=$("$BIN/rtrace" -h -I -ab 0 -ds .01 -dj 0 "$tmp/$src.oct" < "$data/points.txt" | mean)
    "$BIN/rtrace" -h -I -ab 0 -ap "$tmp/$src.pm" 500 "$tmp/$src.oct" < "$data/points.txt" > "$tmp/p500"
    "$BIN/rtrace" -h -I -ab 0 -ap "$tmp/$src.pm" 5 "$tmp/$src.oct" < "$data/points.txt" > "$tmp/p5"
    photons=$(mean < "$tmp/p500")
    echo "$src: classic $classic, direct photons $photons"
    awk -v p="$photons" -v c="$classic" 'BEGIN { d = p / c - 1; exit (d < 0.06 && d > -0.06) ? 0 : 1 }' ||
        { echo "FAIL $src: direct photons $photons against classic $classic"; fail=1; }
    cmp -s "$tmp/p5" "$tmp/p500" && { echo "FAIL $src: the direct map is not used"; fail=1; }
done
exit $fail
