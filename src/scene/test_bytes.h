// Test helper: builds RADIANCE portable binary data by hand (portio.c layout: big-endian
// integers, 5-byte reals, NUL-terminated strings) for the octree and mesh reader tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

namespace rp::testing {

struct PortableBytes {
    std::string s;
    PortableBytes& i(int64_t v, int size) {
        for (int k = size - 1; k >= 0; --k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
        return *this;
    }
    PortableBytes& str(const std::string& v) {
        s += v;
        s.push_back('\0');
        return *this;
    }
    // The inverse of the reader's real(), up to the last bit of the 31-bit mantissa.
    PortableBytes& real(double v) {
        if (v == 0) return i(0, 4).i(0, 1);
        int e;
        double d = std::frexp(v, &e);
        auto m = static_cast<int64_t>(std::llround(d * 0x7fffffff - (d < 0 ? -0.5 : 0.5)));
        return i(m, 4).i(e, 1);
    }
};

}  // namespace rp::testing
