// The Henyey-Greenstein phase function: normalised, and sampled with its own density.
#include "util/henyey_greenstein.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rp {
namespace {

// Integral of p / (4 pi) over the sphere, by the midpoint rule in cos theta.
double sphereIntegral(double g) {
    const int n = 200000;
    double s = 0;
    for (int i = 0; i < n; ++i) s += henyeyGreenstein4Pi(g, -1 + (i + 0.5) * 2.0 / n);
    return s * (2.0 / n) * 2 * kPi / (4 * kPi);
}

TEST(HenyeyGreenstein, NormalisedAndIsotropicAtOrBelowZero) {
    for (double g : {0.0, 0.3, 0.8, 0.95}) EXPECT_NEAR(sphereIntegral(g), 1.0, 1e-4) << g;
    EXPECT_DOUBLE_EQ(henyeyGreenstein4Pi(0, 0.3), 1);
    // RADIANCE compat: a negative eccentricity is isotropic.
    EXPECT_DOUBLE_EQ(henyeyGreenstein4Pi(-0.5, 1), 1);
    // Forward peak (1 + g) / (1 - g)^2, backward (1 - g) / (1 + g)^2.
    EXPECT_NEAR(henyeyGreenstein4Pi(0.5, 1), 6, 1e-12);
    EXPECT_NEAR(henyeyGreenstein4Pi(0.5, -1), 0.5 / 2.25, 1e-12);
}

// Samples about an oblique axis: unit length, mean cosine g (the HG mean; standard error
// of 200 k samples < 0.0013, so 0.006 is ~5 sigma), and the cosine histogram against the
// density's integral over each of 20 bins (chi-square, 19 dof: 99.9th percentile 43.8).
TEST(HenyeyGreenstein, SamplesFollowTheDensity) {
    const Vec3 axis = normalize(Vec3(0.3, -0.5, 0.8));
    for (double g : {0.0, 0.4, 0.85, -0.3}) {
        Rng rng(7, RngDomain::Test, uint64_t(100 * (g + 1)));
        const int n = 200000, bins = 20;
        std::vector<int> hist(bins, 0);
        double mean = 0;
        for (int i = 0; i < n; ++i) {
            Vec3 d = sampleHenyeyGreenstein(axis, g, rng);
            ASSERT_NEAR(length(d), 1, 1e-9);
            const double c = dot(d, axis);
            mean += c;
            ++hist[std::min(bins - 1, int((c + 1) / 2 * bins))];
        }
        EXPECT_NEAR(mean / n, isotropicPhase(g) ? 0 : g, 0.006) << g;
        double chi2 = 0;
        for (int b = 0; b < bins; ++b) {
            // Integral of p/(4 pi) * 2 pi over the bin's cosines, by the midpoint rule.
            double p = 0;
            const int m = 2000;
            for (int k = 0; k < m; ++k) {
                const double c = -1 + (b + (k + 0.5) / m) * 2.0 / bins;
                p += henyeyGreenstein4Pi(g, c) / 2 * (2.0 / bins) / m;
            }
            const double expected = n * p;
            chi2 += (hist[size_t(b)] - expected) * (hist[size_t(b)] - expected) / expected;
        }
        EXPECT_LT(chi2, 43.8) << g;
    }
}

}  // namespace
}  // namespace rp
