#!/usr/bin/env bash
# rpreview loads the example scene (text and oconv'd), writes a picture of the requested
# size whose header getinfo reads; a bad scene gives a one-line file:line error, exit 1.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$RP_SOURCE_DIR/examples/cornell"
"$RP_BIN/oconv" scene.rad > "$tmp/c.oct"
"$RP_BIN/rpreview" -vf view.vf -x 64 -y 64 -o "$tmp/a.hdr" scene.rad 2> "$tmp/log"
grep -q "20 primitives" "$tmp/log"
"$RP_BIN/rpreview" -vf view.vf -x 64 -y 64 "$tmp/c.oct" > "$tmp/b.hdr" 2>/dev/null

[ "$("$RP_BIN/getinfo" -d "$tmp/a.hdr")" = "$tmp/a.hdr: -Y 64 +X 64" ]
grep -a -q "^VIEW= -vtv -vp 2.75 0.05 2.75" "$tmp/a.hdr"
# pixels of the two runs are identical (same view, same scene)
tail -c 4096 "$tmp/a.hdr" > "$tmp/ta"; tail -c 4096 "$tmp/b.hdr" > "$tmp/tb"; cmp -s "$tmp/ta" "$tmp/tb"
printf 'void plastic red\n0\n0\n4 1 0 0 0\n' > "$tmp/bad.rad"
if "$RP_BIN/rpreview" "$tmp/bad.rad" > /dev/null 2> "$tmp/err"; then exit 1; fi
[ "$(wc -l < "$tmp/err")" -eq 1 ]
grep -q "bad.rad:1: " "$tmp/err"
echo "rpreview golden: ok"
