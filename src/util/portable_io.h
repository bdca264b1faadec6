// RADIANCE's "portable" binary encodings (src/common/portio.c): big-endian integers of n
// bytes, floats as a 4-byte signed mantissa plus a 1-byte exponent, NUL-terminated strings.
// Used by photon map files (layout in pmap/photon_map_io.cpp), compiled meshes and binary
// scene records (scene/mesh_write.cpp, scene/radiance_objects_write.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace rp::portable {

constexpr int kPortableFloatSize = 5;  // bytes written by putFlt

// putint(v, n): the low n bytes of v, most significant first (n in 1..8).
void putInt(std::string& out, int64_t value, int size);

// putflt: m = (int32)(frexp(x, &e) * 0x7fffffff) truncated toward zero, then e as one signed
// byte. RADIANCE compat: exponents above 127 clamp to m = +-0x7fffffff, e = 127; below -128
// the value becomes 0 (m = 0, e = 0). Beyond RADIANCE (where this is undefined behaviour):
// NaN is written as 0 and +-infinity as the overflow clamp.
void putFlt(std::string& out, double value);

// The same encodings written to out[0..size) and out[0..kPortableFloatSize) (no string
// growth checks per byte: photon records are written by these).
void putInt(unsigned char* out, int64_t value, int size);
void putFlt(unsigned char* out, double value);

// putstr: the bytes of s followed by a NUL.
void putStr(std::string& out, std::string_view s);

// getint: `size` bytes MSB first, sign-extended from the top byte.
int64_t getInt(const unsigned char* in, int size);
// getint(in, 4), inline: photon records hold four of these (three in floats).
inline int32_t getInt32(const unsigned char* in) {
    uint32_t u;
    std::memcpy(&u, in, 4);
    return static_cast<int32_t>(__builtin_bswap32(u));
}

// getflt: ldexp((m + 0.5 - (m < 0)) / 0x7fffffff, e); m == 0 gives exactly 0 (the exponent
// byte is still consumed). Reads kPortableFloatSize bytes.
double getFlt(const unsigned char* in);

// Bounds-checked sequential decoder over a byte range. Reads past the end return 0 and set
// a sticky failure flag, so a caller checks ok() once after a block of reads.
class ByteReader {
public:
    ByteReader(const unsigned char* data, size_t size) : p_(data), end_(data + size) {}

    int64_t getInt(int size);
    double getFlt();
    // getstr: bytes up to a NUL (consumed, not returned). Fails if no NUL occurs within
    // maxLen bytes, so a foreign binary cannot make us scan or allocate without bound.
    std::string getStr(size_t maxLen);

    bool ok() const { return ok_; }
    size_t remaining() const { return static_cast<size_t>(end_ - p_); }

private:
    bool take(size_t n);
    const unsigned char* p_;
    const unsigned char* end_;
    bool ok_ = true;
};

}  // namespace rp::portable
