# shellcheck shell=bash
# The engine of the analytic suite (tests/analytic/README): runs one case folder both ways,
# classic (rtrace -I, no photon map) and with a photon map (mkpmap, then rtrace -ap), and
# prints one table row per sensor point against the case's closed form, then a row for the
# mean over the points. Sourced by scripts/validate_analytic (full size) and
# tests/golden/analytic_suite.sh (light size). Needs:
#   AN_BIN   folder of the tools (oconv, rtrace, mkpmap, getinfo)
#   AN_TMP   scratch folder
#   AN_MODE  full | light
# A case folder holds scene.rad, points.txt (x y z dx dy dz), closed.awk (reads those
# lines, prints per point "E_total E_photon D": the closed-form irradiance, the part of it
# the photon map carries, and for a point that photons must not reach, the distance D from
# it to the nearest lit photon area, else 0), and case.sh, which sets the variables listed
# in an_case below.
#
# Tolerances (|value - closed form| <= tolerance), from the estimators' statistics:
#  - classic: t x SE + CLASSIC_BIAS x E_total. SE is the standard error of the mean of REPS
#    jittered repeats of the point (the sample standard deviation / sqrt(REPS)); t is
#    Student's quantile with REPS-1 degrees of freedom at the two-sided level of 4 normal
#    sigma (p = 6.3e-5). CLASSIC_BIAS is the case's stated deterministic bias (e.g. the
#    bounce truncation of -ab), plus 1e-5 for rtrace's printed digits.
#  - photon map: 4 sigma + biases. A density estimate over the k nearest photons of equal
#    flux has relative standard deviation 1/sqrt(k) (Poisson: the k-th neighbour's disc
#    area is Gamma(k)-distributed); sigma = E_photon / sqrt(k). Biases: RADIANCE's radius
#    (mean of the k-th and (k+1)-th distances) gives E (1 + 1/(2k)); the disc of radius
#    r = sqrt(k phi / (pi E_photon)) (phi the map's photon flux, getinfo AvgFlux) averages
#    the field: bias r^2 lap(E)/8, taken here from the closed form at four points r away in
#    the tangent plane, (sum E(x +- r) - 4 E(x)) / 8; PMAP_BIAS x E_photon, the case's stated
#    bias. At a point photons must not reach (E_photon = 0, distance D to the nearest
#    photons), every photon the lookup finds is at least D away: the estimate is at most
#    k phi / (pi D^2), which is the tolerance there. With a final gather (-ab 1) the photon
#    part is an average of density estimates at the gather rays' hits, each with relative
#    sigma 1/sqrt(k), so its sigma is at most E_photon / sqrt(k) still; the gather's own
#    sampling noise adds t x SE over PMAP_REPS repeats, as the classic's.
#  - mean rows: the mean of value / closed form over the points with E_total > 0;
#    tolerance 4 x sqrt(sum (sigma_i / E_i)^2) / n plus the mean bias, with the sum of the
#    sigmas in place of the root sum of squares when two points' photon discs overlap
#    (their estimates share photons); classic likewise with t x SE.

AN_LIB_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# Student-t quantile for REPS repeats (REPS-1 degrees of freedom) at two-sided p = 6.3e-5.
an_t() {
    case $1 in
        4) echo 32.6 ;; 8) echo 8.47 ;; 16) echo 5.48 ;; 32) echo 4.62 ;; 64) echo 4.29 ;;
        *) echo "analytic suite: REPS must be 4, 8, 16, 32 or 64, not $1" >&2; return 1 ;;
    esac
}

an_header() {
    printf "%-20s %-20s %10s %10s %8s %8s %10s %8s %8s  %s\n" case point closed classic dev \
        tol "photon map" dev tol result
}

# grey value of rtrace's RGB lines (the scenes are grey; the weights of scripts/validate)
an_grey() { awk '{ printf "%.7g\n", 0.265 * $1 + 0.670 * $2 + 0.065 * $3 }'; }

# an_case DIR: runs the case in DIR; prints its rows; returns 1 when a row fails.
an_case() {
    local dir=$1 name w n reps preps k photons t tp phi lib="$AN_LIB_DIR/closed_forms.awk"
    name=$(basename "$dir")
    w=$AN_TMP/$name
    mkdir -p "$w"
    # What case.sh sets (defaults here):
    CLASSIC=""          # rtrace options of the classic run (added to -h -I -n 2)
    REPS=32             # jittered repeats of each point (classic), full size
    REPS_LIGHT=8        #   light size
    CLASSIC_BIAS=0      # stated relative bias of the classic value
    MAP=""              # mkpmap map option: -apd, -apg or -apc
    MAP_OPTS=""         # further mkpmap options (ports -apo, sensors -aps)
    PHOTONS=""          # photons to store, full size
    PHOTONS_LIGHT=""    #   light size
    K=""                # density estimate bandwidth (photons per lookup), full size
    K_LIGHT=""          #   light size
    RENDER=""           # rtrace options of the photon map run (besides -ap map k)
    PMAP_BIAS=0         # stated relative bias of the photon part
    PMAP_REPS=1         # repeats of the photon map run (a final gather's sampling noise)
    PMAP_REPS_LIGHT=1   #   light size
    LIGHT_POINTS=""     # lines of points.txt used at light size (all when empty)
    SEED=1              # mkpmap -apr
    # shellcheck disable=SC1091
    . "$dir/case.sh"
    SEED=${AN_SEED:-$SEED}  # another photon distribution (scripts/validate_analytic -s)
    if [ "$AN_MODE" = light ]; then
        reps=$REPS_LIGHT; k=$K_LIGHT; photons=$PHOTONS_LIGHT
        if [ -n "$LIGHT_POINTS" ]; then
            # shellcheck disable=SC2086 # a list of line numbers
            sed -n "$(printf '%sp;' $LIGHT_POINTS)" "$dir/points.txt" > "$w/pts"
        else
            cp "$dir/points.txt" "$w/pts"
        fi
    else
        reps=$REPS; k=$K; photons=$PHOTONS
        cp "$dir/points.txt" "$w/pts"
    fi
    n=$(wc -l < "$w/pts")
    t=$(an_t "$reps") || return 1
    preps=$PMAP_REPS; tp=0
    [ "$AN_MODE" = light ] && preps=$PMAP_REPS_LIGHT
    [ "$preps" -gt 1 ] && { tp=$(an_t "$preps") || return 1; }

    # -f: a frozen octree, which does not read scene.rad again (by its path) at each run.
    if ! "$AN_BIN/oconv" -f "$dir/scene.rad" > "$w/scene.oct" 2> "$w/oconv.log"; then
        echo "$name: FAIL: oconv: $(head -3 "$w/oconv.log")"; return 1
    fi
    # rtrace -I evaluates the irradiance 1e-4 in front of the given point (RADIANCE compat,
    # render/renderer.cpp; -op prints that point): the closed form is taken there. Under
    # the 2 m high lamp of point_source it is 1e-4 above the value on the floor.
    awk '{ l = sqrt($4 * $4 + $5 * $5 + $6 * $6)
        printf "%.9g %.9g %.9g %s %s %s\n", $1 + 1e-4 * $4 / l, $2 + 1e-4 * $5 / l,
            $3 + 1e-4 * $6 / l, $4, $5, $6 }' "$w/pts" > "$w/pts_eval"
    awk -f "$lib" -f "$dir/closed.awk" < "$w/pts_eval" > "$w/closed.txt"

    # Classic: REPS copies of the point list; line i is point (i-1) % n. -u-: each ray's
    # random numbers depend on its input line only (different for every repeat, the same
    # from run to run), so a run is reproducible.
    # shellcheck disable=SC2086 # option lists (here and below)
    for _ in $(seq "$reps"); do cat "$w/pts"; done |
        "$AN_BIN/rtrace" -h -I -u- $CLASSIC -n 2 "$w/scene.oct" 2> "$w/classic.log" |
        an_grey > "$w/classic_all.txt"
    awk -v n="$n" -v m="$reps" '{ i = (NR - 1) % n; s[i] += $1; q[i] += $1 * $1; c[i]++ }
        END { for (i = 0; i < n; i++) { if (c[i] != m) { print "missing"; exit 1 }
            mu = s[i] / m; v = (q[i] - m * mu * mu) / (m - 1); if (v < 0) v = 0
            printf "%.7g %.4g\n", mu, sqrt(v / m) } }' "$w/classic_all.txt" > "$w/classic.txt" ||
        { echo "$name: FAIL: classic rtrace: $(head -3 "$w/classic.log")"; return 1; }

    # Photon map.
    # shellcheck disable=SC2086
    if ! "$AN_BIN/mkpmap" -fo -apr "$SEED" $MAP "$w/map.pm" "$photons" $MAP_OPTS -n 2 \
        "$w/scene.oct" > "$w/mkpmap.log" 2>&1; then
        echo "$name: FAIL: mkpmap: $(tail -2 "$w/mkpmap.log")"; return 1
    fi
    phi=$("$AN_BIN/getinfo" "$w/map.pm" |
        awk '/AvgFlux/ { gsub(/[\[\],]/, " "); print $(NF - 1) }')
    # PMAP_REPS > 1 (a final gather, whose hemisphere samples are random): the mean of
    # that many repeats, and its standard error, as the classic's.
    # shellcheck disable=SC2086
    for _ in $(seq "$preps"); do cat "$w/pts"; done |
        "$AN_BIN/rtrace" -h -I -u- $RENDER -ap "$w/map.pm" "$k" -n 2 "$w/scene.oct" \
        2> "$w/pmap.log" | an_grey > "$w/pmap_all.txt"
    awk -v n="$n" -v m="$preps" '{ i = (NR - 1) % n; s[i] += $1; q[i] += $1 * $1; c[i]++ }
        END { for (i = 0; i < n; i++) { if (c[i] != m) { print "missing"; exit 1 }
            mu = s[i] / m; v = m > 1 ? (q[i] - m * mu * mu) / (m - 1) : 0; if (v < 0) v = 0
            printf "%.7g %.4g\n", mu, sqrt(v / m) } }' "$w/pmap_all.txt" > "$w/pmap.txt" ||
        { echo "$name: FAIL: photon map rtrace: $(head -3 "$w/pmap.log")"; return 1; }

    # The lookup disc's radius at each point, and the closed form r away in the tangent
    # plane (four points per point; the point itself four times where E_photon = 0).
    paste "$w/pts_eval" "$w/closed.txt" | awk -v k="$k" -v phi="$phi" '{
        nx = $4; ny = $5; nz = $6; l = sqrt(nx * nx + ny * ny + nz * nz); nx /= l; ny /= l; nz /= l
        r = $8 > 0 ? sqrt(k * phi / (atan2(0, -1) * $8)) : 0
        ax = 1; ay = 0; az = 0; if (nx > 0.9 || nx < -0.9) { ax = 0; ay = 1 }
        ux = ny * az - nz * ay; uy = nz * ax - nx * az; uz = nx * ay - ny * ax
        l = sqrt(ux * ux + uy * uy + uz * uz); ux /= l; uy /= l; uz /= l
        vx = ny * uz - nz * uy; vy = nz * ux - nx * uz; vz = nx * uy - ny * ux
        print r > "/dev/stderr"
        for (s = -1; s <= 1; s += 2) {
            print $1 + s * r * ux, $2 + s * r * uy, $3 + s * r * uz, nx, ny, nz
            print $1 + s * r * vx, $2 + s * r * vy, $3 + s * r * vz, nx, ny, nz } }' \
        > "$w/offsets.txt" 2> "$w/radius.txt"
    awk -f "$lib" -f "$dir/closed.awk" < "$w/offsets.txt" |
        awk '{ s += $2 } NR % 4 == 0 { print s; s = 0 }' > "$w/offsets_closed.txt"

    paste "$w/pts" "$w/closed.txt" "$w/classic.txt" "$w/pmap.txt" "$w/radius.txt" \
        "$w/offsets_closed.txt" | awk -v name="$name" -v t="$t" -v k="$k" -v phi="$phi" \
        -v cb="$CLASSIC_BIAS" -v pb="$PMAP_BIAS" -v tg="$tp" '
    function dev(v, c) {
        return c > 0 ? sprintf("%+.2f%%", 100 * (v / c - 1)) : sprintf("%+.2g", v - c)
    }
    function tol(x, c) { return c > 0 ? sprintf("%.2f%%", 100 * x / c) : sprintf("%.2g", x) }
    function within(v, c, t) { return v - c <= t && c - v <= t }
    function verdict(okc, okp) {
        if (!(okc && okp)) bad = 1
        if (okc && okp) return "pass"
        return okc ? "FAIL (photon map)" : okp ? "FAIL (classic)" : "FAIL (both)"
    }
    {
        n++; x[n] = $1; y[n] = $2; z[n] = $3
        et = $7; ep = $8; d = $9; cm = $10; cse = $11; pm = $12; pse = $13; r[n] = $14; off = $15
        tc = t * cse + (cb + 1e-5) * et
        sig = ep / sqrt(k)
        curv = (off - 4 * ep) / 8; if (curv < 0) curv = -curv
        tp = 4 * sig + tg * pse + curv + (pb + 0.5 / k) * ep
        if (ep == 0 && d > 0) tp += k * phi / (atan2(0, -1) * d * d)
        res = verdict(within(cm, et, tc), within(pm, et, tp))
        printf "%-20s %-20s %10.5g %10.5g %8s %8s %10.5g %8s %8s  %s\n", name,
            sprintf("(%.3g, %.3g, %.3g)", $1, $2, $3), et, cm, dev(cm, et), tol(tc, et),
            pm, dev(pm, et), tol(tp, et), res
        if (et > 0) { m++; rc += cm / et; rp += pm / et; vc += (t * cse / et) ^ 2
            bc += cb + 1e-5; s2 += (sig / et) ^ 2; s1 += sig / et; vg += (tg * pse / et) ^ 2
            bp += (curv + (pb + 0.5 / k) * ep) / et }
    }
    END {
        # Do two photon discs overlap? Then their estimates share photons.
        for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++)
            if ((x[i] - x[j]) ^ 2 + (y[i] - y[j]) ^ 2 + (z[i] - z[j]) ^ 2 < (r[i] + r[j]) ^ 2)
                ovl = 1
        if (m > 0) {
            tcm = sqrt(vc) / m + bc / m
            tpm = 4 * (ovl ? s1 : sqrt(s2)) / m + sqrt(vg) / m + bp / m
            res = verdict(within(rc / m, 1, tcm), within(rp / m, 1, tpm))
            printf "%-20s %-20s %10s %10.5f %8s %8s %10.5f %8s %8s  %s\n", name,
                sprintf("mean of %d%s", m, ovl ? " (overlap)" : ""), "ratio 1", rc / m,
                dev(rc / m, 1), tol(tcm, 1), rp / m, dev(rp / m, 1), tol(tpm, 1), res
        }
        exit bad
    }'
}
