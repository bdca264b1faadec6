#!/bin/bash
# Finite but huge coordinates (beyond the 1.8e18 Embree handles, where it aborted) are
# misses, never a crash: rays given to rtrace, a view point for rpict, and a light
# source placed 3e18 from the origin for mkpmap (issue 30's first finding).
set -u
BIN="${RP_BIN:?RP_BIN not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
cat > s.rad <<'END'
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0
grey sphere ball 0 0 4 0 0 1 .5
void light bright 0 0 3 10 10 10
bright sphere lamp 0 0 4 0 0 4 .2
END
"$BIN/oconv" s.rad > s.oct || exit 1
out=$(printf '2e18 2 2 0 0 1\n2 2 2 0 0 -1\n' | "$BIN/rtrace" -h -ab 0 -ov s.oct); rc=$?
echo "rtrace: rc $rc: $(echo "$out" | tr '\n' ' ')"
[ $rc -eq 0 ] && [ "$(echo "$out" | head -1)" = "$(printf '0.000000e+00\t0.000000e+00\t0.000000e+00\t')" ] &&
    [ "$(echo "$out" | wc -l)" -eq 2 ] || { echo "FAIL: rtrace far ray"; fail=1; }
"$BIN/rpict" -vp 2e18 2 2 -x 8 -y 8 s.oct > far.hdr; rc=$?
echo "rpict: rc $rc"
[ $rc -eq 0 ] || { echo "FAIL: rpict far view point"; fail=1; }
printf 'void light l 0 0 3 1 1 1\nl sphere s 0 0 4 3e18 0 0 1\n' > far.rad
"$BIN/mkpmap" -apg far.pm 1k s.rad far.rad 2> err; rc=$?
echo "mkpmap: rc $rc"
[ $rc -le 1 ] || { echo "FAIL: mkpmap with a far light source died (rc $rc)"; cat err; fail=1; }
exit $fail
