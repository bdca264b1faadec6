// RADIANCE's noise functions re-derived from their definitions: noise3 is Perlin's 2002
// improved noise with his reference permutation; noise3x/y/z are backward differences of
// it; fnoise3 is RADIANCE's own midpoint-displacement fractal. Patterns that use them
// (patterns.mat in RADIANCE's test scenes) are only comparable with RADIANCE's pictures
// if every value agrees, so the lattice, hash and step sizes below are RADIANCE's.
#include "calc/noise.h"

#include <cmath>
#include <cstdint>

namespace rp::calc {
namespace {

// Perlin's reference permutation of 0..255 (Perlin 2002, and his ImprovedNoise.java).
constexpr std::uint8_t kPerm[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

int perm(int i) { return kPerm[i & 0xff]; }

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double lerp(double t, double a, double b) { return a + t * (b - a); }

// Dot product of (x, y, z) with one of the 12 cube-edge directions chosen by the hash's
// low four bits (Perlin 2002, section 3; four of the 16 codes repeat directions).
double gradDot(int hash, double x, double y, double z) {
    int h = hash & 15;
    double u = h < 8 ? x : y;
    double v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// RADIANCE compat: the cell index is truncation minus one for negative coordinates, so a
// negative integer coordinate sits at the top of the cell below (floor would differ there).
int cellOf(double x) { return static_cast<int>(x) - (x < 0 ? 1 : 0); }

// RADIANCE's step for fnoise3's lattice and for the noise3 partials.
constexpr double kStep = 0.0005;
constexpr std::int64_t kLatticePerUnit = 2000;  // 1 / kStep

// RADIANCE's integer hash of a lattice point to (-1, 1]: a polynomial in the mixed seed,
// low 31 bits. Unsigned arithmetic wraps as RADIANCE's 64-bit `long` does in practice.
double latticeRandom(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
    auto s = static_cast<std::uint64_t>(17 * ix + 23 * iy + 29 * iz);
    s = (s << 13) ^ s;
    std::uint64_t r = (s * (s * s * 15731u + 789221u) + 1376312589u) & 0x7fffffffu;
    return 1.0 - static_cast<double>(r) / 1073741824.0;
}

}  // namespace

double noise3(double x, double y, double z) {
    int cx = cellOf(x), cy = cellOf(y), cz = cellOf(z);
    x -= cx;
    y -= cy;
    z -= cz;
    cx &= 0xff;
    cy &= 0xff;
    cz &= 0xff;
    double u = fade(x), v = fade(y), w = fade(z);
    // Hash each corner through the permutation, one axis at a time (Perlin's scheme).
    int a = perm(cx) + cy, aa = perm(a) + cz, ab = perm(a + 1) + cz;
    int b = perm(cx + 1) + cy, ba = perm(b) + cz, bb = perm(b + 1) + cz;
    double z0 = lerp(v, lerp(u, gradDot(perm(aa), x, y, z), gradDot(perm(ba), x - 1, y, z)),
                     lerp(u, gradDot(perm(ab), x, y - 1, z), gradDot(perm(bb), x - 1, y - 1, z)));
    double z1 =
        lerp(v, lerp(u, gradDot(perm(aa + 1), x, y, z - 1), gradDot(perm(ba + 1), x - 1, y, z - 1)),
             lerp(u, gradDot(perm(ab + 1), x, y - 1, z - 1),
                  gradDot(perm(bb + 1), x - 1, y - 1, z - 1)));
    return lerp(w, z0, z1);
}

double noise3Partial(double x, double y, double z, int axis) {
    double p[3] = {x, y, z};
    p[axis] -= kStep;
    return (noise3(x, y, z) - noise3(p[0], p[1], p[2])) / kStep;
}

double fnoise3(double x, double y, double z) {
    // Start from the unit cell holding the point, in lattice units; every corner gets a
    // random value. Each level halves the cell (integer halving, so 125 -> 62 -> 31: the
    // cells stop tiling exactly, as in RADIANCE), keeps the half holding the point, and
    // gives each new corner the mean of the old corners it lies between plus a random
    // displacement proportional to the new size. The answer is the mean of the corners of
    // the last cell.
    const double p[3] = {x, y, z};
    std::int64_t target[3], lo[3];
    std::int64_t size = kLatticePerUnit;
    for (int i = 0; i < 3; ++i) {
        target[i] = static_cast<std::int64_t>(static_cast<double>(size) * p[i]);
        lo[i] = static_cast<std::int64_t>(static_cast<double>(size) * std::floor(p[i]));
    }
    double corner[8];
    for (int c = 0; c < 8; ++c)
        corner[c] = latticeRandom(lo[0] + ((c & 1) ? size : 0), lo[1] + ((c & 2) ? size : 0),
                                  lo[2] + ((c & 4) ? size : 0));
    for (;;) {
        double mean = 0;
        for (double v : corner) mean += v;
        mean *= 0.125;
        size >>= 1;
        if (size == 0) return mean;
        int side = 0;  // bit i: the point is in the upper half along axis i
        for (int i = 0; i < 3; ++i)
            if (target[i] > lo[i] + size) side |= 1 << i;
        double next[8];
        for (int c = 0; c < 8; ++c) {
            int mid = (c ^ side) & 7;  // axes on which new corner c sits at the midpoint
            if (mid == 0) {
                next[c] = corner[side];
                continue;
            }
            // Mean of the old corners that agree with `side` off the midpoint axes.
            double sum = 0;
            int n = 0;
            for (int o = 0; o < 8; ++o)
                if (((o ^ side) & ~mid & 7) == 0) {
                    sum += corner[o];
                    ++n;
                }
            std::int64_t at[3];
            for (int i = 0; i < 3; ++i) {
                at[i] = lo[i] + size;
                if (!(mid & (1 << i))) at[i] += (side & (1 << i)) ? size : -size;
            }
            next[c] =
                sum / n + static_cast<double>(size) * kStep * latticeRandom(at[0], at[1], at[2]);
        }
        for (int c = 0; c < 8; ++c) corner[c] = next[c];
        for (int i = 0; i < 3; ++i)
            if (side & (1 << i)) lo[i] += size;
    }
}

}  // namespace rp::calc
