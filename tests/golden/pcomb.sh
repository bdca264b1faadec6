#!/usr/bin/env bash
# pcomb against RADIANCE 5.4's pcomb: for each case in tests/data/pcomb/cases.txt (the
# README's table) the output has the same size, the same header lines (CAPDATE, GMT and
# the command line aside; FORMAT aside without inputs, where RADIANCE writes none) and
# pixels within one RGBE step of RADIANCE's stored output; then -version and one-line
# errors.
set -euo pipefail
set -f  # the cases' expressions hold '*'
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/pcomb
cd "$data"
fail=0
info() { "$RP_BIN/getinfo" < "$1" | grep -v 'pcomb \|CAPDATE=\|GMT=\|FORMAT=' || true; }
while IFS='|' read -r name opts; do
    # shellcheck disable=SC2086
    "$RP_BIN/pcomb" $opts < cornell32.hdr > "$tmp/$name.hdr" 2> "$tmp/err" ||
        { echo "FAIL $name: $(cat "$tmp/err")"; fail=1; continue; }
    cmp -s <(info "$name.hdr") <(info "$tmp/$name.hdr") ||
        { echo "FAIL $name header:"; diff <(info "$name.hdr") <(info "$tmp/$name.hdr") || true; fail=1; }
    "$RP_BIN/getinfo" < "$tmp/$name.hdr" | grep -qF "pcomb $opts" ||
        { echo "FAIL $name: no command line in the header"; fail=1; }
    [ "$("$RP_BIN/getinfo" -d < "$name.hdr")" = "$("$RP_BIN/getinfo" -d < "$tmp/$name.hdr")" ] ||
        { echo "FAIL $name size: $("$RP_BIN/getinfo" -d < "$tmp/$name.hdr")"; fail=1; }
    "$RP_BIN/pvalue" -h -H -d -o "$name.hdr" > "$tmp/want"
    "$RP_BIN/pvalue" -h -H -d -o "$tmp/$name.hdr" > "$tmp/got"
    worst=$(paste "$tmp/want" "$tmp/got" | awk '
        NF != 6 { bad = 1 }
        { m = 0; for (k = 1; k <= 6; k++) if ($k > m) m = $k
          for (k = 1; k <= 3; k++) { d = $k - $(k + 3); if (d < 0) d = -d
                                     if (m > 0 && d / m > w) w = d / m } }
        END { if (bad || NR == 0) print "mismatch"; else if (w > 0.0079) print w }')
    [ -z "$worst" ] || { echo "FAIL $name pixels: worst relative difference $worst"; fail=1; }
done < cases.txt

"$RP_BIN/pcomb" -version | grep -q '^RADIANCE 5\.4a ' || { echo "FAIL -version"; fail=1; }
expect_error() {  # pattern, then the arguments
    local pattern=$1; shift
    if "$RP_BIN/pcomb" "$@" > "$tmp/out" 2> "$tmp/err" < /dev/null; then
        echo "FAIL pcomb $* should fail"; fail=1; return
    fi
    [ "$(wc -l < "$tmp/err")" -eq 1 ] && grep -q "^pcomb: .*$pattern" "$tmp/err" ||
        { echo "FAIL pcomb $*: $(cat "$tmp/err")"; fail=1; }
}
expect_error "unknown option '-q'" cornell32.hdr -q
expect_error "nosuch.hdr" nosuch.hdr
expect_error "README.md" README.md
expect_error "illegal output resolution" -e 'ro=1'
expect_error "bad value 'x' for -s" -s x cornell32.hdr
expect_error "nosuch.cal" -f nosuch.cal cornell32.hdr
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n\0\0\0\0\0\0\0\0' > "$tmp/small.hdr"
expect_error "resolution mismatch" cornell32.hdr "$tmp/small.hdr"
exit $fail
