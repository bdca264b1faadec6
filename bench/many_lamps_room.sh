#!/usr/bin/env bash
# Writes the many-source room of bench/rcontrib_bench.sh and bench/mpi_scaling.sh into the
# current folder: room.rad (20 x 10 x 3 m, 100 small sphere lamps, each its own modifier),
# mods.txt (the lamp modifiers) and sensors.txt (1,000 work-plane sensors at 0.8 m, up).
set -euo pipefail
awk 'BEGIN {
    print "void plastic wall 0 0 5 .6 .6 .6 0 0"
    print "void plastic floor 0 0 5 .3 .3 .3 0 0"
    print "floor polygon f 0 0 12  0 0 0  0 10 0  20 10 0  20 0 0"
    print "wall polygon c 0 0 12  0 0 3  20 0 3  20 10 3  0 10 3"
    print "wall polygon w1 0 0 12  0 0 0  20 0 0  20 0 3  0 0 3"
    print "wall polygon w2 0 0 12  0 10 0  0 10 3  20 10 3  20 10 0"
    print "wall polygon w3 0 0 12  0 0 0  0 0 3  0 10 3  0 10 0"
    print "wall polygon w4 0 0 12  20 0 0  20 10 0  20 10 3  20 0 3"
    for (i = 0; i < 100; i++) {
        x = 1 + 2 * (i % 10); y = 0.5 + int(i / 10)
        printf "void light lamp%02d 0 0 3 %g %g %g\n", i, 50 + i, 80, 130 - i
        printf "lamp%02d sphere bulb%02d 0 0 4 %g %g 2.8 0.05\n", i, i, x, y
        printf "lamp%02d\n", i > "mods.txt"
    }
}' > room.rad
awk 'BEGIN { for (i = 0; i < 40; i++) for (j = 0; j < 25; j++)
    printf "%g %g 0.8 0 0 1\n", 0.25 + 0.5 * i, 0.2 + 0.4 * j }' > sensors.txt
