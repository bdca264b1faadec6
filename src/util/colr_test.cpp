// The RGBE codec: the table-driven colrToRgb against RADIANCE's ldexp formula for every
// exponent and mantissa byte, and round trips through toColr.
#include "util/colr.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace rp {
namespace {

// colr_color() as color.c writes it, kept here as the reference for the table.
std::array<float, 3> colrToRgbLdexp(const Colr& c) {
    if (c[3] == 0) return {0, 0, 0};
    const double f = std::ldexp(1.0, static_cast<int>(c[3]) - (128 + 8));
    return {static_cast<float>((c[0] + 0.5) * f), static_cast<float>((c[1] + 0.5) * f),
            static_cast<float>((c[2] + 0.5) * f)};
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Colr, TableDecodeIsBitIdenticalForEveryExponentAndMantissa) {
    for (int e = 0; e < 256; ++e) {
        EXPECT_EQ(colr_detail::kExpScale[size_t(e)], std::ldexp(1.0, e - 136)) << e;
        for (int m = 0; m < 256; ++m) {
            const Colr c = {uint8_t(m), uint8_t(255 - m), uint8_t((m * 7) & 255), uint8_t(e)};
            const auto got = colrToRgb(c), want = colrToRgbLdexp(c);
            for (int k = 0; k < 3; ++k)
                ASSERT_TRUE(sameBits(got[k], want[k])) << "e=" << e << " m=" << m << " k=" << k;
        }
    }
}

TEST(Colr, KnownValues) {
    EXPECT_EQ(colrToRgb(Colr{0, 0, 0, 0}), (std::array<float, 3>{0, 0, 0}));
    EXPECT_EQ(colrToRgb(Colr{200, 0, 0, 0}), (std::array<float, 3>{0, 0, 0}));  // black
    // (128 + 0.5) * 2^(129 - 136) = 1.00390625
    EXPECT_EQ(colrToRgb(Colr{128, 64, 0, 129})[0], 1.00390625f);
    EXPECT_EQ(colrToRgb(Colr{128, 64, 0, 129})[1], 64.5f / 128);
    // Largest value, 255.5 * 2^119 (just under FLT_MAX), and the smallest non-zero one.
    EXPECT_EQ(colrToRgb(Colr{255, 0, 0, 255})[0], std::ldexp(255.5f, 119));
    EXPECT_EQ(colrToRgb(Colr{0, 0, 0, 1})[0], std::ldexp(0.5f, -135));
}

TEST(Colr, RoundTripKeepsMantissaInterval) {
    for (double v : {1e-20, 3.7e-6, 0.5, 1.0, 12345.678, 1e30}) {
        const Colr c = toColr(v, v / 2, v / 3);
        const auto rgb = colrToRgb(c);
        EXPECT_NEAR(rgb[0], v, v / 128) << v;
        EXPECT_EQ(toColr(rgb[0], rgb[1], rgb[2]), c) << v;
    }
}

}  // namespace
}  // namespace rp
