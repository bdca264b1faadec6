// Portable I/O against bytes worked out by hand from portio.c's definitions.
#include "util/portable_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace rp::portable {
namespace {

std::vector<int> bytes(const std::string& s) {
    std::vector<int> v;
    for (char c : s) v.push_back(static_cast<unsigned char>(c));
    return v;
}

std::vector<int> flt(double x) {
    std::string s;
    putFlt(s, x);
    return bytes(s);
}

double decode(const std::vector<int>& b) {
    unsigned char raw[5];
    for (int i = 0; i < 5; ++i) raw[i] = static_cast<unsigned char>(b[i]);
    return getFlt(raw);
}

TEST(PortableIo, PutIntIsMsbFirst) {
    std::string s;
    putInt(s, 0x01020304, 4);
    putInt(s, -2, 2);
    putInt(s, 51763, 8);
    EXPECT_EQ(bytes(s), (std::vector<int>{1, 2, 3, 4, 0xff, 0xfe, 0, 0, 0, 0, 0, 0, 0xca, 0x33}));
}

TEST(PortableIo, GetIntSignExtends) {
    const unsigned char b[] = {0xff, 0xfe, 0x7f, 0x80};
    EXPECT_EQ(getInt(b, 2), -2);
    EXPECT_EQ(getInt(b + 2, 1), 127);
    EXPECT_EQ(getInt(b + 3, 1), -128);
    EXPECT_EQ(getInt(b + 2, 2), 0x7f80);
    const unsigned char big[] = {0x80, 0, 0, 0, 0, 0, 0, 1};
    EXPECT_EQ(getInt(big, 8), INT64_MIN + 1);
}

// Hand derivations: frexp(x) = f * 2^e with f in [0.5, 1); m = trunc(f * 2147483647).
TEST(PortableIo, PutFltExactBytes) {
    // 0: frexp gives f = 0, e = 0.
    EXPECT_EQ(flt(0.0), (std::vector<int>{0, 0, 0, 0, 0}));
    // 1 = 0.5 * 2^1: 0.5 * 2147483647 = 1073741823.5 -> 1073741823 = 0x3fffffff, e = 1.
    EXPECT_EQ(flt(1.0), (std::vector<int>{0x3f, 0xff, 0xff, 0xff, 0x01}));
    // -1: m = -1073741823 = 0xc0000001 (two's complement), e = 1.
    EXPECT_EQ(flt(-1.0), (std::vector<int>{0xc0, 0x00, 0x00, 0x01, 0x01}));
    // 0.5 = 0.5 * 2^0: same mantissa as 1, e = 0.
    EXPECT_EQ(flt(0.5), (std::vector<int>{0x3f, 0xff, 0xff, 0xff, 0x00}));
    // 1e-30 = 0.6338253001141147 * 2^-99: * 2147483647 = 1361129467.05 -> 0x51212ffb,
    // e = -99 = 0x9d.
    EXPECT_EQ(flt(1e-30), (std::vector<int>{0x51, 0x21, 0x2f, 0xfb, 0x9d}));
    // 3.14159 = 0.7853975 * 2^2: * 2147483647 = 1686628287.7 -> 0x6487e7bf, e = 2.
    EXPECT_EQ(flt(3.14159), (std::vector<int>{0x64, 0x87, 0xe7, 0xbf, 0x02}));
    // -3.14159: -1686628287 = 0x9b781841.
    EXPECT_EQ(flt(-3.14159), (std::vector<int>{0x9b, 0x78, 0x18, 0x41, 0x02}));
}

TEST(PortableIo, PutFltFastPathMatchesFrexpDefinition) {
    // putFlt's bit-level frexp against the definition written with std::frexp, over
    // random doubles of every exponent, float positions, zeros, subnormals and specials.
    auto reference = [](double x) {
        int64_t m = 0;
        int e = 0;
        if (std::isinf(x)) {
            m = x > 0 ? 0x7fffffff : -0x7fffffff;
            e = 127;
        } else if (!std::isnan(x)) {
            m = static_cast<int64_t>(std::frexp(x, &e) * double(0x7fffffff));
            if (e > 127) {
                m = m > 0 ? 0x7fffffff : -0x7fffffff;
                e = 127;
            } else if (e < -128) {
                m = 0;
                e = 0;
            }
        }
        std::string s;
        putInt(s, m, 4);
        putInt(s, e, 1);
        return s;
    };
    std::mt19937_64 gen(7);
    std::vector<double> xs = {0.0,          -0.0,     1.0,       -1.0,     0.5,      5.5,
                              1e-300,       4.9e-324, -2.2e-308, 1e300,    HUGE_VAL, -HUGE_VAL,
                              std::nan(""), 0x1p127,  0x1p-128,  0x1p-129, -0x1p128};
    for (int i = 0; i < 200000; ++i) {
        uint64_t bits = gen();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        xs.push_back(d);
        xs.push_back(double(float(std::ldexp(double(gen() >> 11), -50))));  // positions
    }
    for (double x : xs) {
        std::string viaString;
        putFlt(viaString, x);
        unsigned char direct[kPortableFloatSize];
        putFlt(direct, x);
        const std::string expect = reference(x);
        ASSERT_EQ(viaString, expect) << x;
        ASSERT_EQ(std::string(reinterpret_cast<const char*>(direct), kPortableFloatSize), expect)
            << x;
    }
}

TEST(PortableIo, PutFltClampsExponent) {
    // 2^200 = 0.5 * 2^201: overflow -> m = 0x7fffffff, e = 127.
    EXPECT_EQ(flt(std::ldexp(1.0, 200)), (std::vector<int>{0x7f, 0xff, 0xff, 0xff, 0x7f}));
    EXPECT_EQ(flt(-std::ldexp(1.0, 200)), (std::vector<int>{0x80, 0x00, 0x00, 0x01, 0x7f}));
    // 2^-200: underflow -> exactly zero.
    EXPECT_EQ(flt(std::ldexp(1.0, -200)), (std::vector<int>{0, 0, 0, 0, 0}));
    // Not defined in C; we write NaN as 0 and infinity as the overflow clamp.
    EXPECT_EQ(flt(NAN), (std::vector<int>{0, 0, 0, 0, 0}));
    EXPECT_EQ(flt(INFINITY), (std::vector<int>{0x7f, 0xff, 0xff, 0xff, 0x7f}));
}

TEST(PortableIo, GetFltDecodesHandValues) {
    // (1073741823 + 0.5) / 2147483647 = 0.5 exactly, times 2^1.
    EXPECT_EQ(decode({0x3f, 0xff, 0xff, 0xff, 0x01}), 1.0);
    // Negative mantissas take -0.5: (-1073741823 - 0.5) / 2147483647 = -0.5.
    EXPECT_EQ(decode({0xc0, 0x00, 0x00, 0x01, 0x01}), -1.0);
    EXPECT_EQ(decode({0x3f, 0xff, 0xff, 0xff, 0x00}), 0.5);
    // m == 0 is exactly 0 whatever the exponent byte says.
    EXPECT_EQ(decode({0, 0, 0, 0, 0x42}), 0.0);
    EXPECT_NEAR(decode({0x64, 0x87, 0xe7, 0xbf, 0x02}), 3.14159, 3.14159 * 1e-9);
    EXPECT_NEAR(decode({0x51, 0x21, 0x2f, 0xfb, 0x9d}), 1e-30, 1e-30 * 1e-9);
}

TEST(PortableIo, FloatsSurviveRoundTripExactly) {
    // Photon positions are floats: 24-bit mantissas fit the 31-bit portable mantissa, so
    // decoding and rounding to float must give back the same float.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1000.0f, 1000.0f);
    for (int i = 0; i < 100000; ++i) {
        float f = u(rng) * std::ldexp(1.0f, static_cast<int>(rng() % 60) - 30);
        std::string s;
        putFlt(s, f);
        ASSERT_EQ(static_cast<float>(getFlt(reinterpret_cast<const unsigned char*>(s.data()))), f)
            << f;
    }
}

TEST(PortableIo, EncodingsSurviveDecodeEncode) {
    // Any encoding putflt can produce decodes to a double that encodes back to the same bytes,
    // so maps we read are written back byte for byte (header doubles included).
    std::mt19937 rng(11);
    for (int i = 0; i < 100000; ++i) {
        int64_t m = (int64_t{1} << 30) - 1 + static_cast<int64_t>(rng() % ((1u << 30) - 1));
        if (rng() & 1) m = -m;
        int e = static_cast<int>(rng() % 256) - 128;
        std::string in;
        putInt(in, m, 4);
        putInt(in, e, 1);
        std::string out;
        putFlt(out, getFlt(reinterpret_cast<const unsigned char*>(in.data())));
        ASSERT_EQ(bytes(out), bytes(in)) << m << " " << e;
    }
}

TEST(PortableIo, PutStrAndByteReader) {
    std::string s;
    putStr(s, "3.1k");
    EXPECT_EQ(bytes(s), (std::vector<int>{'3', '.', '1', 'k', 0}));
    putInt(s, 300, 2);
    putFlt(s, 1.0);
    ByteReader r(reinterpret_cast<const unsigned char*>(s.data()), s.size());
    EXPECT_EQ(r.getStr(16), "3.1k");
    EXPECT_EQ(r.getInt(2), 300);
    EXPECT_EQ(r.getFlt(), 1.0);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.remaining(), 0u);
    EXPECT_EQ(r.getInt(1), 0);  // past the end
    EXPECT_FALSE(r.ok());

    const std::string noNul = "abcdefgh";
    ByteReader r2(reinterpret_cast<const unsigned char*>(noNul.data()), noNul.size());
    r2.getStr(4);
    EXPECT_FALSE(r2.ok());
}

}  // namespace
}  // namespace rp::portable
