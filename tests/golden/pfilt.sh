#!/usr/bin/env bash
# pfilt against RADIANCE 5.4's pfilt: for each case in tests/data/pfilt/README.md the
# output has the same size and orientation, the same header lines (the input's, the
# command line, PIXASPECT/EXPOSURE/COLORCORR) and pixels within one RGBE step (the
# Gaussian and threshold filters within 1 %) of RADIANCE's stored output; then stdin,
# -version and one-line errors.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/pfilt
cd "$data"
fail=0
# name|options|input, as in the README's table.
cases='box_half|-x /2 -y /2|cornell64.hdr
box_32x20|-x 32 -y 20|cornell64.hdr
box_up|-x 60 -y 50 -e -2|hot.hdr
one_pass|-1 -e 2 -x 20 -y 30|cornell64.hdr
gauss_aa|-r .6 -x /2 -y /2|cornell64.hdr
gauss_up|-r 1 -x 60 -y 60|hot.hdr
aspect|-p 1.5 -x 32 -y 32|cornell64.hdr
correct|-c -x 32 -y 20|cornell64.hdr
colour|-er 2 -eb .5 -x 20|cornell64.hdr
thresh|-m .25 -x /2 -y /2|cornell64.hdr
thresh_odd|-r 1.5 -m .2 -x 40 -y 40|cornell64.hdr
stars|-n 6 -x /2 -y /2|hot.hdr
stars_spread|-n 8 -s 1e-3 -h 120 -r .6 -x 20 -y 15|hot.hdr
hot_avg|-a -x 20 -y 15|hot.hdr
rotated|-x 30 -y 20|cornell45_rot.hdr
wrap_gauss|-r .6 -x 15 -y 7|pano.hdr
wrap_thresh|-m .2 -x 15 -y 7|pano.hdr'
while IFS='|' read -r name opts input; do
    # shellcheck disable=SC2086
    "$RP_BIN/pfilt" $opts "$input" > "$tmp/$name.hdr" 2> "$tmp/err" ||
        { echo "FAIL $name: $(cat "$tmp/err")"; fail=1; continue; }
    "$RP_BIN/getinfo" < "$name.hdr" | grep -v 'pfilt \|FORMAT=' > "$tmp/want.info" || true
    "$RP_BIN/getinfo" < "$tmp/$name.hdr" | grep -v 'pfilt \|FORMAT=' > "$tmp/got.info" || true
    cmp -s "$tmp/want.info" "$tmp/got.info" ||
        { echo "FAIL $name header:"; diff "$tmp/want.info" "$tmp/got.info"; fail=1; }
    "$RP_BIN/getinfo" < "$tmp/$name.hdr" | grep -q "pfilt $opts\$" ||
        { echo "FAIL $name: no command line in the header"; fail=1; }
    [ "$("$RP_BIN/getinfo" -d < "$name.hdr")" = "$("$RP_BIN/getinfo" -d < "$tmp/$name.hdr")" ] ||
        { echo "FAIL $name size: $("$RP_BIN/getinfo" -d < "$tmp/$name.hdr")"; fail=1; }
    "$RP_BIN/pvalue" -h -H -d -o "$name.hdr" > "$tmp/want"
    "$RP_BIN/pvalue" -h -H -d -o "$tmp/$name.hdr" > "$tmp/got"
    case $opts in *-r*|*-m*) tol=0.01 ;; *) tol=0.0079 ;; esac  # 1 step: 1/128 of the largest
    worst=$(paste "$tmp/want" "$tmp/got" | awk -v tol="$tol" '
        NF != 6 { bad = 1 }
        { m = 0; for (k = 1; k <= 6; k++) if ($k > m) m = $k
          for (k = 1; k <= 3; k++) { d = $k - $(k + 3); if (d < 0) d = -d
                                     if (m > 0 && d / m > w) w = d / m } }
        END { if (bad || NR == 0) print "mismatch"; else if (w > tol) print w }')
    [ -z "$worst" ] || { echo "FAIL $name pixels: worst relative difference $worst"; fail=1; }
done <<< "$cases"

# Standard input gives the same picture as the file.
"$RP_BIN/pfilt" -x /2 -y /2 < cornell64.hdr > "$tmp/stdin.hdr"
cmp -s <(sed '1,/^$/d' "$tmp/stdin.hdr") <(sed '1,/^$/d' "$tmp/box_half.hdr") ||
    { echo "FAIL standard input differs from the file"; fail=1; }
"$RP_BIN/pfilt" -version | grep -q '^RADIANCE 5\.4a ' || { echo "FAIL -version"; fail=1; }

expect_error() {  # pattern, then the arguments
    local pattern=$1; shift
    if "$RP_BIN/pfilt" "$@" > "$tmp/out" 2> "$tmp/err" < /dev/null; then
        echo "FAIL pfilt $* should fail"; fail=1; return
    fi
    [ "$(wc -l < "$tmp/err")" -eq 1 ] && grep -q "^pfilt: .*$pattern" "$tmp/err" ||
        { echo "FAIL pfilt $*: $(cat "$tmp/err")"; fail=1; }
}
expect_error "unknown option '-q'" -q cornell64.hdr
expect_error "nosuch.hdr" nosuch.hdr
expect_error "bad # file arguments" cornell64.hdr hot.hdr
expect_error "'-x'" -x 0 cornell64.hdr
expect_error "exposure" -e 0 cornell64.hdr
expect_error "README.md" README.md
black=$tmp/black.hdr
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n\0\0\0\0\0\0\0\0' > "$black"
expect_error "too dark" "$black"
exit $fail
