#!/bin/bash
# Ports that see the outside (mkpmap -apE, issue 48) on tests/data/port_exterior: a room
# whose window sees a sunlit ground and an overhang. RADIANCE's ports emit the sun and sky
# alone, and a final gather looking out finds no photon on the ground or the overhang:
# without -apE the 17 points outside the sun patch read 23-37 % below RADIANCE's classic
# irradiance. With it, `rtrace -I -ab 1 -ap g.pm 200` on a 300k map: each point within
# 5 % of RADIANCE's classic (three seeds spread 1.2 % rms a point; the estimator's
# k/(k-1) bias is +0.5 %) and their mean within 2.5 %; without -apE the mean of the 17
# is more than 15 % low. The map is the same for -n 1 and -n 2, and -apE is refused with
# a contribution map. The same with the window open and an antimatter port, and as a
# spectral map set (below).
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
data="$SRC/tests/data/port_exterior"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }
export RAYPATH=".:$SRC/lib"

"$BIN/oconv" "$data/scene.rad" > room.oct || exit 1
"$BIN/mkpmap" -apg e.pm 300k -apE -apo window_glass -n 2 room.oct 2> e.err || bad "mkpmap -apE: $(cat e.err)"
"$BIN/mkpmap" -apg e1.pm 300k -apE -apo window_glass -n 1 room.oct 2> /dev/null || bad "mkpmap -n 1"
body() { awk 'BEGIN { RS = "\n\n" } NR == 1 { print length($0) }' "$1"; }  # header size
cmp -s <(tail -c +"$(($(body e.pm) + 3))" e.pm) <(tail -c +"$(($(body e1.pm) + 3))" e1.pm) ||
    bad "-apE maps differ between -n 1 and -n 2"
"$BIN/mkpmap" -apg p.pm 300k -apo window_glass -n 2 room.oct 2> /dev/null || bad "mkpmap"
for m in e p; do
    "$BIN/rtrace" -h -I -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 256 -ap $m.pm 200 -n 2 room.oct \
        < "$data/points.txt" > $m.txt || bad "rtrace $m"
done
# ours / RADIANCE per point; sun-patch points (> 100 W/m2) are left out of the means.
paste e.txt p.txt "$data/ref_radiance_classic.txt" | awk '
    function y(r, g, b) { return 0.265 * r + 0.670 * g + 0.065 * b }
    { e = y($1, $2, $3); p = y($4, $5, $6); c = y($7, $8, $9)
      printf "point %2d: classic %7.2f  -apE %+5.1f %%  without %+5.1f %%\n", NR, c,
          100 * (e / c - 1), 100 * (p / c - 1)
      if (e / c > 1.05 || e / c < 0.95) { print "FAIL: point " NR " with -apE"; bad = 1 }
      if (c < 100) { n++; se += e / c; sp += p / c } }
    END { printf "mean of %d: -apE %+.1f %%, without %+.1f %%\n", n, 100 * (se / n - 1),
              100 * (sp / n - 1)
          if (se / n > 1.025 || se / n < 0.975) { print "FAIL: -apE mean"; bad = 1 }
          if (sp / n > 0.85) { print "FAIL: without -apE the outside is already there"; bad = 1 }
          exit bad }' || fail=1

# The same room with its window open and an antimatter port in the opening (open_window.rad),
# and with the port set back 1 cm into the room, against RADIANCE's classic there (which
# the port does not change): every point within 5 %, the mean within 2.5 % (measured
# -1.5 ... +2.5 % both). Set back, the port's rays see the room's wall around the opening
# past its edges; counted as outside light, a point beside the window read +8 ... +15 %.
sed 's/^12  1.25 0 0.9  1.25 0 2.3  3.75 0 2.3  3.75 0 0.9$/12  1.25 .01 .9  1.25 .01 2.3  3.75 .01 2.3  3.75 .01 .9/' \
    "$data/open_window.rad" > set_back.rad
cmp -s set_back.rad "$data/open_window.rad" && bad "the port was not moved"
for v in open_window set_back; do
    "$BIN/oconv" "$([ $v = set_back ] && echo set_back.rad || echo "$data/$v.rad")" > $v.oct || exit 1
    "$BIN/mkpmap" -apg $v.pm 300k -apE -apo port_mat -n 2 $v.oct 2> /dev/null || bad "mkpmap $v"
    "$BIN/rtrace" -h -I -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 256 -ap $v.pm 200 -n 2 $v.oct \
        < "$data/points.txt" > $v.txt || bad "rtrace $v"
    paste $v.txt "$data/ref_radiance_open_window.txt" | awk -v v=$v '
        function y(r, g, b) { return 0.265 * r + 0.670 * g + 0.065 * b }
        { e = y($1, $2, $3); c = y($4, $5, $6); s += e / c
          if (e / c > 1.05 || e / c < 0.95) { printf "FAIL: %s point %d %+.1f %%\n", v, NR,
              100 * (e / c - 1); bad = 1 } }
        END { printf "%s, antimatter port: mean %+.1f %%\n", v, 100 * (s / NR - 1)
              if (s / NR > 1.025 || s / NR < 0.975) { print "FAIL: " v " mean"; bad = 1 }
              exit bad }' || fail=1
done

# A spectral map set (-cs 9, issue 50): each pass's ports see the outside in their own
# bands. The work plane's photopic irradiance (-pY, lux over 179) against the same
# classic reference: each point within 5 %, the mean of the 17 within 2.5 % (measured
# -1.0 ... +2.0 %, mean +0.5 %; without -apE -28 %).
"$BIN/mkpmap" -apg s.pm 300k -apE -apo window_glass -cs 9 -n 2 room.oct 2> s.err ||
    bad "mkpmap -apE -cs 9: $(cat s.err)"
"$BIN/rtrace" -h -I -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 256 -cs 9 -pY -ap s.pm 200 -n 2 room.oct \
    < "$data/points.txt" > s.txt || bad "rtrace -cs 9"
paste s.txt "$data/ref_radiance_classic.txt" | awk '
    { e = $1 / 179; c = 0.265 * $2 + 0.670 * $3 + 0.065 * $4
      if (e / c > 1.05 || e / c < 0.95) { printf "FAIL: -cs 9 point %d %+.1f %%\n", NR,
          100 * (e / c - 1); bad = 1 }
      if (c < 100) { n++; s += e / c } }
    END { printf "-cs 9, -apE: mean of %d %+.1f %%\n", n, 100 * (s / n - 1)
          if (s / n > 1.025 || s / n < 0.975) { print "FAIL: -cs 9 mean"; bad = 1 }
          exit bad }' || fail=1

out=$("$BIN/mkpmap" -apC c.pm 10k -apE -apo window_glass room.oct 2>&1)
[ $? -ne 0 ] && [ "$out" = "mkpmap: -apE: not with a contribution photon map (-apC)" ] ||
    bad "-apE with -apC: $out"
exit $fail
