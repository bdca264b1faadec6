#!/bin/bash
# Golden test for genrev: RADIANCE's text (header line, name.<i> numbering, cone/cup/ring/
# cylinder choice, tab + %18.12g columns, -s Phong texfuncs) for the man page's torus and a
# closed can (bottom ring facing -z, cylinder, top ring facing +z), compared with the
# gen_rev.expected (RADIANCE genrev 2.14's output for the same commands); then the
# error exits.
set -u
GENREV="${RP_BIN:?RP_BIN not set}/genrev"
EXPECTED="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/golden/gen_rev.expected"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

can_z='if(t-.5,1,0)'
can_r='if(t-.9,0,if(t-.1,1,0))'
{ "$GENREV" steel torus 'sin(2*PI*t)' '1+cos(2*PI*t)' 4 && echo "=====" &&
  "$GENREV" tin can "$can_z" "$can_r" 3 && echo "=====" &&
  "$GENREV" tin can "$can_z" "$can_r" 3 -s; } \
    > "$tmp/out" 2> "$tmp/err" || { echo "FAIL: genrev exited non-zero"; fail=1; }
if ! diff -u "$EXPECTED" "$tmp/out"; then
    echo "FAIL: genrev output differs from gen_rev.expected"
    fail=1
fi
[ -s "$tmp/err" ] && { echo "FAIL: unexpected stderr"; cat "$tmp/err"; fail=1; }

# Bad input: one "genrev: ..." line on stderr, nothing on stdout, exit status 1.
check_error() {  # expected-message args...
    local want=$1; shift
    "$GENREV" "$@" > "$tmp/eout" 2> "$tmp/eerr"
    local st=$?
    [ "$st" -eq 1 ] || { echo "FAIL: genrev $* exited $st, expected 1"; fail=1; }
    [ -s "$tmp/eout" ] && { echo "FAIL: genrev $* wrote to stdout"; fail=1; }
    if [ "$(cat "$tmp/eerr")" != "$want" ]; then
        echo "FAIL: genrev $*: stderr '$(cat "$tmp/eerr")', expected '$want'"
        fail=1
    fi
}
check_error "genrev: bad nseg 'ten': expected an integer" m c t 1 ten
check_error "genrev: z(t): syntax error: unexpected ';'" m c 't*(' 1 4
check_error "genrev: r(t): undefined variable 'q'" m c t q 4
check_error "genrev: unknown option '-o'" m c t 1 4 -o

[ "$fail" -eq 0 ] && echo "gen_rev: all checks passed"
exit "$fail"
