#include "util/dir_code.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace rp {
namespace {

TEST(DirCode, RoundTripWithinRadiancesAccuracy) {
    // dircode.c: maximum error 0.0058 degrees.
    std::mt19937 gen(7);
    std::normal_distribution<double> n;
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        std::array<double, 3> v{n(gen), n(gen), n(gen)};
        const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (double& c : v) c /= len;
        const std::array<double, 3> d = decodeDirection(encodeDirection(v));
        const double cosine = v[0] * d[0] + v[1] * d[1] + v[2] * d[2];
        worst = std::max(worst, std::acos(std::min(1.0, cosine)) * 180 / M_PI);
    }
    EXPECT_LT(worst, 0.0058);
    EXPECT_GT(worst, 0.001);  // it is a lossy code
}

TEST(DirCode, AxesAndZero) {
    EXPECT_EQ(encodeDirection({0, 0, 0}), 0);
    EXPECT_EQ(decodeDirection(0), (std::array<double, 3>{0, 0, 0}));
    for (const std::array<double, 3>& v :
         {std::array<double, 3>{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}) {
        const auto d = decodeDirection(encodeDirection(v));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(d[size_t(k)], v[size_t(k)], 1e-12);
    }
}

}  // namespace
}  // namespace rp
