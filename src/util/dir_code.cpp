#include "util/dir_code.h"

#include <algorithm>
#include <cmath>

namespace rp {

namespace {
constexpr double kScale = 11584.5;  // ((1 << 13) - .5) * sqrt(2)
constexpr int32_t kFirstIsX = 010, kSecondIsZ = 020;
}  // namespace

int32_t encodeDirection(const std::array<double, 3>& dv) {
    int32_t dc = 0;
    int cd[3];
    for (int i = 0; i < 3; ++i) {
        if (dv[i] < 0.) {
            cd[i] = static_cast<int>(dv[i] * -kScale + .5);
            dc |= 1 << i;
        } else {
            cd[i] = static_cast<int>(dv[i] * kScale + .5);
        }
    }
    if (!(cd[0] | cd[1] | cd[2])) return 0;
    // The smaller of x and y goes in the first field, the smaller of z and the other in
    // the second; the largest component is implied.
    int cm;
    if (cd[0] <= cd[1]) {
        dc |= kFirstIsX | cd[0] << 5;
        cm = cd[1];
    } else {
        dc |= cd[1] << 5;
        cm = cd[0];
    }
    if (cd[2] <= cm)
        dc |= kSecondIsZ | cd[2] << 18;
    else
        dc |= cm << 18;
    return dc ? dc : kFirstIsX;  // 0 means the zero vector
}

std::array<double, 3> decodeDirection(int32_t code) {
    if (code == 0) return {0, 0, 0};
    const uint32_t c = static_cast<uint32_t>(code);
    const double a = ((c >> 5) & 0x1fff) / kScale;
    const double b = ((c >> 18) & 0x1fff) / kScale;
    const double rest = std::sqrt(std::max(0.0, 1.0 - a * a - b * b));
    const bool firstIsX = c & kFirstIsX, secondIsZ = c & kSecondIsZ;
    std::array<double, 3> d;
    d[firstIsX ? 0 : 1] = a;
    d[firstIsX ? 1 : 0] = secondIsZ ? rest : b;
    d[2] = secondIsZ ? b : rest;
    for (int i = 0; i < 3; ++i)
        if (c & (1u << i)) d[size_t(i)] = -d[size_t(i)];
    return d;
}

}  // namespace rp
