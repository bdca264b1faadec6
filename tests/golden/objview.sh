#!/usr/bin/env bash
# objview: RADIANCE's lights and standard view around an object, through rad; -r renders
# the view to a picture (a red ball: red in the middle, the dim blue glow at the corner),
# a scene on standard input (pmapdump's photons) works as a file, and bad input is one
# line.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
export PATH="$RP_BIN:$PATH"
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
fail=0
printf 'void plastic red 0 0 5 .7 .1 .1 0 0\nred sphere ball 0 0 4 0 0 0 1\n' > ball.rad
objview -s -r ball.hdr ball.rad
[ "$(getinfo -d < ball.hdr)" = "-Y 512 +X 512" ] || { echo "FAIL: size $(getinfo -d < ball.hdr)"; fail=1; }
# pvalue -h -H -o: pixels as RGB, one a line, top row first.
pvalue -h -H -o ball.hdr | awk 'NR == 256 * 512 + 257 { r = $3; g = $4; b = $5 }
    NR == 1 { cr = $3; cb = $5 }
    END { if (!(r > 3 * g && r > 3 * b)) { print "FAIL: centre " r, g, b; exit 1 }
          if (!(cb > cr && cb > 0)) { print "FAIL: corner " cr, cb; exit 1 } }' || fail=1
objview -s -v Zl -r top.hdr < ball.rad
[ "$(getinfo -d < top.hdr)" = "-Y 512 +X 512" ] || { echo "FAIL: stdin scene"; fail=1; }
getinfo top.hdr | grep -q "VIEW= -vtl" || { echo "FAIL: -v Zl"; fail=1; }
expect_error 'objview: bad option: -q' objview -q ball.rad
expect_error 'objview: glrad output' objview -g ball.rad
expect_error 'objview: none.rad: cannot open scene file' objview -r x.hdr none.rad
exit $fail
