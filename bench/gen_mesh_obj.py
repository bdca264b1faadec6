#!/usr/bin/env python3
"""Write a wavy heightfield OBJ for the mesh benchmarks (bench/mesh_scenes.sh).

Usage: gen_mesh_obj.py N SIZE OUT.obj
  N x N vertices over SIZE x SIZE m centred on the origin, z = 0.1*sin(x)*cos(y),
  with per-vertex `vn` normals and material `wavy`; 2*(N-1)^2 triangles (N=2237 -> ~10 M, N=224 -> ~100 k).
"""
import math
import sys


def main():
    n = int(sys.argv[1])
    size = float(sys.argv[2])
    out = sys.argv[3]
    h = size / (n - 1)
    xs = [-0.5 * size + i * h for i in range(n)]
    sx = [math.sin(x) for x in xs]
    cx = [math.cos(x) for x in xs]
    with open(out, "w", buffering=1 << 22) as f:
        f.write("# wavy heightfield %dx%d, %d triangles\n" % (n, n, 2 * (n - 1) ** 2))
        f.write("o grid\nusemtl wavy\n")
        for j in range(n):            # v: rows of constant y
            y = xs[j]
            sy, cy = sx[j], cx[j]
            f.write("".join("v %.5f %.5f %.6f\n" % (xs[i], y, 0.1 * sx[i] * cy)
                            for i in range(n)))
        for j in range(n):            # vn: normal of z = 0.1 sin x cos y
            sy, cy = sx[j], cx[j]
            rows = []
            for i in range(n):
                dx = -0.1 * cx[i] * cy
                dy = 0.1 * sx[i] * sy
                inv = 1.0 / math.sqrt(dx * dx + dy * dy + 1.0)
                rows.append("vn %.5f %.5f %.5f\n" % (dx * inv, dy * inv, inv))
            f.write("".join(rows))
        for j in range(n - 1):        # two counter-clockwise triangles per cell (+z up)
            rows = []
            base = j * n + 1
            for i in range(n - 1):
                a = base + i
                b = a + 1
                c = a + n
                d = c + 1
                rows.append("f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n"
                            % (a, a, b, b, d, d, a, a, d, d, c, c))
            f.write("".join(rows))


if __name__ == "__main__":
    main()
