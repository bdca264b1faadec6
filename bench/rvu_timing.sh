#!/usr/bin/env bash
# rvu's responsiveness on the Cornell box at 512 x 512 with the demo's photon maps:
# seconds from launch to the first (coarse) picture, and to the fully refined picture,
# beside rpict's time for the same picture (-ps 1: every pixel traced, as rvu -ps 1
# refines) and for rpict's default adaptive sampling (-ps 4). Medians of $RUNS runs.
#   bench/rvu_timing.sh [build/tools]     (RUNS=3, THREADS=2, PHOTONS=250k)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$root/build/tools}" && pwd)
runs=${RUNS:-3}; threads=${THREADS:-2}; photons=${PHOTONS:-250k}
tmp=$(mktemp -d); pid=
trap '[ -n "$pid" ] && kill $pid 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$root/examples/cornell"
"$bin/mkpmap" -apg "$tmp/g.pm" "$photons" -apc "$tmp/c.pm" "$photons" -n "$threads" scene.rad 2> /dev/null
# rvu's defaults written out, so that both programs compute the same picture.
opts="-vf view.vf -x 512 -y 512 -u- -dt .1 -dc .25 -dr 0 -dp 128 -ds 0 -st .3 -ss 1 -lr 6 -lw .01
      -ab 1 -aa 0 -ad 256 -as 0 -ap $tmp/g.pm 50 -ap $tmp/c.pm 50 -n $threads"
now() { date +%s.%N; }
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

for r in $(seq "$runs"); do
    t0=$(now)
    "$bin/rvu" $opts -ps 1 scene.rad 2> "$tmp/err" &
    pid=$!
    until grep -q "rvu: open" "$tmp/err"; do sleep 0.005; done
    t1=$(now)
    url=$(grep -o 'http://[^ ]*' "$tmp/err"); base=${url%%/\?t=*}; token=${url##*t=}
    g=0
    while :; do
        s=$(curl -s -H "X-Rvu-Token: $token" "$base/state?since=$g")
        g=$(echo "$s" | sed 's/.*"generation":\([0-9]*\).*/\1/')
        echo "$s" | grep -q '"done":true' && break
    done
    t2=$(now)
    curl -s -H "X-Rvu-Token: $token" --data-binary quit "$base/command" > /dev/null
    wait $pid; pid=
    echo "$t0 $t1 $t2" | awk '{printf "%.3f %.3f\n", $2 - $1, $3 - $1}' >> "$tmp/rvu"
    t0=$(now); "$bin/rpict" $opts -ps 1 scene.rad > /dev/null 2>&1; t1=$(now)
    "$bin/rpict" $opts scene.rad > /dev/null 2>&1; t2=$(now)
    echo "$t0 $t1 $t2" | awk '{printf "%.3f %.3f\n", $2 - $1, $3 - $2}' >> "$tmp/rpict"
done
first=$(cut -d' ' -f1 "$tmp/rvu" | median); full=$(cut -d' ' -f2 "$tmp/rvu" | median)
ps1=$(cut -d' ' -f1 "$tmp/rpict" | median); ps4=$(cut -d' ' -f2 "$tmp/rpict" | median)
echo "Cornell box 512x512, -ab 1 -ap global+caustic ($photons each), -n $threads, median of $runs"
printf "  rvu first coarse picture      %6.2f s\n" "$first"
printf "  rvu fully refined (-ps 1)     %6.2f s   (%.2fx rpict -ps 1)\n" "$full" "$(echo "$full $ps1" | awk '{print $1/$2}')"
printf "  rpict -ps 1                   %6.2f s\n" "$ps1"
printf "  rpict -ps 4 (default)         %6.2f s\n" "$ps4"
