#!/bin/bash
# Irradiance on the plane z = 0 (normal +z) at the points "x y z ..." on standard input
# from scene.rad's panel (radiance 1, the rectangle x -1.2..1.2, y 0..1 at height 0.1):
# E = L sum over the panel's corners of +-G(a, b), with a, b the corner's offsets and
# G(a, b) = (1/2) [A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2)) + B / sqrt(1 + B^2)
# atan(A / sqrt(1 + B^2))], A = a / h, B = b / h (the parallel-rectangle view factor times
# pi; odd in a and in b, so signed offsets superpose).
awk 'function g(a, b,   A, B, p, q) {
         A = a / 0.1; B = b / 0.1; p = sqrt(1 + A * A); q = sqrt(1 + B * B)
         return 0.5 * (A / p * atan2(B, p) + B / q * atan2(A, q))
     }
     { x = $1; y = $2
       print g(1.2 - x, 1 - y) - g(-1.2 - x, 1 - y) - g(1.2 - x, -y) + g(-1.2 - x, -y) }'
