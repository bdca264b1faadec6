#include "util/rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rp {

TEST(Rng, StreamsAreValuesKeyedBySeedDomainIndex) {
    Rng a(7, RngDomain::Emission, 42), b(7, RngDomain::Emission, 42);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next(), b.next());
    Rng c(7, RngDomain::Scattering, 42), d(7, RngDomain::Emission, 43),
        e(8, RngDomain::Emission, 42);
    Rng f(7, RngDomain::Emission, 42);
    uint64_t x = f.next();
    EXPECT_NE(x, c.next());
    EXPECT_NE(x, d.next());
    EXPECT_NE(x, e.next());
}

TEST(Rng, UniformMeanAndVarianceWithinFourSigma) {
    Rng r(1, RngDomain::Test, 0);
    const int n = 1000000;
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
        double u = r.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        s += u;
        s2 += u * u;
    }
    double mean = s / n, var = s2 / n - mean * mean;
    // mean of U(0,1): 1/2, sd of the mean sqrt(1/12/n); variance 1/12.
    EXPECT_NEAR(mean, 0.5, 4 * std::sqrt(1.0 / 12 / n));
    EXPECT_NEAR(var, 1.0 / 12, 0.001);
}

TEST(Rng, BelowCoversRangeEvenly) {
    Rng r(3, RngDomain::Test, 5);
    int counts[10] = {};
    const int n = 100000;
    for (int i = 0; i < n; ++i) counts[r.below(10)]++;
    for (int c : counts) EXPECT_NEAR(c, n / 10, 4 * std::sqrt(n * 0.1 * 0.9));
}

}  // namespace rp
