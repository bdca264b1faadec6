#!/bin/bash
# Sensor points for scene.rad (rtrace -I input with a label first: cut -d' ' -f2- for
# rtrace). Label "t" is the signed distance from the nearest long edge of the lit
# rectangle in cm (> 0 inside), "in" marks interior points (the uniform region). Points
# run along x = 0.25 .. 0.55 (5 cm or more from the short edges at x = 0.2 and 0.6) on
# both edges y = +-0.1; the normal is the ceiling's, -z.
#   sensors.sh [DISTANCES_CM [STEP_M]]   defaults: "-4 -2 -1 -0.5 -0.25 0 0.25 0.5 1 2 4", 0.01
set -u
dists="${1:--4 -2 -1 -0.5 -0.25 0 0.25 0.5 1 2 4}"
step="${2:-0.01}"
awk -v dists="$dists" -v step="$step" 'BEGIN {
    n = split(dists, d, " ")
    for (x = 0.25; x < 0.55 + 1e-9; x += step)
        for (i = 1; i <= n; i++)
            for (s = -1; s <= 1; s += 2)
                printf "%s %.6f %.6f 0.4 0 0 -1\n", d[i], x, s * (0.1 - d[i] / 100)
    for (x = 0.25; x < 0.55 + 1e-9; x += step)
        for (y = -0.04; y < 0.04 + 1e-9; y += 0.02)
            printf "in %.6f %.6f 0.4 0 0 -1\n", x, y
}'
