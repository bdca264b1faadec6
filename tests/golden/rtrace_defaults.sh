#!/bin/bash
# Golden test for `rtrace -defaults` (no scene needed): RADIANCE 5.4's lines, order and
# formats (rtmain.c printdefaults + renderopts.c print_rdefaults), options modifying them,
# @file and $EVAR expansion, and the one-line error for an unknown option.
set -u
RT="${RP_BIN:?RP_BIN not set}/rtrace"
EXP="${RP_SOURCE_DIR:?}/tests/golden/rtrace_defaults.expected"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

"$RT" -defaults > "$tmp/out" || bad "-defaults exit status"
diff -u "$EXP" "$tmp/out" || bad "-defaults text"

# Options before -defaults change what it prints; @file and $EVAR expand in place.
echo "-ab 2 -dc 0.5" > "$tmp/opts"
RP_RTRACE_TEST_OPTS="-h- -ovw" "$RT" @"$tmp/opts" '$RP_RTRACE_TEST_OPTS' -n 3 -defaults > "$tmp/mod" ||
    bad "modified -defaults exit status"
grep -q $'^-ab 2        \t\t\t# ambient bounces$' "$tmp/mod" || bad "-ab from @file"
grep -q $'^-dc 0.500000\t\t\t# direct certainty$' "$tmp/mod" || bad "-dc from @file"
grep -q $'^-h-\t\t\t\t# no header$' "$tmp/mod" || bad "-h- from \$EVAR"
grep -q $'^-ovw       \t\t\t# output value weight$' "$tmp/mod" || bad "-ovw from \$EVAR"
grep -q $'^-n 3 \t\t\t\t# number of rendering processes$' "$tmp/mod" || bad "-n 3"

# Unknown option: one line on stderr, exit 1, nothing on stdout.
"$RT" -zz scene.oct > "$tmp/o" 2> "$tmp/e"
[ $? -eq 1 ] || bad "unknown option exit status"
[ "$(cat "$tmp/e")" = "rtrace: unknown option '-zz'" ] || bad "unknown option message: $(cat "$tmp/e")"
[ -s "$tmp/o" ] && bad "unknown option wrote output"
"$RT" -ab 1 > /dev/null 2> "$tmp/e"
[ "$(cat "$tmp/e")" = "rtrace: missing octree argument" ] || bad "missing octree: $(cat "$tmp/e")"
"$RT" @"$tmp/none" scene.oct 2> "$tmp/e"
[ "$(cat "$tmp/e")" = "rtrace: cannot expand '@$tmp/none'" ] || bad "bad @file: $(cat "$tmp/e")"
exit $fail
