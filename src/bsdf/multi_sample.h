// RADIANCE's SDmultiSamp for two dimensions (bsdf.c): one uniform number to a point of
// the unit square along a Hilbert curve, so that a sample's position inside a Klems
// patch follows from the same random number that chose the patch. Deterministic runs
// (-ss 0: the number is .5) then pick the very direction RADIANCE picks.
#pragma once

#include <cstdint>

namespace rp::bsdf {

// t[0], t[1] in [0, 1) for x in [0, 1): the point at fraction x along the Hilbert curve
// of order 31 that RADIANCE's hilbert_i2c traces (it starts at (0, 0), runs first along
// t[0] and ends at (0, 1)).
inline void multiSample2(double x, double t[2]) {
    if (x < 0) x = 0;
    if (x >= 1) x = 0.999999999999999;
    constexpr int kOrder = 31;
    uint64_t d = static_cast<uint64_t>(x * static_cast<double>(uint64_t(1) << (2 * kOrder)));
    // The textbook index-to-point walk (quadrants entered rotated or reflected so that
    // each sub-curve starts where the last ended); RADIANCE's axes are its (y, x).
    uint64_t a = 0, b = 0;
    for (uint64_t s = 1; s < (uint64_t(1) << kOrder); s <<= 1) {
        const uint64_t ra = 1 & (d >> 1), rb = 1 & (d ^ ra);
        if (rb == 0) {
            if (ra == 1) {
                a = s - 1 - a;
                b = s - 1 - b;
            }
            const uint64_t tmp = a;
            a = b;
            b = tmp;
        }
        a += s * ra;
        b += s * rb;
        d >>= 2;
    }
    const double scale = 1.0 / static_cast<double>(uint64_t(1) << kOrder);
    t[0] = (static_cast<double>(b) + .5) * scale;
    t[1] = (static_cast<double>(a) + .5) * scale;
}

}  // namespace rp::bsdf
