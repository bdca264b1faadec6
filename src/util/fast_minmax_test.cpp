#include "util/fast_minmax.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace rp {
namespace {

uint64_t bitsOf(double x) { return std::bit_cast<uint64_t>(x); }

// Same bits as std::fmin / std::fmax for every pair, NaN and infinities included; only a
// +0/-0 tie may differ (documented), so that pair is left out.
TEST(FastMinMax, SameBitsAsLibm) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> values = {
        0.0,   1.0,    -1.0, 2.5,  -2.5, 1e-300, -1e-300,     5e-324,
        1e300, -1e300, inf,  -inf, nan,  0.1,    0.1 + 1e-17, std::nextafter(1.0, 2.0)};
    for (double a : values)
        for (double b : values) {
            SCOPED_TRACE(testing::Message() << "a=" << a << " b=" << b);
            const double mn = fastMin(a, b), mx = fastMax(a, b);
            if (std::isnan(std::fmin(a, b))) {
                EXPECT_TRUE(std::isnan(mn));
                EXPECT_TRUE(std::isnan(mx));
                continue;
            }
            EXPECT_EQ(bitsOf(mn), bitsOf(std::fmin(a, b)));
            EXPECT_EQ(bitsOf(mx), bitsOf(std::fmax(a, b)));
        }
    // The one documented freedom: a +0/-0 tie gives a zero of either sign.
    EXPECT_EQ(fastMax(0.0, -0.0), 0.0);
    EXPECT_EQ(fastMin(-0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace rp
