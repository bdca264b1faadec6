#!/bin/bash
# Light materials inside instances glow but are not light sources (RADIANCE 5.4, same
# scene, gives the same answers: 0 on the floor at -ab 0 and -ab 1, 10 looking at the
# bulb, mkpmap "no light sources"); a light material as an instance's or mesh's own
# modifier is a one-line error.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
printf 'void light bright 0 0 3 10 10 10\nbright sphere bulb 0 0 4 0 0 1 .1\n' > bulb.rad
"$BIN/oconv" bulb.rad > bulb.oct || exit 1
cat > scene.rad <<'END'
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0
void instance lamp 1 bulb.oct 0 0
END
"$BIN/oconv" scene.rad > s.oct || exit 1
got=$(printf '2 0 3 0 0 -1\n0 0 3 0 0 -1\n' | "$BIN/rtrace" -h -ab 0 -ov s.oct 2>/dev/null | tr '\n' ' ')
echo "rtrace -ab 0: $got"
[ "$got" = "$(printf '0.000000e+00\t0.000000e+00\t0.000000e+00\t 1.000000e+01\t1.000000e+01\t1.000000e+01\t ')" ] ||
    { echo "FAIL: floor must be dark and the bulb 10"; fail=1; }
got=$(printf '2 0 3 0 0 -1\n' | "$BIN/rtrace" -h -ab 1 -aa 0 -ad 256 -ov s.oct 2>/dev/null)
echo "rtrace -ab 1: $got"
echo "$got" | grep -q '^0.000000e+00	0.000000e+00	0.000000e+00' || { echo "FAIL: ambient rays see no light"; fail=1; }
err=$("$BIN/mkpmap" -apg x.pm 1k s.oct 2>&1); rc=$?
echo "mkpmap: $err"
[ $rc -ne 0 ] && echo "$err" | grep -q "no light sources" && [ ! -e x.pm ] || { echo "FAIL: mkpmap"; fail=1; }
# A mesh places a compiled mesh (oconv reads its cube, as RADIANCE's does).
cp "${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/obj2mesh/cube.rtm" bulb.rtm
for t in instance mesh; do
    f=bulb.oct; [ $t = mesh ] && f=bulb.rtm
    printf "void light bright 0 0 3 10 10 10\nbright $t m 1 $f 0 0\n" > l$t.rad
    "$BIN/oconv" l$t.rad > l$t.oct
    err=$("$BIN/rtrace" -h l$t.oct < /dev/null 2>&1); rc=$?
    echo "$err"
    [ $rc -ne 0 ] && [ "$(echo "$err" | wc -l)" -eq 1 ] &&
        echo "$err" | grep -q "l$t.rad:2: $t 'm': cannot be modified by light material 'bright'" || { echo "FAIL: light on $t"; fail=1; }
done
exit $fail
