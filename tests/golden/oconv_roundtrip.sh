#!/bin/bash
# Golden test for oconv: a validation scene compiles with RADIANCE's octree header (magic
# line, command line, FORMAT=Radiance_octree, blank line), -i adds to an octree, and bad
# input gives exit status 1 with one "oconv: file:line: message" line.
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared validation
OCONV="${RP_BIN:?RP_BIN not set}/oconv"
SHARED="${RP_SHARED_DIR:?RP_SHARED_DIR not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
die() { echo "FAIL: $*"; fail=1; }

cp "$SHARED/validation/cornell/scene.rad" cornell.rad
"$OCONV" -w -r 1024 -n 6 cornell.rad > cornell.oct 2> err || die "oconv exit status $?"
[ -s err ] && die "unexpected stderr: $(cat err)"
head -n 1 cornell.oct | grep -qx '#?RADIANCE' || die "no #?RADIANCE magic line"
head -n 2 cornell.oct | tail -n 1 | grep -q 'oconv -w -r 1024 -n 6 cornell.rad$' || die "no command line"
head -n 3 cornell.oct | tail -n 1 | grep -qx 'FORMAT=Radiance_octree' || die "no FORMAT line"
[ -z "$(head -n 4 cornell.oct | tail -n 1)" ] || die "header not ended by a blank line"
grep -q 'radphoton_scene' cornell.oct && die "octree claims to be a radphoton scene file"

# -i: add a scene that uses a modifier from the first file (inside the octree's cube).
printf 'white sphere extra 0 0 4 1 1 1 .5\n' > extra.rad
"$OCONV" -i cornell.oct extra.rad > both.oct || die "oconv -i exit status $?"
head -n 2 both.oct | tail -n 1 | grep -q 'oconv -w -r 1024 -n 6 cornell.rad$' || die "-i lost the first command line"
head -n 3 both.oct | tail -n 1 | grep -q 'oconv -i cornell.oct extra.rad$' || die "-i: no new command line"

# An old scene file (FORMAT=radphoton_scene) cannot be added to: one line, exit 1.
printf '#?RADIANCE\noconv x.rad\nFORMAT=radphoton_scene\n\nRPSCENE' > old.oct
"$OCONV" -i old.oct extra.rad > /dev/null 2> err
[ $? -eq 1 ] && [ "$(wc -l < err)" -eq 1 ] && grep -q '^oconv: old.oct: a scene file of an older oconv' err ||
    die "old scene file: $(cat err)"

# Bad input: exit 1, one line naming file and line.
"$OCONV" "$SRC/tests/data/scene/bad_count.rad" > /dev/null 2> err
st=$?
[ "$st" -eq 1 ] || die "exit status $st for a bad argument count"
grep -qx "oconv: $SRC/tests/data/scene/bad_count.rad:2: plastic 'wall': expected 5 real arguments, got 4" err ||
    die "unexpected message: $(cat err)"
[ "$(wc -l < err)" -eq 1 ] || die "more than one error line"

"$OCONV" missing.rad > /dev/null 2> err
[ $? -eq 1 ] && grep -q '^oconv: missing.rad: cannot open file' err || die "missing file: $(cat err)"
"$OCONV" -z cornell.rad > /dev/null 2> err
[ $? -eq 1 ] && [ "$(wc -l < err)" -eq 1 ] && grep -q "unknown option: '-z'" err ||
    die "unknown option: $(cat err)"
exit $fail
