// RADIANCE's portable binary output (common/portio.c): big-endian integers of a given
// width, NUL-terminated strings, and reals as a 31-bit mantissa plus a 1-byte
// exponent. Used by the writers of compiled meshes and binary scene records.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace rp::portable {

// The low `bytes` bytes of v, most significant first (negative values sign-extend).
inline void putInt(std::string& out, int64_t v, int bytes) {
    for (int shift = 8 * (bytes - 1); shift >= 0; shift -= 8)
        out.push_back(static_cast<char>((v >> shift) & 0xff));
}

inline void putStr(std::string& out, std::string_view s) {
    out.append(s);
    out.push_back('\0');
}

// frexp's mantissa scaled to 31 bits (truncated toward zero), then the exponent;
// exponents past 127 saturate, below -128 the value is written as zero.
inline void putFlt(std::string& out, double f) {
    int e = 0;
    int64_t m = static_cast<int64_t>(std::frexp(f, &e) * 0x7fffffff);
    if (e > 127) {
        m = m > 0 ? 0x7fffffff : -0x7fffffff;
        e = 127;
    } else if (e < -128) {
        m = 0;
        e = 0;
    }
    putInt(out, m, 4);
    putInt(out, e, 1);
}

}  // namespace rp::portable
