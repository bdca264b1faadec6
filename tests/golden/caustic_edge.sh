#!/bin/bash
# rtrace -ape (edge-aware photon density estimate, issue 48 item 3) on a mirror caustic
# with a closed form (tests/data/caustic_edge: a 0.5 degree sun reflected by a mirror
# onto a ceiling lights a rectangle with sharp long edges; analyse.sh holds the closed
# form). One 50k caustic map (-apr 1; the lit rectangle then holds about 630k photons per
# m2, so a 50-photon disc has radius R0 = 5 mm), rtrace -I with -ap c.pm 50 with and
# without -ape at sensors.sh's points: 62 per distance (31 along each long edge) at
# -4 .. 4 cm from the edge (< 0 outside), 155 interior points. Errors are means over a
# distance's points, as fractions of the interior irradiance E0.
#
# Tolerances, from bench/caustic_edge.sh (8 seeds; RADIANCE 5.4's own maps and rtrace
# give the same default errors to 0.01):
#  - dark side (-0.5, -1, -2, -4 cm): RADIANCE's estimate reads +0.22, +0.11, +0.04,
#    +0.004 (its disc grows until it holds 50 photons of the lit side), in sum 0.380
#    (over seeds 1..10: 0.365 .. 0.394, sd 0.008); -ape's reads +0.06, 0, 0, 0 (sum 0.060,
#    0.044 .. 0.074, sd 0.009: only at -0.5 cm, one search radius out, is the gap before
#    the nearest photons sometimes too small to be significant). The test wants the
#    default's sum in 0.30 .. 0.46 (the problem is there; RADIANCE 5.4's own reads 0.385)
#    and -ape's below a third of it: at 4 sd -ape's sum stays below 0.10, under 0.12,
#    while -ape fails it when its correction at -0.5 cm is halved (sum 0.14) or when
#    it no longer reads 0 from -1 cm out (sum 0.17 and more).
#  - the edge and the lit side (0 .. 4 cm), where -ape's radial model leaves RADIANCE's
#    estimate as it is unless an edge is significant: at most 2 of each distance's 62
#    values may differ from the default's (measured: none), and the mean errors agree to
#    0.01 (a single changed value moves the mean by at most 0.02 x its 0.5 relative change).
#  - interior (equal noise): at most 2 of the 155 values differ (the statistic's false
#    alarm rate is 0.02 % on uniform discs; measured here: none), the relative standard
#    deviations agree to 3 % of themselves, and the mean is E0 to 6 % (RADIANCE's
#    estimate reads 3 % high at k = 50; 4 sigma of the mean of 155 values of rsd 0.14,
#    spaced 2 R0 apart, is 4.5 %).
# Also: -defaults lists -ape+ only when it is on, and rpict accepts -ape.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
DATA="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/caustic_edge"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

"$BIN/mkpmap" -apc c.pm 50k -apr 1 "$DATA/scene.rad" > /dev/null 2>&1 || bad "mkpmap"
"$DATA/sensors.sh" | cut -d' ' -f1 > lab
"$DATA/sensors.sh" | cut -d' ' -f2- > pts
"$BIN/rtrace" -h -I -ap c.pm 50 "$DATA/scene.rad" < pts > a.txt 2> /dev/null || bad "rtrace"
"$BIN/rtrace" -h -I -ap c.pm 50 -ape "$DATA/scene.rad" < pts > c.txt 2> /dev/null ||
    bad "rtrace -ape"
"$DATA/analyse.sh" lab a.txt > a.err
"$DATA/analyse.sh" lab c.txt > c.err
echo "distance mean-error rms n (default | -ape):"
paste -d' ' a.err c.err

# Dark side.
paste -d' ' a.err c.err | awk '$1 < -0.3 { a += $2; c += $6 }
    END { printf "dark side sums: default %.4f, -ape %.4f\n", a, c
          exit !(a > 0.30 && a < 0.46 && c < a / 3) }' ||
    bad "dark side: the default should read 0.30..0.46 in sum, -ape under a third of it"

# Edge and lit side: how many values differ, and the means.
paste -d' ' lab a.txt c.txt | awk '$1 != "in" && $1 >= 0 && $2 != $5 { d[$1]++ }
    END { for (t in d) if (d[t] > 2) { print "distance " t ": " d[t] " values differ"; bad = 1 }
          exit bad }' || bad "-ape changed the estimate on the lit side"
paste -d' ' a.err c.err | awk '$1 != "in" && $1 >= 0 && ($2 - $6 > 0.01 || $6 - $2 > 0.01) {
    print "distance " $1 ": mean error " $2 " vs " $6; bad = 1 } END { exit bad }' ||
    bad "-ape's lit-side means differ from the default's"

# Interior: equal noise.
paste -d' ' lab a.txt c.txt | awk '$1 == "in" && $2 != $5 { d++ } END { exit d > 2 }' ||
    bad "-ape changed more than 2 of the 155 interior values"
paste -d' ' a.err c.err | awk '$1 == "in" { r = $7 / $3
        printf "interior: mean %.4f, rsd %.4f (default) %.4f (-ape)\n", $6, $3, $7
        exit !(r > 0.97 && r < 1.03 && $6 > 0.94 && $6 < 1.06) }' ||
    bad "interior: -ape's noise or mean differs from the default's"

# -defaults: radphoton's own option appears only when set; rpict takes it too.
"$BIN/rtrace" -defaults | grep -q -- '^-ape' && bad "-ape listed by -defaults when off"
"$BIN/rtrace" -ape -defaults | grep -q $'^-ape+\t' || bad "-ape+ missing from -defaults"
"$BIN/rpict" -ape -defaults | grep -q $'^-ape+\t' || bad "rpict -ape"
exit $fail
