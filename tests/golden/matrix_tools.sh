#!/usr/bin/env bash
# rmtxop, rcollate and dctimestep against RADIANCE 5.4's: every line of
# tests/data/matrix/cases.txt (name|mode|stdin|command) is run with our tools and its
# output compared with expected/<name>.out, made by RADIANCE's tools with
# make_expected.sh (README.md there). Mode "exact": the same bytes; "num": the same text
# with numbers within 1e-6 relative. CAPDATE= and GMT= lines (the time of the run) are
# left out of both. Among the cases are RADIANCE's own test/util ones (test.mtx from
# rfmirror.mtx, rmtxop.mtx, dctimestep.mtx). Then -o file sets and one-line errors.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/matrix
fail=0
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
for t in rmtxop rcollate dctimestep; do
    [ -x "$RP_BIN/$t" ] || { echo "FAIL: $RP_BIN/$t missing"; exit 1; }
done
# The commands run in a scratch copy of the data (outputs name their inputs), with our
# tools first on PATH so that headers show "rmtxop ..." as RADIANCE's do.
work=$tmp/work; mkdir "$work"
cp "$data"/*.mtx "$data"/*.fmx "$data"/*.dmx "$data"/*.hdr "$data"/*.txt "$data"/*.flt "$work"/
gzip -dc "$data/rfmirror.mtx.gz" > "$work/rfmirror.mtx"
gzip -dc "$data/expected/rcollate_radiance_test.out.gz" > "$work/test.mtx"  # RADIANCE 5.4's
export PATH="$RP_BIN:$PATH"

untimed() { grep -av -e '^CAPDATE=' -e '^GMT=' "$1" || true; }
# Text whose words are the same, numbers within 1e-6 relative (absolute below 1e-30).
same_numbers() {
    paste -d '\n' <(untimed "$1" | tr -s ' \t' '\n\n') <(untimed "$2" | tr -s ' \t' '\n\n') |
        awk 'NR % 2 { w = $0; next }
             { if (w == $0) next
               if (w !~ /^[-+0-9.eE]+$/ || $0 !~ /^[-+0-9.eE]+$/) { bad = 1; exit }
               d = w - $0; if (d < 0) d = -d; m = w < 0 ? -w : w
               if (d > 1e-6 * m && d > 1e-30) { bad = 1; exit } }
             END { exit bad }'
}

n=0
while IFS='|' read -r name mode stdin cmd; do
    n=$((n + 1))
    want=$data/expected/$name.out
    if [ -f "$want.gz" ]; then gzip -dc "$want.gz" > "$tmp/want"; want=$tmp/want; fi
    if ! (cd "$work" && eval "$cmd" < "${stdin:-/dev/null}" > "$tmp/got" 2> "$tmp/err"); then
        echo "FAIL $name ($cmd): $(head -3 "$tmp/err")"; fail=1; continue
    fi
    case $mode in
        exact) cmp -s <(untimed "$want") <(untimed "$tmp/got") ||
                   { echo "FAIL $name ($cmd): output differs from expected/$name.out"
                     diff <(untimed "$want" | head -c 3000 | od -c | head -12) \
                          <(untimed "$tmp/got" | head -c 3000 | od -c | head -12) | head -8 || true
                     fail=1; } ;;
        num) same_numbers "$want" "$tmp/got" ||
                 { echo "FAIL $name ($cmd): numbers differ from expected/$name.out"
                   diff <(untimed "$want") <(untimed "$tmp/got") | head -6 || true; fail=1; } ;;
    esac
done < "$data/cases.txt"
[ "$n" -ge 60 ] || { echo "FAIL: only $n cases read"; fail=1; }

# -o with %d: one file per time step (as RADIANCE: vectors FRAME= 0.., pictures too).
(cd "$work" && dctimestep -o "$tmp/step%d.dat" a.mtx s4x3.mtx && dctimestep -oc -o "$tmp/frame%d.hdr" dc%03d.hdr sky3.mtx) ||
    { echo "FAIL dctimestep -o"; fail=1; }
for i in 0 1 2; do
    [ "$(untimed "$tmp/step$i.dat" | grep -c '^FRAME=')" = 1 ] && [ "$(sed '1,/^$/d' "$tmp/step$i.dat" | wc -l)" = 3 ] ||
        { echo "FAIL dctimestep -o step$i.dat"; fail=1; }
done
# Each picture frame is a whole picture of the components' size.
for i in 0 1; do
    [ "$("$RP_BIN/getinfo" -d < "$tmp/frame$i.hdr")" = "-Y 3 +X 5" ] &&
        untimed "$tmp/frame$i.hdr" | grep -aq "^FRAME=$i\$" ||
        { echo "FAIL dctimestep -o frame$i.hdr"; fail=1; }
done

# Bad input: one line naming the file (and line or record), non-zero exit.
printf '#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 2\n3\n' > "$tmp/short.mtx"
printf '#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=float\n\n12345678' > "$tmp/short.fmx"
printf '#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\n' > "$tmp/nohead.mtx"
printf '#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=1\nFORMAT=text\n\n1\n' > "$tmp/format.mtx"
printf '#?RADIANCE\nNROWS=4\nNCOLS=1\nNCOMP=3\n\n1 2 3\n' > "$tmp/nofmt.mtx"
cd "$data"
expect_error "short.mtx:8: unexpected end of data: 3 of 4 values" rmtxop "$tmp/short.mtx"
expect_error "short.fmx: unexpected end of data at record 3 of 4" rmtxop "$tmp/short.fmx"
expect_error "nohead.mtx: bad header" rmtxop "$tmp/nohead.mtx"
expect_error "format.mtx: unknown data format 'text'" rmtxop "$tmp/format.mtx"
expect_error "nosuch.mtx: cannot open file" rmtxop nosuch.mtx
expect_error "b.mtx: mismatched dimensions for product (4x2x3 times 4x2x3)" rmtxop b.mtx b.mtx
expect_error "g.mtx: # components do not match (3 and 1)" rmtxop a.mtx -t g.mtx
expect_error "b.mtx: matrix sum failed: sizes differ" rmtxop a.mtx + b.mtx
expect_error "a.mtx: -s must have one or 3 factors" rmtxop -s 1 2 a.mtx
expect_error "missing matrix argument after '+' operation" rmtxop a.mtx +
expect_error "nosuch.xml: cannot open BSDF file" rmtxop -rf nosuch.xml
expect_error "bad option '-rx'" rmtxop -rx a.mtx
expect_error "unknown operation '-q'" rmtxop -q a.mtx
expect_error "short.mtx:8: incomplete record 4 or unexpected end of data" rcollate -fa1 -or 1 -oc 4 "$tmp/short.mtx"
expect_error "nohead.mtx: bad header" rcollate -t "$tmp/nohead.mtx"
expect_error "a.mtx: bad dimension(s): cannot transpose 3x4 to 3x4" rcollate -t -or 3 -oc 4 a.mtx
expect_error "input format 'ascii' != 'float'" rcollate -ff3 -t a.mtx
expect_error "bad option '-x'" rcollate -x a.mtx
expect_error "d.mtx: unexpected column count in header (5, expected 4)" dctimestep a.mtx b.mtx d.mtx s4.mtx
expect_error "a.mtx: unexpected column count in header (4, expected 5)" dctimestep a.mtx s5.mtx
expect_error "short.mtx: unexpected # components" dctimestep a.mtx "$tmp/short.mtx"
expect_error "s4_plain.txt: unexpected EOF in header" dctimestep a.mtx s4_plain.txt
expect_error "nofmt.mtx: missing/unknown data format in header" dctimestep a.mtx "$tmp/nofmt.mtx"
expect_error "s4_plain.txt:4: unexpected EOF: 4 of a whole number of rows of 3 RGB values" dctimestep -n 3 a.mtx s4_plain.txt
expect_error "nosuch.xml: cannot open BSDF file" dctimestep a.mtx nosuch.xml d.mtx s5.mtx
expect_error "dc003.hdr: cannot open file" dctimestep -oc dc%03d.hdr s4.mtx
expect_error "expected 1 to 4 matrix arguments" dctimestep
exit $fail
