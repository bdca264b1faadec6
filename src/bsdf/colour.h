// Colour of BSDF data in RADIANCE RGB (its primaries, equal-energy white), from CIE XYZ
// (Klems CIE-X, visible Y, CIE-Z matrices) or from Y and CIE 1976 u' v' (tensor trees).
#pragma once

#include <array>

#include "util/color.h"
#include "util/spectrum.h"

namespace rp::bsdf {

inline Color rgbOfXyz(double X, double Y, double Z) {
    static const std::array<double, 9> m = spectral::rgbFromXyz(spectral::kStandardPrimaries);
    return {m[0] * X + m[1] * Y + m[2] * Z, m[3] * X + m[4] * Y + m[5] * Z,
            m[6] * X + m[7] * Y + m[8] * Z};
}

// u' v' to x y (CIE 1976 UCS), then XYZ of luminance Y.
inline Color rgbOfYuv(double Y, double u, double v) {
    const double d = 6 * u - 16 * v + 12;
    if (!(d > 0) || !(v > 0)) return Color::grey(Y);
    const double x = 9 * u / d, y = 4 * v / d;
    return rgbOfXyz(x / y * Y, Y, (1 - x - y) / y * Y);
}

}  // namespace rp::bsdf
