#!/bin/bash
# rcontrib, classic and with a contribution photon map (tests/data/contrib, validation/contrib):
# 1. Analytic: a sphere lamp (radius r = 0.1) at d = 2 above a sensor: the -I coefficient
#    (-V-) is the lamp's cosine-weighted solid angle pi (r/d)^2 = 7.854e-3, within 0.5 %;
#    -V+ is that times the lamp's radiance (100).
# 2. Tregenza bins (lib/tregenza.cal) of a uniform sky of radiance 1 seen by a sensor
#    facing up: each band's coefficient is (sin^2 a2 - sin^2 a1) pi, the whole sky pi,
#    ground bin 0. -ad 400000 (0.2 s): the seven 12-degree bands within 0.5 % (measured
#    0.05 %), the zenith cap within 2 % (0.24 %; 5 standard deviations of the samples
#    its edge cuts off a row of the stratified hemisphere), every patch within 5 % (its
#    azimuth numbering; 1.8 %), the total within 0.1 %.
# 3. validation/contrib (three coloured lamps in a room): per-source contributions with
#    -ap cp.pm 50 (300 k contribution photons) within 3 % of RADIANCE's per sensor on
#    average (measured -0.8 to +0.1 %); their sum equals our rtrace -ab 1 -ap g.pm 50
#    total within 1.5 % at every sensor (-ad 2048 for both: the gather's noise is 0.3 %
#    rms per sensor there, 1 % at rcontrib's default -ad 350); classic -ab 6 within 3 %
#    of RADIANCE's per source on average (measured within 0.3 %).
# 4. Weak sources are not biased: lamps of radiance 1000, 10 and 1 share one map with
#    equal photons per source; each one's mean contribution over the 16 sensors agrees
#    with a map of that lamp alone (the others black) within 3 % (measured within 0.7 %).
# 4b. Through glass (tests/data/contrib/glass.rad): with a contribution map the lamp's light
#    reaches sensors under a glass pane as caustic photons (shadow rays through glass
#    are not counted, RADIANCE srcRayInPmap): the mean over 200 sensors equals the
#    classic coefficient within 3 % (measured +1.2 to +1.6 % over four seeds at
#    bandwidth 100, the density estimate's bias; RADIANCE +1.6 % at bandwidth 50).
# 5. Output layout against RADIANCE 5.4a's files (tests/data/contrib/radiance): headers
#    line by line (dates and SOFTWARE masked), records byte for byte in layout, values
#    within 8 %: RADIANCE's -dj .9 aims each shadow ray at one jittered point of a lamp
#    and lands up to 3.5 % from the exact value at these points (ours within 1 %).
# 6. Errors: a global map, no modifier in the map, a bin expression that does not
#    evaluate, an existing output without -fo: one line, non-zero exit, nothing written.
# 7. Bins of photon contributions (tests/data/contrib/sunsky.rad: sun and sky over an open
#    box): RADIANCE's 3.1kPD map gives RADIANCE's Tregenza bins (the same 22 bins, values
#    within 0.5 %; with the sky alone tracked, the sun's photons are left out of the
#    lookups as RADIANCE leaves them out: the same 39 bins); our -apCPD map is version 3.1kPD, puts the whole sun in bin 88 and
#    loses no photon (the bins add up to the one-bin total); a map without primary rays
#    drops binned photons with RADIANCE's warning.
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared validation/contrib
BIN="${RP_BIN:?RP_BIN not set}"
DATA="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}/tests/data/contrib"
VAL="${RP_SHARED_DIR:?RP_SHARED_DIR not set}/validation/contrib"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
export PATH="$BIN:$PATH"
unset RAYPATH
fail=0
check() {  # check NAME COND(awk expression on $0) MESSAGE-INPUT
    if awk "BEGIN { exit !($2) }"; then echo "ok   $1"; else echo "FAIL $1 ($3)"; fail=1; fi
}
lum() { awk '{ for (k = 0; 3 * k + 3 <= NF; k++) printf "%s%.8g", (k ? " " : ""), 0.265*$(3*k+1)+0.670*$(3*k+2)+0.065*$(3*k+3); print "" }' "$@"; }

# 1. analytic lamp
cp "$DATA/lamp_sky.rad" . && oconv lamp_sky.rad > ls.oct || exit 1
c=$(echo "0 0 0 0 0 1" | rcontrib -h -I -u- -ab 0 -m lamp ls.oct | awk '{print $2}')
v=$(echo "0 0 0 0 0 1" | rcontrib -h -I -u- -ab 0 -V+ -m lamp ls.oct | awk '{print $2}')
check "lamp coefficient $c vs pi (r/d)^2 = 7.8540e-3" "sqrt(($c / 7.853982e-3 - 1)^2) < 0.005" "$c"
check "lamp contribution $v = 100 x coefficient" "sqrt(($v / (100 * $c) - 1)^2) < 1e-6" "$v"

# 2. Tregenza bins of a uniform sky
echo "0 0 3 0 0 1" | rcontrib -h -I -u- -ab 1 -ad 400000 -lw 1e-9 -f tregenza.cal -b tbin \
    -bn Ntbins -m skyglow ls.oct > sky.txt || { echo "FAIL tregenza run"; exit 1; }
tr '\t' '\n' < sky.txt | awk 'NF' | awk 'NR % 3 == 2' > sky_g.txt
res=$(awk 'function s2(a) { return sin(a * 3.14159265358979 / 180)^2 }
    { v[NR - 1] = $1 }
    END { split("30 30 24 24 18 12 6 1", n, " "); k = 1; worst = 0; total = 0; patch = 0
          for (b = 1; b <= 8; b++) { sum = 0
              a1 = 12 * (b - 1); a2 = (b == 8) ? 90 : 12 * b
              exact = 3.14159265358979 * (s2(a2) - s2(a1))
              for (i = 0; i < n[b]; i++) {
                  d = v[k] / (exact / n[b]) - 1; if (d < 0) d = -d; if (d > patch) patch = d
                  sum += v[k++] }
              d = sum / exact - 1; if (d < 0) d = -d
              if (b < 8 && d > worst) worst = d
              if (b == 8) cap = d
              total += sum }
          printf "%.5f %.5f %.5f %.5f %g", worst, cap, patch, total / 3.14159265358979 - 1, v[0] }' sky_g.txt)
read -r worst cap patch totdev ground <<< "$res"
check "tregenza: worst of the 7 bands $worst relative" "$worst < 0.005" "$res"
check "tregenza: zenith cap $cap relative" "$cap < 0.02" "$res"
check "tregenza: worst patch $patch relative" "$patch < 0.05" "$res"
check "tregenza: sky total vs pi ($totdev)" "sqrt(($totdev)^2) < 0.001" "$res"
check "tregenza: ground bin zero" "$ground == 0" "$res"

# 3. validation/contrib
oconv "$VAL/scene.rad" > c.oct || exit 1
mkpmap -apC cp.pm 300k -n 2 c.oct > /dev/null 2>&1 && mkpmap -apg g.pm 300k -n 2 c.oct > /dev/null 2>&1 \
    || { echo "FAIL mkpmap"; exit 1; }
cp "$VAL/modfile.txt" .
rcontrib -I -h -V -u- -ap cp.pm 50 -M modfile.txt c.oct < "$VAL/points.txt" > pm.txt 2> pm.err \
    || { echo "FAIL rcontrib -ap"; cat pm.err; exit 1; }
lum pm.txt > pm_l.txt; lum "$VAL/ref_pmap_rcontrib_rgb.txt" > ref_l.txt
for k in 1 2 3; do
    d=$(paste pm_l.txt ref_l.txt | awk -v k=$k '{ s += $k / $(k + 3) - 1 } END { printf "%.4f", s / NR }')
    check "pmap source $k: mean relative to RADIANCE $d" "sqrt(($d)^2) < 0.03" "$d"
done
# Out of core (-aC below the map's size): the same photons, so the same contributions.
rcontrib -I -h -V -u- -ap cp.pm 50 -aC 30k -M modfile.txt c.oct < "$VAL/points.txt" > pmooc.txt 2> /dev/null
cmp -s pmooc.txt pm.txt && echo "pmap out of core: same as in core" ||
    { echo "FAIL pmap out of core differs from in core"; fail=1; }
rcontrib -I -h -V -u- -ad 2048 -ap cp.pm 50 -M modfile.txt c.oct < "$VAL/points.txt" | lum > pm2.txt
rtrace -I -h -u- -ab 1 -ad 2048 -ap g.pm 50 c.oct < "$VAL/points.txt" | lum > tot.txt
d=$(paste pm2.txt tot.txt | awk '{ r = ($1 + $2 + $3) / $4 - 1; if (r < 0) r = -r; if (r > w) w = r } END { printf "%.4f", w }')
check "pmap: sum of sources vs rtrace total, worst sensor $d" "$d < 0.015" "$d"
rcontrib -I -h -V -u- -ab 6 -ad 2048 -lw 1e-5 -M modfile.txt c.oct < "$VAL/points.txt" | lum > cl.txt
lum "$VAL/ref_classic_rcontrib_ab6_rgb.txt" > refc.txt
for k in 1 2 3; do
    d=$(paste cl.txt refc.txt | awk -v k=$k '{ s += $k / $(k + 3) - 1 } END { printf "%.4f", s / NR }')
    check "classic -ab 6 source $k: mean relative to RADIANCE $d" "sqrt(($d)^2) < 0.03" "$d"
done

# 4. weak sources
sed -e 's/^3 100 10 10$/3 1000 1000 1000/' -e 's/^3 10 100 10$/3 10 10 10/' \
    -e 's/^3 10 10 100$/3 1 1 1/' "$VAL/scene.rad" > all.rad
oconv all.rad > all.oct && mkpmap -apC all.pm 300k -n 2 all.oct > /dev/null 2>&1 || exit 1
rcontrib -h -I -V -u- -ad 1024 -ap all.pm 50 -M modfile.txt all.oct < "$VAL/points.txt" > all.txt
k=0
for s in red green blue; do
    k=$((k + 1))
    awk -v s=$s 'BEGIN { skip = 0 }
        /^void light lamp_/ { if ($3 != "lamp_" s) { print "void plastic " $3; print "0"; print "0"; print "5 0 0 0 0 0"; skip = 3; next } }
        skip > 0 { skip--; next } { print }' all.rad > only.rad
    oconv only.rad > only.oct && mkpmap -fo -apC only.pm 300k -n 2 only.oct > /dev/null 2>&1 || exit 1
    rcontrib -h -I -V -u- -ad 1024 -ap only.pm 50 -m lamp_$s only.oct < "$VAL/points.txt" > only.txt
    r=$(paste all.txt only.txt | awk -v k=$k '{ a += $(3 * (k - 1) + 2); b += $11 } END { printf "%.4f", a / b - 1 }')
    check "weak sources: lamp_$s joint map vs alone $r" "sqrt(($r)^2) < 0.03" "$r"
done

# 4b. through glass
oconv "$DATA/glass.rad" > g.oct && mkpmap -apC gc.pm 500k -n 2 g.oct > /dev/null 2>&1 || exit 1
awk 'BEGIN { for (i = 0; i < 200; i++) { x = -0.4 + 0.8 * ((i * 0.618034) % 1); y = -0.4 + 0.8 * ((i * 0.754878) % 1); print x, y, 0, 0, 0, 1 } }' > gp.txt
cg=$(rcontrib -h -I -u- -ab 0 -m lamp g.oct < gp.txt | awk '{ s += $1 } END { print s / NR }')
pg=$(rcontrib -h -I -u- -ap gc.pm 100 -m lamp g.oct < gp.txt | awk '{ s += $1 } END { print s / NR }')
check "through glass: photons $pg vs classic $cg" "sqrt(($pg / $cg - 1)^2) < 0.03" "$pg $cg"

# 5. layout against RADIANCE
mkdir lay && cd lay && cp "$DATA/lamp_sky.rad" "$DATA/radiance/pts.txt" . && oconv lamp_sky.rad > ls.oct
for f in a f d; do rcontrib -I+ -ab 0 -fa$f -m lamp -m lamp2 -m skyglow ls.oct < pts.txt > stdout_f$f.out; done
rcontrib -I+ -ab 0 -V+ -o c_%s.txt -m lamp -m lamp2 ls.oct < pts.txt
# head FILE: the header, dates and SOFTWARE masked; body FILE: the bytes after it
head_of() { awk '{ if ($0 == "") exit; sub(/^(SOFTWARE|CAPDATE|GMT)=.*/, substr($0, 1, index($0, "=")) "*"); print }' "$1"; }
body_of() { tail -c +$(( $(awk '{ n += length($0) + 1; if ($0 == "") { print n; exit } }' "$1") + 1 )) "$1"; }
# values FILE FORMAT: one number per line
values_of() {
    case $2 in
        ascii) body_of "$1" | tr -s ' \t' '\n\n' | awk 'NF' ;;
        float) body_of "$1" | od -An -v -tf4 | tr -s ' ' '\n' | awk 'NF' ;;
        double) body_of "$1" | od -An -v -tf8 | tr -s ' ' '\n' | awk 'NF' ;;
    esac
}
for f in stdout_fa.out stdout_ff.out stdout_fd.out c_lamp.txt c_lamp2.txt; do
    ref="$DATA/radiance/$f"
    fmt=$(awk -F= '/^FORMAT=/ { print $2 }' "$ref")
    same_head=$(cmp -s <(head_of "$ref") <(head_of "$f") && echo same || echo differs)
    if [ "$fmt" = ascii ]; then
        same_rec=$(cmp -s <(body_of "$ref" | sed 's/[-+.e0-9]\+/#/g') <(body_of "$f" | sed 's/[-+.e0-9]\+/#/g') && echo same || echo differ)
    else
        same_rec=$([ "$(body_of "$ref" | wc -c)" = "$(body_of "$f" | wc -c)" ] && echo same || echo differ)
    fi
    worst=$(paste <(values_of "$ref" "$fmt") <(values_of "$f" "$fmt") | awk '{ d = $1 - $2; if (d < 0) d = -d;
        m = ($1 < 0 ? -$1 : $1); if (($2 < 0 ? -$2 : $2) > m) m = ($2 < 0 ? -$2 : $2); if (m < 1e-9) m = 1e-9
        if (d / m > w) w = d / m; n++ } END { printf "%.3f %d", w, n }')
    read -r w n <<< "$worst"
    if [ "$same_head" = same ] && [ "$same_rec" = same ] && [ "$n" -gt 0 ] && awk "BEGIN { exit !($w < 0.08) }"; then
        echo "ok   layout $f (header same, records same, $n values, worst $w)"
    else
        echo "FAIL layout $f (header $same_head, records $same_rec, $n values, worst $w)"; fail=1
        diff <(head_of "$ref") <(head_of "$f")
    fi
done
cd ..

# 6. errors: one line on stderr, non-zero exit, nothing on standard output
err() {  # err NAME EXPECTED-TEXT ARGS...
    local name=$1 want=$2; shift 2
    echo "1 1 0.001 0 0 1" | rcontrib "$@" > out.txt 2> err.txt
    local rc=$?
    if [ $rc -ne 0 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q -- "$want" err.txt && [ ! -s out.txt ]; then
        echo "ok   error: $name"
    else
        echo "FAIL error: $name (rc $rc: $(cat err.txt))"; fail=1
    fi
}
err "global map" "global photon map does not support contributions" -I -ap g.pm 50 -m lamp_red c.oct
err "no modifier in map" "modifiers not in photon map" -I -ap cp.pm 50 -m wall_white c.oct
err "bad bin expression" "undefined function 'nosuch'" -I -b 'nosuch(Dx)' -bn 4 -m lamp_red c.oct
echo keep > c_lamp_red.txt
err "existing output" "cannot open 'c_lamp_red.txt' for writing: File exists" -I -o c_%s.txt -m lamp_red c.oct
[ "$(cat c_lamp_red.txt)" = keep ] || { echo "FAIL existing output was changed"; fail=1; }

# 7. photon bins by direction
oconv "$DATA/sunsky.rad" > ss.oct && cp "$DATA/radiance/sunsky_pd.pm" . && touch sunsky_pd.pm
bins="-f tregenza.cal -b tbin -bn Ntbins"
echo "0 0 0.001 0 0 1" > pt.txt
# -u-: the sun's bin carries its -dj .9 jitter (RADIANCE's reference too): over random
# seeds the worst bin ranged 0.02 to 0.56 % from RADIANCE's, so a seed of its own would
# make the 0.5 % check fail now and then; this seed gives 0.11 % (-dj 0: 0.20 %).
rcontrib -u- -h -I -ab -1 -ap sunsky_pd.pm 50 $bins -m skyglow -m sunmod ss.oct < pt.txt > pd.txt
d=$(paste <(tr '\t' '\n' < pd.txt | awk 'NF') <(tr '\t' '\n' < "$DATA/radiance/sunsky_pd_tbin.txt" | awk 'NF') |
    awk '{ if (($1 == 0) != ($2 == 0)) bad++; else if ($2 != 0) { r = $1 / $2 - 1; if (r < 0) r = -r; if (r > w) w = r } }
         END { printf "%d %.4f", bad, w }')
read -r bad w <<< "$d"
check "RADIANCE's 3.1kPD map: same bins ($bad differ), worst value $w" "$bad == 0 && $w < 0.005" "$d"
rcontrib -h -I -ab -1 -ap sunsky_pd.pm 50 $bins -m skyglow ss.oct < pt.txt > pd_sky.txt
d=$(paste <(tr '\t' '\n' < pd_sky.txt | awk 'NF') <(tr '\t' '\n' < "$DATA/radiance/sunsky_pd_tbin_sky.txt" | awk 'NF') |
    awk '{ if (($1 == 0) != ($2 == 0)) bad++; else if ($2 != 0) { r = $1 / $2 - 1; if (r < 0) r = -r; if (r > w) w = r }; if ($2 != 0) nz++ }
         END { printf "%d %.4f %d", bad, w, nz }')
read -r bad w nz <<< "$d"
check "sky alone tracked: untracked photons skipped ($nz non-zero values, 39 bins x 3; $bad differ, worst $w)" "$bad == 0 && $w < 0.005 && $nz == 117" "$d"
mkpmap -apCPD own.pm 20k ss.oct > /dev/null 2>&1 || exit 1
getinfo own.pm | grep -q "VERSION=3.1kPD" && echo "ok   -apCPD writes VERSION=3.1kPD" || { echo "FAIL -apCPD version"; fail=1; }
rcontrib -h -I -u- -ab -1 -ap own.pm 50 $bins -m skyglow -m sunmod ss.oct < pt.txt | tr '\t' '\n' | awk 'NF' | awk 'NR % 3 == 2' > own.txt
rcontrib -h -I -u- -ab -1 -ap own.pm 50 -m skyglow -m sunmod ss.oct < pt.txt | awk '{ print $2, $5 }' > own1.txt
res=$(awk -v t="$(cat own1.txt)" 'BEGIN { split(t, one, " ") } { if (NR <= 146) sky += $1; else { sun += $1; if (NR == 146 + 89) at88 = $1 } }
      END { printf "%.6g %.6g %.6g %.6g %.6g", sky, one[1], sun, one[2], at88 }' own.txt)
read -r sky sky1 sun sun1 at88 <<< "$res"
check "-apCPD: sky bins add up ($sky vs $sky1)" "sqrt(($sky / $sky1 - 1)^2) < 1e-5" "$res"
check "-apCPD: the sun all in bin 88 ($at88 of $sun1)" "$sun1 > 0 && sqrt(($at88 / $sun1 - 1)^2) < 1e-5 && sqrt(($sun / $sun1 - 1)^2) < 1e-5" "$res"
mkpmap -apC plain.pm 20k ss.oct > /dev/null 2>&1 || exit 1
rcontrib -h -I -ab -1 -ap plain.pm 50 $bins -m skyglow ss.oct < pt.txt > plain.txt 2> plain.err
z=$(tr '\t' '\n' < plain.txt | awk 'NF { s += $1 } END { print s + 0 }')
if grep -q "no photon primary directions for bin evaluation" plain.err && [ "$z" = 0 ]; then
    echo "ok   map without primary rays: binned photons dropped, RADIANCE's warning"
else
    echo "FAIL map without primary rays ($z; $(cat plain.err))"; fail=1
fi
exit $fail
