#!/usr/bin/env bash
# rad against RADIANCE 5.4's rad on RADIANCE's own test models: `rad -n` prints the same
# variables (-e), views (-V) and commands, in the same order, for every .rif in
# ../shared/radiance-tests/renders and for three RIFs of ours (tests/data/rad: standard
# views, no ZONE, abbreviations, REPORT/RAWFILE/ZFILE/OPTFILE, photon maps, illum files,
# tool variables that name programs), then RADIANCE's test-rad (inst.oct made by our
# oconv, `rad -n -s -e inst.rif` against ref/inst_rad.txt) and one-line errors.
# Outputs are RADIANCE's (tests/data/rad/README.md); mkillum's temporary file names
# ("ilXXXXXX") are random and compared as ilTEMP.
set -euo pipefail
. "$(dirname "$0")/lib/shared.sh"
require_shared radiance-tests
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/rad
cp -r "$RP_SHARED_DIR/radiance-tests/renders" "$tmp/renders"
cp "$data"/edge*.rif "$tmp/renders/"
cd "$tmp/renders"
export RAYPATH=.:$RP_SHARED_DIR/radiance-tests/lib
fail=0
n=0
while IFS= read -r line; do
    n=$((n + 1))
    want="$data/expected/$(printf %02d $n).out"
    eval "\"\$RP_BIN/rad\" $line" 2>&1 | sed 's/il[A-Za-z0-9]\{6\}/ilTEMP/g' > "$tmp/out" || true
    cmp -s "$want" "$tmp/out" ||
        { echo "FAIL line $n (rad $line):"; diff "$want" "$tmp/out" | head -10; fail=1; }
done < "$data/cases.txt"
[ "$n" -ge 30 ] || { echo "FAIL: only $n cases read"; fail=1; }
for f in edge1.opt inst.opt; do
    cmp -s "$data/expected/$f" "$f" || { echo "FAIL: OPTFILE $f differs"; diff "$data/expected/$f" "$f"; fail=1; }
done

# RADIANCE's test-rad: the octree made (by rad with our oconv), then rad -n -s -e.
"$RP_BIN/rad" -s -v 0 inst.rif
"$RP_BIN/rad" -n -s -e inst.rif > inst_rad.txt
"$RP_BIN/radcompare" ref/inst_rad.txt inst_rad.txt || { echo "FAIL: test-rad"; fail=1; }

expect_error 'usage: rad' rad -n
expect_error 'usage: rad' rad -x inst.rif
expect_error 'nonexist.rif: cannot open' rad -n nonexist.rif
expect_error 'unknown variable: FOO=1' rad -n inst.rif FOO=1
expect_error "illegal value for qualitative variable 'QUALITY'" rad -w -n inst.rif QUAL=foo
expect_error "bad value for variable 'ZONE'" rad -w -n inst.rif "ZONE=I 1 2"
expect_error "cannot find scene file 'nofile.rad'" rad -n inst.rif scene=nofile.rad
printf 'OCTREE = x.oct\nscene = diorama_walls.rad\nBOGUS = 1\n' > bad.rif
expect_error 'bad.rif:3: unknown variable: BOGUS = 1' rad -n bad.rif
printf 'scene = diorama_walls.rad\nPEN = maybe\n' > bad2.rif
expect_error "bad2.rif:2: illegal value for boolean variable 'PENUMBRAS'" rad -n bad2.rif
printf 'scene = a.rad\nscene = missing.rad\n' > bad3.rif
touch a.rad
expect_error "bad3.rif:2: cannot find scene file 'missing.rad'" rad -n bad3.rif
printf 'scene = diorama_walls.rad\nPGMAP = x.gpm\n' > bad4.rif
expect_error "bad4.rif:2: 'PGMAP' missing # photons argument" rad -n bad4.rif
exit $fail
