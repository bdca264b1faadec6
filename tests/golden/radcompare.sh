#!/usr/bin/env bash
# radcompare gives RADIANCE 5.4's verdicts (exit 0 same, 1 different, 2 error) and its
# report lines on every case in tests/data/radcompare/cases.txt: pictures (tolerances,
# sizes, formats, headers), text and ascii matrices (numbers as reals, -c comments),
# float/double data (BigEndian= swapping), binary and octree bytes. expected.out is
# RADIANCE's own output (tests/data/radcompare/README.md says how it was made). Our errors
# go to standard error as "radcompare: file: why", RADIANCE's as "file: why" (and
# "Usage: ..."), so those lines are mapped before comparing.
set -euo pipefail
data=$(cd "$(dirname "$0")/../data/radcompare" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/bin"; ln -s "$RP_BIN/radcompare" "$tmp/bin/radcompare"
cd "$data"
while read -r line; do
    echo "== $line"
    rc=0; PATH="$tmp/bin:$PATH" radcompare $line > "$tmp/out" 2> "$tmp/err" || rc=$?
    if [ -s "$tmp/err" ] && [ "$(wc -l < "$tmp/err")" -ne 1 ]; then
        echo "FAIL: radcompare $line wrote more than one error line" >&2; cat "$tmp/err" >&2; exit 1
    fi
    cat "$tmp/out"
    sed -e 's/^radcompare: usage: /Usage: /' \
        -e 's/^radcompare: \(.*: \(unknown error reading header\|cannot open for reading\|unexpected end-of-file\)\)$/\1/' \
        "$tmp/err"
    echo "rc=$rc"
done < cases.txt > "$tmp/got"
diff -u expected.out "$tmp/got" || { echo "FAIL: radcompare differs from RADIANCE's"; exit 1; }

# The renders Makefile's rule: a picture compared with itself under another name passes.
cp base.hdr "$tmp/copy.hdr"
"$RP_BIN/radcompare" -rel 0.007 -rms 0.1 -max 1.5 base.hdr "$tmp/copy.hdr"
"$RP_BIN/radcompare" -version | grep -q '^RADIANCE 5\.4a '
echo ok
