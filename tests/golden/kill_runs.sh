#!/bin/bash
# Runs killed at random moments (SIGKILL, 20 times each, delays from a fixed-seed draw over
# one uninterrupted run's duration):
#  - mkpmap never leaves a partial map, or any other file, at or beside its target: a map
#    that is there is the uninterrupted run's, byte for byte (they are written to an
#    unnamed temporary file and linked when complete);
#  - rpict -o -z leaves what RADIANCE's rpict leaves, a picture and depth file cut at a
#    scanline, and rpict -ro finishes them to the uninterrupted run's pixels and depths,
#    leaving no temporary file.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SCENE="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/examples/cornell/scene.rad"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }
now() { date +%s.%N; }
# delays N SECONDS SEED: N delays uniform in [0, SECONDS)
delays() { awk -v n="$1" -v t="$2" -v s="$3" 'BEGIN { srand(s); for (i = 0; i < n; i++) printf "%.3f\n", t * rand() }'; }
# run_killed DELAY CMD...: starts CMD in the background and kills it after DELAY seconds
run_killed() {
    local d=$1; shift
    "$@" > /dev/null 2>&1 &
    local pid=$!
    sleep "$d"
    kill -9 "$pid" 2> /dev/null
    wait "$pid" 2> /dev/null
}

# mkpmap: two maps, so that kills also fall between the first file and the second.
mkdir ref && cd ref || exit 1
MK=(-apg g.pm 300k -apc c.pm 100k -apr 4 -n 2 "$SCENE")
t0=$(now); "$BIN/mkpmap" "${MK[@]}" 2> /dev/null || bad "uninterrupted mkpmap"; t1=$(now)
cd .. || exit 1
span=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print (b - a) * 1.1 }')
k=0 killed=0
for d in $(delays 20 "$span" 11); do
    k=$((k + 1))
    mkdir m$k && cd m$k || exit 1
    run_killed "$d" "$BIN/mkpmap" "${MK[@]}"
    for f in $(ls -A); do
        case $f in
            g.pm | c.pm) cmp -s "$f" "../ref/$f" || bad "mkpmap killed at $d s: partial $f" ;;
            *) bad "mkpmap killed at $d s left $f" ;;
        esac
    done
    [ -e g.pm ] && [ -e c.pm ] || killed=$((killed + 1))
    # The next run goes through, and leaves nothing else behind.
    "$BIN/mkpmap" -fo "${MK[@]}" 2> /dev/null || bad "mkpmap after a kill"
    [ "$(ls -A | tr '\n' ' ')" = "c.pm g.pm " ] || bad "after a kill: $(ls -A)"
    cd .. && rm -rf m$k
done
[ $killed -ge 10 ] || bad "only $killed of 20 mkpmap runs were cut short"

# rpict -o -z, then -ro.
RP=(-u- -x 96 -y 96 -ab 1 -aa 0 -ad 64 -as 0 -vp 2.75 0.05 2.75 -vd 0 1 0 -vh 85 -vv 85)
pix() { sed '1,/^$/d' "$1" | md5sum; }
"$BIN/oconv" "$SCENE" > scene.oct
t0=$(now); "$BIN/rpict" "${RP[@]}" -z ref.z -o ref.hdr scene.oct 2> /dev/null || bad "rpict"; t1=$(now)
span=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print (b - a) * 1.1 }')
k=0 cut=0
for d in $(delays 20 "$span" 12); do
    k=$((k + 1))
    mkdir p$k && cd p$k || exit 1
    run_killed "$d" "$BIN/rpict" "${RP[@]}" -z p.z -o p.hdr ../scene.oct
    if [ -e p.hdr ] && [ "$(pix p.hdr)" != "$(pix ../ref.hdr)" ]; then
        cut=$((cut + 1))
        "$BIN/rpict" "${RP[@]}" -z p.z -ro p.hdr ../scene.oct 2> err || bad "rpict -ro after $d s: $(cat err)"
    elif [ ! -e p.hdr ]; then
        "$BIN/rpict" "${RP[@]}" -z p.z -o p.hdr ../scene.oct 2> /dev/null || bad "rpict after $d s"
    fi
    [ "$(pix p.hdr)" = "$(pix ../ref.hdr)" ] || bad "rpict killed at $d s: picture not recovered"
    cmp -s p.z ../ref.z || bad "rpict killed at $d s: depths not recovered"
    [ "$(ls -A | grep -v '^err$' | tr '\n' ' ')" = "p.hdr p.z " ] || bad "rpict after a kill: $(ls -A)"
    cd .. && rm -rf p$k
done
[ $cut -ge 10 ] || bad "only $cut of 20 rpict runs were cut short"
echo "cut short: mkpmap $killed of 20, rpict $cut of 20"
exit $fail
