#!/bin/bash
# Golden test for genbox: RADIANCE's exact text (header line, polygon names from corner
# codes, vertex order, tab + %18.12g columns) for an outward and an inward (-i) box,
# compared with gen_genbox.expected (RADIANCE genbox 2.13's output for the same two
# commands, -i mirroring the corners); then the error exits.
set -u
GENBOX="${RP_BIN:?RP_BIN not set}/genbox"
EXPECTED="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/golden/gen_genbox.expected"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

{ "$GENBOX" wood crate 1 2 0.5 && echo "=====" && "$GENBOX" wood crate 1 2 0.5 -i; } \
    > "$tmp/out" 2> "$tmp/err" || { echo "FAIL: genbox exited non-zero"; fail=1; }
if ! diff -u "$EXPECTED" "$tmp/out"; then
    echo "FAIL: genbox output differs from gen_genbox.expected"
    fail=1
fi
[ -s "$tmp/err" ] && { echo "FAIL: unexpected stderr"; cat "$tmp/err"; fail=1; }

# Bad input: one "genbox: ..." line on stderr, nothing on stdout, exit status 1.
check_error() {  # expected-message args...
    local want=$1; shift
    "$GENBOX" "$@" > "$tmp/eout" 2> "$tmp/eerr"
    local st=$?
    [ "$st" -eq 1 ] || { echo "FAIL: genbox $* exited $st, expected 1"; fail=1; }
    [ -s "$tmp/eout" ] && { echo "FAIL: genbox $* wrote to stdout"; fail=1; }
    if [ "$(cat "$tmp/eerr")" != "$want" ]; then
        echo "FAIL: genbox $*: stderr '$(cat "$tmp/eerr")', expected '$want'"
        fail=1
    fi
}
check_error "genbox: y size must be positive, got -2" wood crate 1 -2 3
check_error "genbox: z size must be positive, got 0" wood crate 1 2 0
check_error "genbox: unknown option '-q'" wood crate 1 2 3 -q

[ "$fail" -eq 0 ] && echo "gen_genbox: all checks passed"
exit "$fail"
