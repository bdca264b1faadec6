#!/bin/bash
# A sunlit room with Lambertian venetian blinds in daylight's spectrum (issue 50): the
# room of tests/data/cycles_blinds (grey surfaces, independent Cycles reference in
# golden.cycles_blinds) with its sun modified by lib/cie_d65.dat (CIE D65, luminance
# factor 1), rendered with a spectral photon map set (mkpmap -cs 9 through the window's
# antimatter port, rtrace -cs 9 -ab 1) beside the RGB map of the plain room. With grey
# surfaces band k of every result is the RGB result times D65's band k (read from a glow
# seen with rtrace -cs 9 -co): each band at each of 20 work-plane points within 2 % of
# that (photons follow the same paths in every pass, since grey albedos make the same
# choices; the 0.6 % left is the flux's RGBE rounding when a pass's three bands differ).
# And melanopic work-plane illuminance (-pM): photon map against classic (-ab 16, as
# golden.cycles_blinds), the mean of the 20 points within 5 % (classic spreads about 7 %
# a point at -ad 1024, 1.6 % on the mean; the photon map's bias here is under 2 %).
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/cycles_blinds"
export RAYPATH="$SRC/lib"
head -20 "$data/points.txt" > "$tmp/points"
printf 'void antimatter port_mat 1 void 0 0\nport_mat polygon port 0 0 12 .5 0 1  .5 0 2  3.5 0 2  3.5 0 1\n' \
    > "$tmp/port.rad"
sed 's/^void light solar$/void specfile d65 1 cie_d65.dat 0 0\nd65 light solar/' \
    "$data/room_open.rad" > "$tmp/room_d65.rad"
grep -q '^d65 light solar' "$tmp/room_d65.rad" || { echo "FAIL: no spectral sun"; exit 1; }
"$BIN/oconv" "$tmp/room_d65.rad" "$data/slats_lambertian.rad" "$tmp/port.rad" > "$tmp/s.oct" &&
    "$BIN/oconv" "$data/room_open.rad" "$data/slats_lambertian.rad" "$tmp/port.rad" > "$tmp/g.oct" ||
    exit 1
"$BIN/mkpmap" -cs 9 -apg "$tmp/s.pm" 1m -apo port_mat -apr 1 -n 2 "$tmp/s.oct" 2> /dev/null &&
    "$BIN/mkpmap" -apg "$tmp/g.pm" 1m -apo port_mat -apr 1 -n 2 "$tmp/g.oct" 2> /dev/null || exit 1
gather="-h -u- -I -ab 1 -ad 1024 -aa 0 -n 2"
"$BIN/rtrace" $gather -cs 9 -co -ap "$tmp/s.pm" 50 "$tmp/s.oct" < "$tmp/points" > "$tmp/spec" &&
    "$BIN/rtrace" $gather -ap "$tmp/g.pm" 50 "$tmp/g.oct" < "$tmp/points" > "$tmp/rgb" || exit 1
printf 'void specfile d65 1 cie_d65.dat 0 0\nd65 glow g 0 0 4 1 1 1 0\ng polygon p 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n' \
    > "$tmp/d65.rad"
"$BIN/oconv" "$tmp/d65.rad" > "$tmp/d.oct" &&
    echo "0.5 0.5 1 0 0 -1" | "$BIN/rtrace" -h -cs 9 -co -ab 0 "$tmp/d.oct" 2> /dev/null > "$tmp/bands" ||
    exit 1
fail=0
awk 'FILENAME == ARGV[1] { for (i = 1; i <= NF; ++i) d[i] = $i; next }
     FILENAME == ARGV[2] { g[FNR] = $1; next }
     { for (i = 1; i <= NF; ++i) {
           r = $i / (g[FNR] * d[i]) - 1; if (r < 0) r = -r; if (r > worst) worst = r
           if (r > 0.02) { printf "FAIL: point %d band %d: %g, RGB x D65 %g\n", FNR, i, $i, g[FNR] * d[i]; bad = 1 } } }
     END { printf "spectral bands against RGB x D65: largest difference %.2f %%\n", 100 * worst; exit bad }' \
    "$tmp/bands" "$tmp/rgb" "$tmp/spec" || fail=1
"$BIN/rtrace" -h -u- -I -cs 9 -pM -ab 16 -lr -20 -ad 1024 -aa 0 -lw 1e-5 -n 2 "$tmp/s.oct" \
    < "$tmp/points" > "$tmp/mel_classic" &&
    "$BIN/rtrace" $gather -cs 9 -pM -ap "$tmp/s.pm" 50 "$tmp/s.oct" < "$tmp/points" > "$tmp/mel_pm" || exit 1
paste "$tmp/mel_classic" "$tmp/mel_pm" | awk '{ c += $1; p += $2 }
    END { d = p / c - 1; printf "melanopic work plane: classic %.1f, photon map %.1f (%+.2f %%)\n", c / NR, p / NR, 100 * d
          exit (d > 0.05 || d < -0.05) }' || { echo "FAIL: melanopic mean"; fail=1; }
# A grey BSDF (the tensor tree tests/data/bsdf/ttree4.xml as a film in the opening, as
# golden.bsdf_final_gather) is the same in every band: classic -ab 1 through it, each
# band the RGB result times D65's, to 1e-5 (the passes draw the same samples).
export RAYPATH="$SRC/tests/data/bsdf:$SRC/lib"
head -12 "$data/points.txt" > "$tmp/p12"
"$BIN/oconv" "$tmp/room_d65.rad" "$SRC/tests/data/bsdf_window/window_in.rad" > "$tmp/bs.oct" &&
    "$BIN/oconv" "$data/room_open.rad" "$SRC/tests/data/bsdf_window/window_in.rad" > "$tmp/bg.oct" ||
    exit 1
"$BIN/rtrace" -h -u- -I -ab 1 -ad 256 -aa 0 -cs 9 -co "$tmp/bs.oct" < "$tmp/p12" > "$tmp/bspec" &&
    "$BIN/rtrace" -h -u- -I -ab 1 -ad 256 -aa 0 "$tmp/bg.oct" < "$tmp/p12" > "$tmp/brgb" || exit 1
awk 'FILENAME == ARGV[1] { for (i = 1; i <= NF; ++i) d[i] = $i; next }
     FILENAME == ARGV[2] { g[FNR] = $1; next }
     { for (i = 1; i <= NF; ++i) { r = $i / (g[FNR] * d[i]) - 1; if (r < 0) r = -r; if (r > w) w = r } }
     END { printf "grey BSDF window, spectral bands against RGB x D65: %.1e\n", w; exit w > 1e-5 }' \
    "$tmp/bands" "$tmp/brgb" "$tmp/bspec" || { echo "FAIL: grey BSDF in spectral rendering"; fail=1; }
[ "$fail" -eq 0 ] && echo ok
exit $fail
