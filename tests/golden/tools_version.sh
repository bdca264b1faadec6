#!/usr/bin/env bash
# Every tool answers -version with one line that starts as RADIANCE 5.4's (scripts such
# as honeybee-radiance read the second word as the version, the third as a date), then
# names radphoton and the commit; and -defaults on every tool prints something and
# exits 0. mkpmap's -defaults lists its real defaults in RADIANCE's layout.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
tools=$(cd "$RP_BIN" && ls cnt falsecolor gen* getbbox getinfo mkillum mkpmap obj2mesh oconv pcomb pcond pfilt pmapdump pvalue rad radcompare rcalc \
        ra_png rcontrib rlam rpict rpreview rtrace rvu total vwrays xform 2> /dev/null)
[ "$(echo "$tools" | wc -w)" -ge 27 ] || { echo "FAIL: tools missing from $RP_BIN"; exit 1; }
for t in $tools; do
    rc=0; "$RP_BIN/$t" -version > "$tmp/out" 2> "$tmp/err" < /dev/null || rc=$?
    if [ "$rc" -ne 0 ] || [ "$(wc -l < "$tmp/out")" -ne 1 ] || [ -s "$tmp/err" ] ||
       ! grep -Eq '^RADIANCE 5\.4a ([0-9]{4}-[0-9]{2}-[0-9]{2}|unknown) radphoton [0-9.]+ \(.+\)$' "$tmp/out"; then
        echo "FAIL $t -version: rc=$rc, out: $(cat "$tmp/out"), err: $(cat "$tmp/err")"; fail=1
    fi
    rc=0; "$RP_BIN/$t" -defaults > "$tmp/out" 2> "$tmp/err" < /dev/null || rc=$?
    if [ "$rc" -ne 0 ] || [ ! -s "$tmp/out" ]; then
        echo "FAIL $t -defaults: rc=$rc, err: $(cat "$tmp/err")"; fail=1
    fi
done
"$RP_BIN/mkpmap" -defaults > "$tmp/mk"
for line in '^-apD 0\.250000' '^-apM 4' '^-apm 5000' '^-bv\+' '^-dp  1000\.0' '^-ds  0\.010000' \
            '^-fo-' '^-n   1' '^-apr 0'; do
    grep -Eq "$line" "$tmp/mk" || { echo "FAIL mkpmap -defaults lacks $line"; fail=1; }
done
# -version at any option position, not only first (util/options.h, info_options.h).
for cmd in "rtrace -ab 1 -version" "rpict -x 10 -version" "rcontrib -V+ -version" \
           "mkpmap -apD 0.5 -version" "rvu -b -version" "oconv -f -version" \
           "obj2mesh -w -version" "pmapdump -a -version" "genbox m n 1 1 1 -i -version"; do
    rc=0; $RP_BIN/$cmd > "$tmp/out" 2> "$tmp/err" < /dev/null || rc=$?
    if [ "$rc" -ne 0 ] || [ "$(wc -l < "$tmp/out")" -ne 1 ] || [ -s "$tmp/err" ] ||
       ! grep -q '^RADIANCE 5\.4a ' "$tmp/out"; then
        echo "FAIL $cmd: rc=$rc, out: $(cat "$tmp/out"), err: $(cat "$tmp/err")"; fail=1
    fi
done
# Values given before -defaults are the ones listed, as RADIANCE's rtrace -defaults does.
"$RP_BIN/mkpmap" -apD 0.5 -n 3 -defaults > "$tmp/mk"
grep -q '^-apD 0\.500000' "$tmp/mk" && grep -q '^-n   3' "$tmp/mk" ||
    { echo "FAIL mkpmap -defaults ignores earlier options"; fail=1; }
exit $fail
