// RADIANCE portable binary encodings (see portable_io.h for the contracts).
#include "util/portable_io.h"

#include <array>
#include <cmath>
#include <cstring>

#include "util/fast_frexp.h"

namespace rp::portable {

namespace {
constexpr double kMantissaScale = 0x7fffffff;

// kPow2[e + 128] = 2^e for the exponent byte's range -128..127, exact (built by doubling
// and halving). d * 2^e is exact for getFlt's |d| in [2^-31, 2] (far from double underflow
// or overflow), so multiplying by the table equals std::ldexp bit for bit (checked on 5 M
// random encodings, every exponent byte) and is several times faster: a map load decodes
// three floats per photon.
constexpr std::array<double, 256> makePow2() {
    std::array<double, 256> t{};
    double v = 1.0;
    for (int e = 0; e < 128; ++e, v *= 2) t[size_t(e + 128)] = v;
    v = 0.5;
    for (int e = -1; e >= -128; --e, v *= 0.5) t[size_t(e + 128)] = v;
    return t;
}
constexpr std::array<double, 256> kPow2 = makePow2();
}  // namespace

void putInt(std::string& out, int64_t value, int size) {
    const uint64_t u = static_cast<uint64_t>(value);
    while (size--) out.push_back(static_cast<char>((u >> (size * 8)) & 0xff));
}

void putInt(unsigned char* out, int64_t value, int size) {
    const uint64_t u = static_cast<uint64_t>(value);
    for (int i = 0; i < size; ++i) out[i] = static_cast<unsigned char>(u >> ((size - 1 - i) * 8));
}

void putFlt(std::string& out, double value) {
    unsigned char b[kPortableFloatSize];
    putFlt(b, value);
    out.append(reinterpret_cast<const char*>(b), kPortableFloatSize);
}

void putFlt(unsigned char* out, double value) {
    int64_t m = 0;
    int e = 0;
    if (std::isnan(value)) {
        // m = 0, e = 0
    } else if (std::isinf(value)) {
        m = value > 0 ? 0x7fffffff : -0x7fffffff;
        e = 127;
    } else {
        // std::frexp, inline for normal numbers (every float position is one, or zero),
        // which was a visible part of writing a map (three calls per photon). The C
        // conversion (long)(double) truncates toward zero; static_cast does the same.
        m = static_cast<int64_t>(frexpFast(value, e) * kMantissaScale);
        if (e > 127) {
            m = m > 0 ? 0x7fffffff : -0x7fffffff;
            e = 127;
        } else if (e < -128) {
            m = 0;
            e = 0;
        }
    }
    putInt(out, m, 4);
    putInt(out + 4, e, 1);
}

void putStr(std::string& out, std::string_view s) {
    out.append(s.data(), s.size());
    out.push_back('\0');
}

int64_t getInt(const unsigned char* in, int size) {
    uint64_t u = 0;
    for (int i = 0; i < size; ++i) u = (u << 8) | in[i];
    const int bits = size * 8;
    if (bits < 64 && (u >> (bits - 1)) & 1) u |= ~uint64_t{0} << bits;  // sign extend
    return static_cast<int64_t>(u);
}

double getFlt(const unsigned char* in) {
    const int32_t m = getInt32(in);
    if (m == 0) return 0.0;
    const int e = static_cast<int8_t>(in[4]);
    const double d = (static_cast<double>(m) + (m > 0 ? 0.5 : -0.5)) / kMantissaScale;
    return d * kPow2[size_t(e + 128)];
}

bool ByteReader::take(size_t n) {
    if (!ok_ || remaining() < n) {
        ok_ = false;
        p_ = end_;
        return false;
    }
    return true;
}

int64_t ByteReader::getInt(int size) {
    if (!take(size)) return 0;
    int64_t v = portable::getInt(p_, size);
    p_ += size;
    return v;
}

double ByteReader::getFlt() {
    if (!take(kPortableFloatSize)) return 0;
    double v = portable::getFlt(p_);
    p_ += kPortableFloatSize;
    return v;
}

std::string ByteReader::getStr(size_t maxLen) {
    std::string s;
    for (size_t i = 0; ok_ && p_ < end_ && i < maxLen; ++i) {
        unsigned char c = *p_++;
        if (c == 0) return s;
        s.push_back(static_cast<char>(c));
    }
    ok_ = false;
    return s;
}

}  // namespace rp::portable
