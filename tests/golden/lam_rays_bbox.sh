#!/usr/bin/env bash
# rlam, vwrays and getbbox against RADIANCE 5.4's own outputs on the same inputs: every
# line of tests/data/lam_rays_bbox/cases.txt is run in that folder and its standard output
# must be byte-identical to expected/NN.out (how those were made: README.md there). Then
# bad input: one line naming the problem, non-zero exit.
set -u
DATA="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/lam_rays_bbox"
: "${RP_BIN:?RP_BIN not set}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
cd "$DATA" || exit 1
fail=0
run_cases 50

expect_error "^rlam: missing.txt: cannot open file$" rlam a.txt missing.txt
expect_error "^rlam: no input streams$" rlam -t,
expect_error "^rlam: bad option '-iq'$" rlam -iq a.txt
expect_error "^rlam: bad option '-q'$" rlam -q a.txt
expect_error "^rlam: input size too big$" rlam -id9000 a.txt
expect_error "^vwrays: usage: vwrays" vwrays
expect_error "^vwrays: bad x resolution$" vwrays -x 0
expect_error "^vwrays: bad option '-fq'" vwrays -fq -x 2 -y 2
expect_error "^vwrays: bad option '-q'" vwrays -q
expect_error "^vwrays: missing.vf" vwrays -vf missing.vf
expect_error "^vwrays: a.txt" vwrays a.txt
expect_error "^vwrays: missing.zbf: cannot open$" vwrays pic.hdr missing.zbf
expect_error "^vwrays: a.txt: expected length is 12, actual length is 3$" vwrays pic.hdr a.txt
IN=a.txt expect_error "^vwrays: expected px py on input$" vwrays -i -x 2 -y 2
IN=pos.txt expect_error "^vwrays: input pixel outside image$" vwrays -i pic.hdr pic.zbf
expect_error "^vwrays: .*view" vwrays -vd 0 0 0 -x 2 -y 2
expect_error "^getbbox: missing.rad" getbbox missing.rad
expect_error "^getbbox: ball.oct: not a scene description" getbbox ball.oct
expect_error "^getbbox: a.txt:1: " getbbox a.txt
[ "$fail" -eq 0 ] && echo ok
exit "$fail"
