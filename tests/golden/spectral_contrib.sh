#!/bin/bash
# Contribution photon maps as spectral map sets (issue 50): ../shared/validation/contrib (three
# coloured lamps, 16 floor sensors), rcontrib -cs 9 -V with the modifier file. Each lamp's
# 9 band contributions summed over the sensors, from
#   - a contribution map set (mkpmap -cs 9 -apC cp.pm 300k: cp.pm, cp.pm.3-5, cp.pm.6-8),
#     rcontrib -ap cp.pm 50;
#   - a precomputed contribution map set (mkpmap -cs 9 -apC d.pm 300k 200 0 -V -M ...: each
#     pass's coefficients beside its own file, d.pm.rc, d.pm.3-5.rc, d.pm.6-8.rc, one
#     d.pm.opt), rcontrib -ab 1 -ad 1024 -ap d.pm @d.pm.opt;
# against classic rcontrib -cs 9 -ab 6 -ad 2048 -lw 1e-5. Measured: +1.3 ... +2.9 % and
# +0.7 ... +2.1 % a band, as the RGB maps read against RADIANCE's classic (+1.5 ... +2.1 %,
# +0.7 ... +1.7 %: the k/(k-1) bias of a 50- or 200-photon estimate and the classic's
# bounces left out). Each band within 4 %; the map set's files must all be there.
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared validation/contrib
BIN="${RP_BIN:?RP_BIN not set}"
val="$RP_SHARED_DIR/validation/contrib"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }
"$BIN/oconv" "$val/scene.rad" > c.oct || exit 1
"$BIN/rcontrib" -I -h -V -cs 9 -ab 6 -ad 2048 -lw 1e-5 -n 2 -M "$val/modfile.txt" c.oct \
    < "$val/points.txt" > classic.txt || bad "classic rcontrib"
"$BIN/mkpmap" -apC cp.pm 300k -cs 9 -n 2 c.oct 2> mk.err || bad "mkpmap -apC: $(cat mk.err)"
"$BIN/mkpmap" -apC d.pm 300k 200 0 -V -M "$val/modfile.txt" -cs 9 -n 2 c.oct 2> mk.err ||
    bad "mkpmap precomputed: $(cat mk.err)"
for f in cp.pm cp.pm.3-5 cp.pm.6-8 d.pm d.pm.3-5 d.pm.6-8 d.pm.opt d.pm.rc d.pm.3-5.rc d.pm.6-8.rc; do
    [ -e "$f" ] || bad "no $f"
done
"$BIN/rcontrib" -I -h -V -cs 9 -ap cp.pm 50 -M "$val/modfile.txt" c.oct < "$val/points.txt" \
    > map.txt || bad "rcontrib -ap cp.pm"
"$BIN/rcontrib" -I -h -cs 9 -ab 1 -ad 1024 -lw 1e-4 -ap d.pm @d.pm.opt c.oct \
    < "$val/points.txt" > precomputed.txt || bad "rcontrib -ap d.pm"
for m in map precomputed; do
    paste classic.txt $m.txt | awk -v m=$m '
        NF != 54 { print "FAIL: " m ": " NF - 27 " columns, not 27"; bad = 1; exit }
        { for (i = 1; i <= 27; i++) { c[i] += $i; p[i] += $(i + 27) } }
        END { if (bad) exit 1
              for (s = 0; s < 3; s++) {
                  line = ""
                  for (j = 1; j <= 9; j++) {
                      i = 9 * s + j; d = p[i] / c[i] - 1
                      line = line sprintf(" %+.1f", 100 * d)
                      if (d > 0.04 || d < -0.04) bad = 1
                  }
                  printf "%s, lamp %d, band against classic (%%):%s\n", m, s + 1, line
              }
              if (bad) print "FAIL: a band more than 4 % off"
              exit bad }' || fail=1
done
exit $fail
