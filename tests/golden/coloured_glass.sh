#!/bin/bash
# A room lit through strongly coloured glass (tests/data/coloured_glass, README there):
# the global photon map's floor irradiance against Cycles, summed over 20 points, within
# 3 % in each channel (measured: R 0.980, G 0.997; the pane's slab model in Cycles and
# RADIANCE's thin glass differ by about 1 % when grey), and the channels' balance R/G
# within 2.5 % of Cycles'. The classic calculation reads R 4 % low here (README), which
# this check would catch in the photon map. Then the dichroic filter of room_dichroic.rad
# with a spectral photon map set (mkpmap -cs 9): every one of the nine bands within 4 % of
# Cycles' (measured 0.976-0.997; classic reads 0.949 in the weakest band).
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/coloured_glass"
export RAYPATH="$SRC/lib"
"$BIN/oconv" "$data/room.rad" > "$tmp/r.oct" || exit 1
"$BIN/mkpmap" -apg "$tmp/g.pm" 300k -n 2 "$tmp/r.oct" 2> /dev/null || exit 1
"$BIN/rtrace" -h -u- -I -ab 1 -ad 1024 -aa 0 -n 2 -ap "$tmp/g.pm" 50 "$tmp/r.oct" \
    < "$data/points.txt" > "$tmp/pm" || exit 1
paste "$tmp/pm" "$data/cycles_rgb.txt" | awk '
    { for (i = 1; i <= 3; ++i) { p[i] += $i; c[i] += $(i + 3) } }
    END { r = p[1] / c[1]; g = p[2] / c[2]; b = p[3] / c[3]
          printf "photon map against Cycles: R %.3f G %.3f B %.3f, R/G %.3f\n", r, g, b, r / g
          bad = r < 0.97 || r > 1.03 || g < 0.97 || g > 1.03 || b < 0.97 || b > 1.03
          exit bad || r / g < 0.975 || r / g > 1.025 }' ||
    { echo "FAIL: coloured glass"; exit 1; }
"$BIN/oconv" "$data/room_dichroic.rad" > "$tmp/d.oct" &&
    "$BIN/mkpmap" -cs 9 -apg "$tmp/d.pm" 300k -n 2 "$tmp/d.oct" 2> /dev/null &&
    "$BIN/rtrace" -h -u- -I -cs 9 -co -ab 1 -ad 1024 -aa 0 -n 2 -ap "$tmp/d.pm" 50 "$tmp/d.oct" \
        < "$data/points.txt" > "$tmp/dpm" || exit 1
paste "$tmp/dpm" "$data/cycles_dichroic.txt" | awk '
    { for (i = 1; i <= 9; ++i) { p[i] += $i; c[i] += $(i + 9) } }
    END { printf "dichroic, spectral photon map against Cycles by band:"
          for (i = 1; i <= 9; ++i) { r = p[i] / c[i]; printf " %.3f", r; if (r < 0.96 || r > 1.04) bad = 1 }
          print ""; exit bad }' || { echo "FAIL: dichroic filter"; exit 1; }
