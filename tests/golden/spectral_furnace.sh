#!/bin/bash
# Spectral rendering against a closed form, classic and with a spectral photon map set
# (issue 50): tests/data/spectral_furnace/sphere.rad, an integrating sphere (radius 1)
# whose reflectance rises from 0.1 at the long end to 0.5 at the short end in 9 bands
# (rtrace -cs 9), lit by a white lamp of radius 1 cm and radiance 1000 at z = 0.5. In each
# band k the reflected light is uniform over the inside (tests/analytic/integrating_sphere):
#   E_k = pi L (r/d)^2 cos(theta) + pi r^2 L rho_k / (R^2 (1 - rho_k)),
# the first term the lamp's own light at the point. Classic -ab 12 -aa 0 -ad 2048 -as 0:
# the 12 bounces leave out rho^12 <= 2.4e-4; measured spread 0.3 %: each band at each
# point within 1 %. Photon map: mkpmap -cs 9 -apg 500k (each pass its own file), -ab -1
# -ap 1000: a 1000-photon estimate spreads 3.2 %, and the three bands of a pass share
# photons, so the mean over the 6 points spreads 1.3 %: within 4 % (3 sigma), each point
# within 10 %. rcontrib -cs 9 with the classic options gives the lamp's coefficients:
# the same closed form over L. Then what must fail does: a spectral map rendered in RGB or another
# sampling, an RGB map in spectral rendering; and -cs 3 is RGB: the map of mkpmap -cs 3
# is the plain map, byte for byte after the command line.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data="$SRC/tests/data/spectral_furnace"
export RAYPATH="$SRC/lib"
"$BIN/oconv" "$data/sphere.rad" > "$tmp/s.oct" || exit 1
fail=0
"$BIN/rtrace" -h -I -cs 9 -co -ab 12 -aa 0 -ad 2048 -as 0 -lw 1e-5 "$tmp/s.oct" \
    < "$data/points.txt" > "$tmp/classic" || exit 1
"$BIN/mkpmap" -cs 9 -apg "$tmp/g.pm" 500k "$tmp/s.oct" 2> "$tmp/mk.err" || { cat "$tmp/mk.err"; exit 1; }
for f in g.pm g.pm.3-5 g.pm.6-8; do
    [ -s "$tmp/$f" ] || { echo "FAIL: mkpmap -cs 9 wrote no $f"; fail=1; }
done
"$BIN/rtrace" -h -I -cs 9 -co -ab -1 -ap "$tmp/g.pm" 1000 "$tmp/s.oct" \
    < "$data/points.txt" > "$tmp/photons" || exit 1
check() {  # name per-point-tolerance mean-tolerance file
    paste "$data/points.txt" "$4" | awk -v name="$1" -v tp="$2" -v tm="$3" '
        function closed(k) {
            rho = 0.1 + 0.05 * k  # band 0 is the longest wavelength
            dx = -$1; dy = -$2; dz = 0.5 - $3; d = sqrt(dx * dx + dy * dy + dz * dz)
            c = (dx * $4 + dy * $5 + dz * $6) / d; if (c < 0) c = 0
            return 3.14159265 * 1000 * (0.01 / d) ^ 2 * c + 3.14159265e-1 * rho / (1 - rho)
        }
        { for (k = 0; k < 9; ++k) {
              e = closed(k); d = ($(7 + k) - e) / e; sum[k] += d
              if (d > tp || d < -tp) {
                  printf "FAIL: %s point %d band %d: %.4f, closed form %.4f\n", name, NR, k, $(7 + k), e
                  bad = 1 } } }
        END { for (k = 0; k < 9; ++k) {
                  m = sum[k] / NR
                  printf "%s band %d: mean deviation %+.2f %%\n", name, k, 100 * m
                  if (m > tm || m < -tm) { print "FAIL: " name " mean out of tolerance"; bad = 1 } }
              exit bad }' || fail=1
}
check classic 0.01 0.01 "$tmp/classic"
# rcontrib -cs 9: the lamp's coefficients (irradiance per unit radiance) are the same
# closed form over 1000, and its header names the sampling as RADIANCE 6.1a's does.
"$BIN/rcontrib" -h -I -cs 9 -ab 12 -aa 0 -ad 2048 -as 0 -lw 1e-5 -m emitter "$tmp/s.oct" \
    < "$data/points.txt" | awk '{ for (i = 1; i <= NF; ++i) $i *= 1000; print }' > "$tmp/contrib" ||
    { echo "FAIL: rcontrib -cs 9"; fail=1; }
check rcontrib 0.01 0.01 "$tmp/contrib"
echo "0 0 0 0 0 -1" | "$BIN/rcontrib" -cs 9 -m emitter "$tmp/s.oct" |
    grep -E '^(NCOMP|WAVELENGTH_SPLITS)=' > "$tmp/h"
printf '%s\n' "NCOMP=9" "WAVELENGTH_SPLITS= 780 588 480 380" | diff - "$tmp/h" ||
    { echo "FAIL: rcontrib -cs 9 header"; fail=1; }
check photons 0.10 0.04 "$tmp/photons"
# Each sampling reads only its own maps.
err() { "$BIN/rtrace" -h -I "$@" "$tmp/s.oct" < "$data/points.txt" 2>&1 > /dev/null; }
msg=$(err -ab -1 -ap "$tmp/g.pm" 100)
case "$msg" in *"spectral photon map (NCOMP=9)"*) ;; *) echo "FAIL: RGB reading a spectral map: $msg"; fail=1 ;; esac
msg=$(err -cs 9 -cw 400 700 -ab -1 -ap "$tmp/g.pm" 100)
case "$msg" in *"not of the rendering's -cs 9 -cw 400 700"*) ;; *) echo "FAIL: other sampling: $msg"; fail=1 ;; esac
"$BIN/mkpmap" -apg "$tmp/rgb.pm" 20k "$tmp/s.oct" 2> /dev/null || exit 1
msg=$(err -cs 9 -ab -1 -ap "$tmp/rgb.pm" 100)
case "$msg" in *"an RGB photon map"*) ;; *) echo "FAIL: spectral reading an RGB map: $msg"; fail=1 ;; esac
"$BIN/mkpmap" -cs 3 -apg "$tmp/rgb3.pm" 20k "$tmp/s.oct" 2> /dev/null || exit 1
cmp <(tail -n +3 "$tmp/rgb.pm") <(tail -n +3 "$tmp/rgb3.pm") ||
    { echo "FAIL: mkpmap -cs 3 differs from the RGB map"; fail=1; }
[ "$fail" -eq 0 ] && echo ok
exit $fail
