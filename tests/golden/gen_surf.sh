#!/bin/bash
# Golden test for gensurf: RADIANCE's text (header line, name.<k> numbering, vertex order
# by the (s,t) right-hand rule with alternating diagonals, "%18.12g %18.12g %18.12g" lines)
# for a 2x2 plane, x y z triplets from standard input (a non-planar cell: two triangles),
# a smoothed plane (-s: Phong texfunc with zero perturbation) and z data with -o -s
# (.OBJ with the plane z = s + 2t's normal), compared with gen_surf.expected (RADIANCE
# gensurf 2.29's output for the same commands); then the error exits.
set -u
GENSURF="${RP_BIN:?RP_BIN not set}/gensurf"
EXPECTED="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/golden/gen_surf.expected"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

{ "$GENSURF" m p 'sx*s' t 0 2 2 -e 'sx = 2' && echo "=====" &&
  printf '0 0 0  1 0 0\n0 1 0  1 1 1\n' | "$GENSURF" m q - - - 1 1 && echo "=====" &&
  "$GENSURF" m p s t 0 1 1 -s && echo "=====" &&
  printf '0 1\n2 3\n' | "$GENSURF" m r s t - 1 1 -o -s; } \
    > "$tmp/out" 2> "$tmp/err" || { echo "FAIL: gensurf exited non-zero"; fail=1; }
if ! diff -u "$EXPECTED" "$tmp/out"; then
    echo "FAIL: gensurf output differs from gen_surf.expected"
    fail=1
fi
[ -s "$tmp/err" ] && { echo "FAIL: unexpected stderr"; cat "$tmp/err"; fail=1; }

check_error() {  # expected-message args...
    local want=$1; shift
    "$GENSURF" "$@" < /dev/null > "$tmp/eout" 2> "$tmp/eerr"
    local st=$?
    [ "$st" -eq 1 ] || { echo "FAIL: gensurf $* exited $st, expected 1"; fail=1; }
    [ -s "$tmp/eout" ] && { echo "FAIL: gensurf $* wrote to stdout"; fail=1; }
    if [ "$(cat "$tmp/eerr")" != "$want" ]; then
        echo "FAIL: gensurf $*: stderr '$(cat "$tmp/eerr")', expected '$want'"
        fail=1
    fi
}
check_error "gensurf: bad m 'two': expected an integer" m p s t 0 two 2
check_error "gensurf: y(s,t): syntax error: unexpected ';'" m p s 't+' 0 2 2
check_error "gensurf: <stdin>: bad number of data points: expected 9 or 4 values, got 0" \
    m p s t - 2 2
check_error "gensurf: unknown option '-x'" m p s t 0 2 2 -x

[ "$fail" -eq 0 ] && echo "gen_surf: all checks passed"
exit "$fail"
