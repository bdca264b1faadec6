#!/usr/bin/env bash
# rpict draws light sources thinner than its pixel sampling into the picture (RADIANCE's
# bitty sources, srcdraw.c): a 0.5-degree sun and a small bulb, in a perspective view and
# an angular fisheye, against RADIANCE 5.4's pictures (tests/data/bitty_sources): the
# same source pixels, each within 2 %, and the picture's total within 2 %. The same
# pixels with -n 2; with -dv- the sources are gone.
set -euo pipefail
data="$RP_SOURCE_DIR/tests/data/bitty_sources"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
persp="-vtv -vp 0 0 1 -vd 0.3 1 0.25 -vu 0 0 1 -vh 40 -vv 40 -x 63 -y 63 -ps 1 -pj 0 -ab 0"
fish="-vta -vp 0 0 1 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180 -x 64 -y 64 -ps 2 -pj 0 -ab 0"

brightness() { "$RP_BIN/pvalue" -h -H -b -o "$1"; }  # "x y value" per pixel

# Source pixels are those above 3 in either picture (sky 1.2, ground below 1).
compare() {  # name, RADIANCE's picture, ours
    paste <(brightness "$2") <(brightness "$3") | awk -v name="$1" '
        $1 != $4 || $2 != $5 { print name ": pixel order differs"; bad = 1; exit }
        { tr += $3; to += $6 }
        $3 > 3 || $6 > 3 {
            n++
            if ($6 < 0.98 * $3 || $6 > 1.02 * $3) {
                printf "%s: source pixel %d %d: ours %g, RADIANCE %g\n", name, $1, $2, $6, $3
                bad = 1
            }
        }
        END {
            if (bad) exit 1
            if (n < 2) { print name ": only " n " source pixels"; exit 1 }
            if (to < 0.98 * tr || to > 1.02 * tr) {
                printf "%s: total ours %g, RADIANCE %g\n", name, to, tr; exit 1
            }
        }'
}

"$RP_BIN/rpict" $persp "$data/scene.rad" > persp.hdr
compare perspective "$data/persp.hdr" persp.hdr
"$RP_BIN/rpict" $fish "$data/scene.rad" > fish.hdr
compare fisheye "$data/fish.hdr" fish.hdr

# Threads draw nothing differently.
"$RP_BIN/rpict" $fish -n 2 "$data/scene.rad" > fish2.hdr
cmp -s <(sed '1,/^$/d' fish.hdr) <(sed '1,/^$/d' fish2.hdr)

# -dv-: no source seen, none drawn.
"$RP_BIN/rpict" $persp -dv- "$data/scene.rad" > dark.hdr
brightness dark.hdr | awk '$3 > 3 { print "-dv-: pixel " $1 " " $2 " is " $3; bad = 1 }
                           END { exit bad }'
echo "rpict bitty sources golden: ok"
