#!/usr/bin/env bash
# rcalc, total and cnt against RADIANCE 5.4's own outputs on the same inputs: every line
# of tests/data/data_tools/cases.txt is run in that folder and its standard output must
# be byte-identical to expected/NN.out (how those were made: README.md there). Then bad
# input: one line naming the problem, non-zero exit.
set -u
DATA="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/data_tools"
: "${RP_BIN:?RP_BIN not set}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
cd "$DATA" || exit 1
fail=0
run_cases 50

expect_error "^rcalc: missing.txt: cannot open$" rcalc -e '$1=$1' missing.txt
expect_error "^rcalc: in.txt: record 1: line 1: undefined variable 'nothing'$" rcalc -e '$1=nothing' in.txt
expect_error "^rcalc: line 1: syntax error" rcalc -e '$1=(2' in.txt
expect_error "^rcalc: nolib.cal: cannot find function file" rcalc -f nolib.cal in.txt
expect_error "^rcalc: f.txt: record 1: no column input$" rcalc -i in.fmt -e '$1=$1' f.txt
expect_error "^rcalc: format error$" rcalc -i 'a $x' f.txt
expect_error "^rcalc: bad option '-q'" rcalc -q in.txt
expect_error "^rcalc: file argument(s) incompatible with -n$" rcalc -n -e '$1=1' in.txt
expect_error "^rcalc: missing value for option '-e'$" rcalc -e
expect_error "^total: missing: cannot open$" total missing t.txt
expect_error "^total: average maximum?!$" total -m -u t.txt
expect_error "^total: bad option '-q'" total -q t.txt
# total goes on with the other files after one it cannot open, as RADIANCE's does.
"$RP_BIN/total" missing t.txt > "$tmp/out" 2> /dev/null
[ $? -eq 2 ] && cmp -s "$tmp/out" expected/27.out || { echo "FAIL: total after a missing file"; fail=1; }
[ "$fail" -eq 0 ] && echo ok
exit "$fail"
