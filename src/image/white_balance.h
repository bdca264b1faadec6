// RADIANCE's conversion from CIE XYZ to the RGB of other primaries with a white balance
// (color.c compxyz2rgbWBmat): von Kries in its sharpened cone space, from its equal-energy
// white to the primaries' white. Used by pcond -p and rtrace/rpict -pc.
#pragma once

#include <array>

namespace rp {

// Row-major, in single precision as RADIANCE's COLORMAT; primaries rx ry gx gy bx by wx wy.
std::array<float, 9> xyzToRgbWhiteBalanced(const std::array<float, 8>& primaries);

}  // namespace rp
