#!/usr/bin/env bash
# Total flux stored in the Cornell global and caustic maps (AvgFlux x NumPhotons, per
# RGB channel) against RADIANCE 5.4's maps of ../shared/validation/cornell/README.md
# (g.pm 497,550 x [5.14e-04 4.55e-04 3.42e-04], c.pm 988,961 x [5.10e-05 4.55e-05
# 3.84e-05]). Stored flux does not depend on the photon count, so small maps do; 5 %
# allows for 3-digit AvgFlux, ~1 % noise at these counts and RADIANCE's own noise.
set -euo pipefail
. "$(dirname "$0")/lib/shared.sh"
require_shared validation/cornell
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$RP_BIN/mkpmap" -apg "$tmp/g.pm" 50k -apc "$tmp/c.pm" 100k -apr 3 -n 2 \
    "$RP_SHARED_DIR/validation/cornell/scene.rad" > "$tmp/log" 2>&1
check() {  # map, reference photons, reference r g b
    "$RP_BIN/getinfo" "$1" | awk -v N="$2" -v R="$3" -v G="$4" -v B="$5" -v map="$1" '
        /NumPhotons/ { n = $NF }
        /AvgFlux/ { gsub(/[\[\],]/, " "); r = $(NF-2); g = $(NF-1); b = $NF }
        END {
            split(R " " G " " B, ref, " "); split(r " " g " " b, ours, " ")
            bad = 0
            for (i = 1; i <= 3; i++) {
                dev = ours[i] * n / (ref[i] * N) - 1
                printf "%s channel %d: total flux %+.1f%% vs RADIANCE\n", map, i, 100 * dev
                if (dev > 0.05 || dev < -0.05) bad = 1
            }
            exit bad
        }'
}
check "$tmp/g.pm" 497550 5.14e-04 4.55e-04 3.42e-04
check "$tmp/c.pm" 988961 5.10e-05 4.55e-05 3.84e-05
