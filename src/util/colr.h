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

// RADIANCE compat: colr_color() in color.c: (mantissa + 0.5) * 2^(exp - 136), i.e. the
// centre of the truncation interval; exponent byte 0 means black.
std::array<float, 3> colrToRgb(const Colr& c);

}  // namespace rp
