// RADIANCE's 4-byte shared-exponent colour (COLR: RGBE, or XYZE in pictures), used by
// picture files (image/) and by stored photon flux (pmap/). One codec for both, so a
// photon's flux and a pixel round through exactly the same arithmetic as in RADIANCE.
#pragma once

#include <array>
#include <cstdint>

namespace rp {

// Three 8-bit mantissas and a shared exponent biased by 128.
using Colr = std::array<uint8_t, 4>;

// RADIANCE compat: setcolr() in color.c. The largest component d is split with frexp
// (d = m * 2^e, m in [0.5,1)); each component is scaled by m*256/d and truncated, so the
// largest mantissa is in [128,255]; the exponent byte is e+128. A maximum <= 1e-32 (or
// below the smallest exponent) gives (0,0,0,0); negative components become 0. Beyond
// RADIANCE, NaN counts as 0 and values too large for the exponent byte saturate to
// (255,255,255,255).
Colr toColr(double r, double g, double b);

namespace colr_detail {
// kExpScale[e] = 2^(e - 136) (COLXS + 8 mantissa bits), exact in double for every byte e
// (2^-136 .. 2^119 are normal doubles): built by repeated halving/doubling, which is exact.
// Replaces a std::ldexp call per decoded colour (photon flux is decoded ~10^7 times a run).
constexpr std::array<double, 256> makeExpScale() {
    std::array<double, 256> t{};
    double v = 1.0;
    for (int e = 136; e < 256; ++e, v *= 2) t[e] = v;
    v = 0.5;
    for (int e = 135; e >= 0; --e, v *= 0.5) t[e] = v;
    return t;
}
inline constexpr std::array<double, 256> kExpScale = makeExpScale();
}  // namespace colr_detail

// RADIANCE compat: colr_color() in color.c: (mantissa + 0.5) * 2^(exp - 136), i.e. the
// centre of the truncation interval; exponent byte 0 means black. Computed in double and
// rounded once to float, bit for bit what the ldexp formula gives (colr_test.cpp checks
// every exponent and mantissa).
inline std::array<float, 3> colrToRgb(const Colr& c) {
    if (c[3] == 0) return {0, 0, 0};
    const double f = colr_detail::kExpScale[c[3]];
    return {static_cast<float>((c[0] + 0.5) * f), static_cast<float>((c[1] + 0.5) * f),
            static_cast<float>((c[2] + 0.5) * f)};
}

}  // namespace rp
