#!/usr/bin/env bash
# rtrace's trace output (-o...t...) and its -ti/-te/-tI/-tE filters against RADIANCE: a box
# with white walls, a red block, a chrome (metal) plate and a lamp, seven rays, -ab 0.
# rtrace_trace_filter.expected is RADIANCE 5.4a's output, made with
#   oconv box.rad > box.oct    (RADIANCE's genbox and xform on PATH)
#   rtrace -h -ab 0 -ds 0 -dt 0 <filter> -omtmMLw box.oct < rays
# for each "=== <filter>" block. The same records, in the same order (each ray after the
# rays it spawned) with the same tabs and names must come out; numbers within 1e-3
# relative (the chrome plate's reflected weight is 3e-4 above RADIANCE's).
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cat > box.rad <<'RAD'
void light bright
0
0
3 10 10 10

void plastic white
0
0
5 .7 .7 .7 0 0

void plastic red
0
0
5 .7 .1 .1 0 0

void metal chrome
0
0
5 .8 .8 .8 .9 0

!genbox white room 4 4 3 -i
!genbox red block 1 1 1 | xform -t 1.5 2 0

chrome polygon plate
0
0
12 0.01 1 0.5  0.01 3 0.5  0.01 3 2  0.01 1 2

bright polygon lamp
0
0
12 1.5 1.5 2.9  1.5 2.5 2.9  2.5 2.5 2.9  2.5 1.5 2.9
RAD
cat > rays <<'RAYS'
2 0.5 1.5 0 1 -0.5
2 0.5 1.5 -1 0.5 0
2 0.5 1.5 0 1 0
2 0.5 1.5 0 0.5 1
2 2 1 -1 0.1 0.3
1 1 1 -1 1 -0.3
3 3 0.5 -1 -0.4 0.2
RAYS
printf 'red\nbright\n' > mods
"$RP_BIN/oconv" box.rad > box.oct
grep '^=== ' "$RP_SOURCE_DIR/tests/golden/rtrace_trace_filter.expected" | while IFS= read -r line; do
    filter=${line#=== }
    echo "$line"
    # shellcheck disable=SC2086
    "$RP_BIN/rtrace" -h -ab 0 -ds 0 -dt 0 $filter -omtmMLw box.oct < rays
done > got
# Field by field (tabs kept: empty fields are the indentation): names equal, numbers close.
awk -F'\t' 'NR == FNR { want[FNR] = $0; n = FNR; next }
    {
        if (FNR > n) { print "extra line " FNR ": " $0; bad = 1; next }
        k = split(want[FNR], w, "\t")
        if (k != NF) { print "line " FNR ": got \"" $0 "\", want \"" want[FNR] "\""; bad = 1; next }
        for (i = 1; i <= NF; ++i) {
            if ($i ~ /^-?[0-9.]+e[-+][0-9]+$/ && w[i] ~ /^-?[0-9.]+e[-+][0-9]+$/) {
                d = $i - w[i]; if (d < 0) d = -d
                s = w[i] < 0 ? -w[i] : w[i]
                if (d > 1e-3 * s + 1e-9) { print "line " FNR " field " i ": " $i " vs " w[i]; bad = 1 }
            } else if ($i != w[i]) { print "line " FNR ": got \"" $0 "\", want \"" want[FNR] "\""; bad = 1 }
        }
    }
    END { if (FNR < n) { print "missing lines after " FNR; bad = 1 } exit bad }' \
    "$RP_SOURCE_DIR/tests/golden/rtrace_trace_filter.expected" got

# A ray up through a glass pane (index 1.52, transmissivity .95) that meets a lamp above
# it: the transmitted ray is one tab in, a generation below the ray that made it, though
# it keeps its -lr level; the ray the pane reflects down lights the floor, whose shadow
# ray the pane passes on (three tabs: what it goes on as; two: the shadow ray). RADIANCE
# 5.4a's rtrace -h -ab 0 -otv, and the same with -oTv, writes (tabs, then the value):
#   1 40, 3 40, 2 34.88990, 1 0.4770224, 0 34.92705
cat > pane.rad <<'RAD'
void light lamp_mat 0 0 3 40 40 40
lamp_mat polygon lamp 0 0 12 1.6 1.6 2.99  1.6 2.4 2.99  2.4 2.4 2.99  2.4 1.6 2.99
void glass pane_glass 0 0 3 .95 .95 .95
pane_glass polygon pane 0 0 12 1.2 1.2 2.2  2.8 1.2 2.2  2.8 2.8 2.2  1.2 2.8 2.2
void plastic grey 0 0 5 .6 .6 .6 0 0
grey polygon floor 0 0 12 0 0 0  4 0 0  4 4 0  0 4 0
RAD
"$RP_BIN/oconv" pane.rad > pane.oct
tree() {  # SPEC SCENE RAY: "tabs value" per record
    echo "$3" | "$RP_BIN/rtrace" -h -ab 0 "$1" "$2" |
        awk -F '\t' '{ printf "%d %.4g\n", NF - 4, $(NF - 3) }'
}
for spec in -otv -oTv; do
    got=$(tree $spec pane.oct "2 2 1 0 0 1" | tr '\n' ' ')
    [ "$got" = "1 40 3 40 2 34.89 1 0.477 0 34.93 " ] || { echo "pane tree $spec: $got"; exit 1; }
done
# Under the pane, the four cells of the lamp (-ds 0.2 at weight 1): each shadow ray and its
# way on through the glass, as RADIANCE 5.4a's -oTv (values 34.82071, 34.76527 twice,
# 34.70191 under 40 each, then 0.3153386).
got=$(tree -otv pane.oct "1 1 1 0 0 -1" | tr '\n' ' ')
[ "$got" = "2 40 1 34.82 2 40 1 34.77 2 40 1 34.77 2 40 1 34.7 0 0.3153 " ] ||
    { echo "under the pane: $got"; exit 1; }

# -oT: every shadow ray tested, also one that meets its source directly (a sphere lamp)
# and one that leaves through a distant source (the sun), the brighter first; -ot shows
# neither. RADIANCE 5.4a's -oTvm: \t1e4 sunl, \t10 lamp, 0.1001321 grey.
cat > lamp.rad <<'RAD'
void light lamp 0 0 3 10 10 10
lamp sphere bulb 0 0 4 0 0 2 0.1
void light sunl 0 0 3 1e4 1e4 1e4
sunl source sun 0 0 4 0.3 0.3 1 0.5
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12 -2 -2 0  2 -2 0  2 2 0  -2 2 0
RAD
"$RP_BIN/oconv" lamp.rad > lamp.oct
got=$(echo "0 0 0.5 0 0 -1" | "$RP_BIN/rtrace" -h -ab 0 -oTvm lamp.oct | awk -F '\t' '{ print NF - 5, $(NF - 1) }' |
    tr '\n' ' ')
[ "$got" = "1 sunl 1 lamp 0 grey " ] ||
    { echo "-oT shadow rays: $got"; exit 1; }
[ "$(echo "0 0 0.5 0 0 -1" | "$RP_BIN/rtrace" -h -ab 0 -otv lamp.oct | wc -l)" = 1 ] ||
    { echo "-ot reports shadow rays that met their source"; exit 1; }
echo "rtrace trace filter golden: ok"
