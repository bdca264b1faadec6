#!/bin/bash
# Golden test for obj2mesh: converts the OBJ files in tests/data/obj2mesh and compares
# the .rtm bytes with the stored files, which are byte-identical to RADIANCE 5.4
# obj2mesh's output for the same commands and which RADIANCE's rtrace renders with the
# answers stored beside them (see tests/data/obj2mesh/README.md); then the header,
# the -v statistics and the one-line errors.
set -u
OBJ2MESH="${RP_BIN:?RP_BIN not set}/obj2mesh"
DATA="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/obj2mesh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
cd "$DATA" || exit 1

for m in cube grid; do
    "$OBJ2MESH" -a cube.rad $m.obj "$tmp/$m.rtm" 2> "$tmp/err" || { echo "FAIL: obj2mesh $m exited non-zero"; fail=1; }
    cmp -s $m.rtm "$tmp/$m.rtm" || { echo "FAIL: $m.rtm differs from the stored file"; fail=1; }
done
# Standard input and output give the same bytes (the header names no input file).
"$OBJ2MESH" -a cube.rad < cube.obj > "$tmp/stdin.rtm" 2>/dev/null
head -c 200 "$tmp/stdin.rtm" | grep -qa "^obj2mesh -a cube.rad$" || { echo "FAIL: stdin header"; fail=1; }
"$OBJ2MESH" dense.obj > "$tmp/dense.rtm" || { echo "FAIL: obj2mesh dense"; fail=1; }
"$OBJ2MESH" -v dense.obj 2> "$tmp/stats" > /dev/null
[ "$(sha256sum < "$tmp/dense.rtm" | cut -c1-64)" = "$(cat dense.rtm.sha256)" ] ||
    { echo "FAIL: dense.rtm checksum differs"; fail=1; }
# RADIANCE's obj2mesh -v for the same file prints exactly these lines.
expected_stats=$'Mesh statistics:\n\t0 materials\n\t10 patches (0.05 MBytes)\n\t2532 vertices (0.0% w/ normals, 0.0% w/ uv)\n\t5046 triangles (79.7% local, 19.7% joiner)\n\t12552 leaves in octree (45.6% empty, 4.92 avg. set size)'
[ "$(cat "$tmp/stats")" = "$expected_stats" ] || { echo "FAIL: -v statistics"; cat "$tmp/stats"; fail=1; }

# Header: magic, command (options and input, not the output), format, blank line;
# then the 2-byte mesh magic 323 (MESHMAGIC 319 + 4-byte object references).
head -c 60 "$tmp/cube.rtm" > "$tmp/head"
printf '#?RADIANCE\nobj2mesh -a cube.rad cube.obj\nFORMAT=Radiance_tmesh\n\n\001\103' > "$tmp/want"
cmp -s "$tmp/want" <(head -c "$(stat -c %s "$tmp/want")" "$tmp/cube.rtm") ||
    { echo "FAIL: cube.rtm header"; fail=1; }

check_error() {  # expected-message args...
    local want=$1; shift
    "$OBJ2MESH" "$@" > "$tmp/eout" 2> "$tmp/eerr"
    local st=$?
    [ "$st" -eq 1 ] || { echo "FAIL: obj2mesh $* exited $st, expected 1"; fail=1; }
    if [ "$(cat "$tmp/eerr")" != "$want" ]; then
        echo "FAIL: obj2mesh $*: stderr '$(cat "$tmp/eerr")', expected '$want'"; fail=1
    fi
}
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' > "$tmp/bad.obj"
check_error "obj2mesh: $tmp/bad.obj:4: vertex index 4 out of range (3 defined)" "$tmp/bad.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl green\nf 1 2 3\n' > "$tmp/mat.obj"
check_error "obj2mesh: $tmp/mat.obj:5: undefined modifier \"green\"" -a cube.rad "$tmp/mat.obj"
check_error "obj2mesh: unknown option: '-q'" -q cube.obj
check_error "obj2mesh: cannot find library material: 'nosuch.rad'" -l nosuch.rad cube.obj

[ "$fail" -eq 0 ] && echo "obj2mesh_rtm: all checks passed"
exit "$fail"
