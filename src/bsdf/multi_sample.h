// RADIANCE's SDmultiSamp for two dimensions (bsdf.c): one uniform number to a point of
// the unit square along a Hilbert curve, so that a sample's position inside a Klems
// patch follows from the same random number that chose the patch. Deterministic runs
// (-ss 0: the number is .5) then pick the very direction RADIANCE picks.
#pragma once

#include <cstdint>

namespace rp::bsdf {

// The point (x, y) at index d along the Hilbert curve on a 2^order x 2^order grid: the
// textbook index-to-point walk (quadrants entered rotated or reflected so that each
// sub-curve starts where the last ended). It starts at (0, 0), runs first along y and
// ends at (2^order - 1, 0).
inline void hilbertPoint(int order, uint64_t d, uint64_t& x, uint64_t& y) {
    x = y = 0;
    for (uint64_t s = 1; s < (uint64_t(1) << order); s <<= 1) {
        const uint64_t rx = 1 & (d >> 1), ry = 1 & (d ^ rx);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            const uint64_t t = x;
            x = y;
            y = t;
        }
        x += s * rx;
        y += s * ry;
        d >>= 2;
    }
}

// t[0], t[1] in [0, 1) for x in [0, 1): the point at fraction x along the Hilbert curve
// of order 31 that RADIANCE's hilbert_i2c traces (its axes are hilbertPoint's (y, x)).
inline void multiSample2(double x, double t[2]) {
    if (x < 0) x = 0;
    if (x >= 1) x = 0.999999999999999;
    constexpr int kOrder = 31;
    const auto d = static_cast<uint64_t>(x * static_cast<double>(uint64_t(1) << (2 * kOrder)));
    uint64_t a, b;
    hilbertPoint(kOrder, d, a, b);
    const double scale = 1.0 / static_cast<double>(uint64_t(1) << kOrder);
    t[0] = (static_cast<double>(b) + .5) * scale;
    t[1] = (static_cast<double>(a) + .5) * scale;
}

}  // namespace rp::bsdf
