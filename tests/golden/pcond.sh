#!/usr/bin/env bash
# pcond against RADIANCE 5.4's pcond: for each case in tests/data/pcond/README.md the
# output has the same size and orientation, the same header lines (the input's, the
# command line as RADIANCE writes it, PRIMARIES= and EXPOSURE=) and pixels within one
# RGBE step of RADIANCE's stored output (1 % for the histogram mappings of -h); the -x
# mapping matches RADIANCE's; then an output file, -version and one-line errors.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/pcond
cd "$data"
fail=0
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
# Run as "pcond" (found on PATH), so the header's command line reads as RADIANCE's did.
pcond() { PATH="$RP_BIN:$PATH" command pcond "$@"; }

# Largest difference between two pictures' pixels, relative to the larger of the two
# pixels' largest component; "mismatch" when their sizes differ.
worst_difference() {
    "$RP_BIN/pvalue" -h -H -d -o "$1" > "$tmp/want"
    "$RP_BIN/pvalue" -h -H -d -o "$2" > "$tmp/got"
    paste "$tmp/want" "$tmp/got" | awk '
        NF != 6 { bad = 1 }
        { m = 0; for (k = 1; k <= 6; k++) if ($k > m) m = $k
          for (k = 1; k <= 3; k++) { d = $k - $(k + 3); if (d < 0) d = -d
                                     if (m > 0 && d / m > w) w = d / m } }
        END { if (bad || NR == 0) print "mismatch"; else printf "%.6f\n", w }'
}

# name|options|input|standard input, as in the README's table.
cases='default||split.hdr|
human|-h|split.hdr|
acuity|-a|dark.hdr|
veil|-v|split.hdr|
sens|-s|split.hdr|
color|-c|dark.hdr|
weight|-w|split.hdr|
linear|-l|split.hdr|
ldmax|-s -u 200|split.hdr|
lddyn|-d 50|split.hdr|
expose|-e +2|split.hdr|
prims|-p .64 .33 .29 .6 .15 .06 .3127 .329|split.hdr|
fixations|-i 0.2|split.hdr|fix.txt
prehist|-I|split.hdr|hist.txt
human_dark|-h|dark.hdr|
human_xyze|-h|xyze.hdr|
macbeth|-f film.cal|split.hdr|'
while IFS='|' read -r name opts input stdin; do
    # shellcheck disable=SC2086
    pcond $opts "$input" > "$tmp/$name.hdr" 2> "$tmp/err" < "${stdin:-/dev/null}" ||
        { echo "FAIL $name: $(cat "$tmp/err")"; fail=1; continue; }
    # The whole header, the command line included.
    cmp -s <("$RP_BIN/getinfo" < "$name.hdr") <("$RP_BIN/getinfo" < "$tmp/$name.hdr") ||
        { echo "FAIL $name header:"
          diff <("$RP_BIN/getinfo" < "$name.hdr") <("$RP_BIN/getinfo" < "$tmp/$name.hdr") || true
          fail=1; }
    [ "$("$RP_BIN/getinfo" -d < "$name.hdr")" = "$("$RP_BIN/getinfo" -d < "$tmp/$name.hdr")" ] ||
        { echo "FAIL $name size: $("$RP_BIN/getinfo" -d < "$tmp/$name.hdr")"; fail=1; }
    case $opts in *-h*) tol=0.01 ;; *) tol=0.0079 ;; esac  # 1 step: 1/128 of the largest
    worst=$(worst_difference "$name.hdr" "$tmp/$name.hdr")
    awk -v w="$worst" -v t="$tol" 'BEGIN { exit !(w != "mismatch" && w <= t) }' ||
        { echo "FAIL $name pixels: worst relative difference $worst"; fail=1; }
done <<< "$cases"

# The mapping from world to display luminance (-x), within 1e-5 relative.
pcond -h -x "$tmp/human.map" split.hdr > /dev/null
paste human.map "$tmp/human.map" | awk '
    NF != 4 { bad = 1 }
    { for (k = 1; k <= 2; k++) { d = $k - $(k + 2); if (d < 0) d = -d; if (d > 1e-5 * $k) bad = 1 } }
    END { exit bad || NR != 100 }' || { echo "FAIL -x mapping differs from human.map"; fail=1; }

# An output file holds the same picture as the standard output.
pcond -h split.hdr "$tmp/file.hdr"
cmp -s <(sed '1,/^$/d' "$tmp/file.hdr") <(sed '1,/^$/d' "$tmp/human.hdr") ||
    { echo "FAIL the output file differs from the standard output"; fail=1; }
"$RP_BIN/pcond" -version | grep -q '^RADIANCE 5\.4a ' || { echo "FAIL -version"; fail=1; }

expect_error "unknown option '-q'" pcond -q split.hdr
expect_error "unknown option '-hx'" pcond -hx split.hdr
expect_error "nosuch.hdr: No such file" pcond nosuch.hdr
expect_error "README.md: not a RADIANCE" pcond README.md
expect_error "expected an input picture" pcond -h
expect_error "only one of -i or -I" pcond -i .2 -I split.hdr
expect_error "only one of -p, -m or -f" pcond -p 1 2 3 4 5 6 7 8 -f film.cal split.hdr
expect_error "not supported" pcond -m warp.cwp split.hdr
expect_error "macbethcal only works with RGB" pcond -f film.cal xyze.hdr
expect_error "'-u': must be > 0" pcond -u 0 split.hdr
IN=fix.txt expect_error "uneven step size in histogram data" pcond -I split.hdr
IN=hist.txt expect_error "format error reading fixation data" pcond -i .5 split.hdr
# RADIANCE's exit status for a file it cannot open is 2.
set +e
"$RP_BIN/pcond" nosuch.hdr > /dev/null 2>&1
status=$?
set -e
[ "$status" -eq 2 ] || { echo "FAIL missing input: exit status $status, expected 2"; fail=1; }
exit $fail
