// frexpFast against std::frexp: the same fraction bits and exponent for normal numbers of
// every exponent and sign, and for zeros, subnormals, infinities and NaN.
#include "util/fast_frexp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace rp {
namespace {

void expectSameAsStd(double x) {
    int e1 = 12345, e2 = 12345;
    const double f1 = frexpFast(x, e1), f2 = std::frexp(x, &e2);
    if (std::isnan(x)) {
        EXPECT_TRUE(std::isnan(f1));
        return;
    }
    EXPECT_EQ(std::memcmp(&f1, &f2, sizeof f1), 0) << x;
    if (std::isfinite(x)) {  // the exponent is unspecified for infinities
        EXPECT_EQ(e1, e2) << x;
    }
}

TEST(FastFrexp, MatchesStdFrexpBitForBit) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> mant(1.0, 2.0);
    for (int e = -1074; e <= 1023; ++e)
        for (int k = 0; k < 4; ++k) {
            const double x = std::ldexp(mant(rng), e);
            expectSameAsStd(x);
            expectSameAsStd(-x);
        }
    for (double x :
         {0.0, -0.0, std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
          std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), 0.5,
          1.0, 3e-32, 1e32})
        expectSameAsStd(x);
}

}  // namespace
}  // namespace rp
