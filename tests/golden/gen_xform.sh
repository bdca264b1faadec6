#!/bin/bash
# Golden test for xform: RADIANCE's output layout (header line, copied comments, "%18.12g"
# columns), -n/-m on surfaces only, mirrored polygons reversed, radii and glow distance
# scaled, pattern transforms appended, an expanded command, arrays with -c (commands
# re-wrapped in "| xform -e ..."), and the cornell mirror box (genbox | xform). Errors exit
# non-zero.
set -u
XFORM="${RP_BIN:?RP_BIN not set}/xform"
EXPECTED="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/golden/gen_xform.expected"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0

cat > in.rad <<'RAD'
# small test scene
void plastic red 0 0 5 .8 .1 .1 0 0
void brightfunc stripes 4 stripe stripe.cal -s 0.5 0 0
stripes plastic striped 0 0 5 .5 .5 .5 0 0
red polygon floor 0 0 12 0 0 0 2 0 0 2 1 0 0 1 0
striped sphere ball 0 0 4 1 0.5 0.25 0.25
red ring disc 0 0 8 0 0 1 0 0 1 0 0.5
void glow lamp 0 0 4 10 10 10 2
!echo void alias red2 red
RAD
# genbox mirror_mat mbox 1.5 1.5 3.0 (corner bits: 1 = x, 2 = y, 4 = z)
box() {
    echo "# genbox mirror_mat mbox 1.5 1.5 3.0"
    for f in 1540 4620 2310 3267 5137 6457; do
        printf '\nmirror_mat polygon mbox.%s\n0\n0\n12\n' "$f"
        for c in $(echo "$f" | fold -w1); do
            x=0 y=0 z=0
            (( c & 1 )) && x=1.5
            (( c & 2 )) && y=1.5
            (( c & 4 )) && z=3
            printf '\t\t%s\t\t%s\t\t%s\n' "$x" "$y" "$z"
        done
    done
}

{
    "$XFORM" -n g -m red -s 2 -my -rz 90 -t 1 2 3 in.rad
    "$XFORM" -c -a 2 -t 0 0 1 in.rad
    box | "$XFORM" -t -0.75 -0.75 0 -rz 20 -t 1.5 3.6 0
} > out 2> err
st=$?
if ! diff -u "$EXPECTED" out; then echo "FAIL: output differs"; fail=1; fi
[ "$st" -eq 0 ] || { echo "FAIL: exit status $st"; fail=1; }
[ -s err ] && { echo "FAIL: unexpected stderr"; cat err; fail=1; }

# The mirror box must match the cornell reference scene (genbox | xform from RADIANCE).
ref="${RP_SHARED_DIR:-}/validation/cornell/scene.rad"
if [ -f "$ref" ]; then
    box | "$XFORM" -t -0.75 -0.75 0 -rz 20 -t 1.5 3.6 0 | grep -v '^#' | grep -v '^$' > box_out
    grep -A 7 '^mirror_mat polygon mbox' "$ref" | grep -v '^--$' > box_ref
    if ! diff -u box_ref box_out; then echo "FAIL: cornell mirror box"; fail=1; fi
fi

# Bad input: non-zero exit, one message.
if "$XFORM" -t 1 2 in.rad > /dev/null 2> err_bad; then echo "FAIL: bad -t accepted"; fail=1; fi
[ "$(wc -l < err_bad)" -eq 1 ] || { echo "FAIL: expected one error line"; cat err_bad; fail=1; }
echo 'm blob b 0 0 0' | "$XFORM" > /dev/null 2>&1 && { echo "FAIL: unknown type accepted"; fail=1; }

exit $fail
