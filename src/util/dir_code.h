// RADIANCE's 4-byte direction code (common/dircode.c), used by compiled meshes (vertex
// normals) and contribution photon maps with primary directions: sign bits for x, y, z
// (bits 0-2), two 13-bit components (bits 5-17 and 18-30, in units of 1/11584.5) whose
// axes bits 3 and 4 choose, the third component making the vector unit length. Mean
// error 0.0022 degrees. Code 0 is the zero vector.
#pragma once

#include <array>
#include <cstdint>

namespace rp {

int32_t encodeDirection(const std::array<double, 3>& unit);
std::array<double, 3> decodeDirection(int32_t code);

}  // namespace rp
