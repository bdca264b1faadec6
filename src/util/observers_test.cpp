#include "util/observers.h"

#include <gtest/gtest.h>

#include <vector>

#include "util/spectrum.h"

namespace rp::spectral {
namespace {

// A RADIANCE `spectrum` modifier's values at evenly spaced wavelengths wl0..wl1 are
// bands of the same width centred on them (rt/p_data.c p_spectrum), re-binned to the
// working sampling as toWorking() does.
std::vector<double> spectrumModifier(const std::vector<double>& v, double wl0, double wl1,
                                     const Sampling& s) {
    const double h = 0.5 * (wl1 - wl0) / static_cast<double>(v.size() - 1);
    std::vector<double> out(static_cast<size_t>(s.n));
    toWorking(v, wl0 - h, wl1 + h, s, out);
    return out;
}

TEST(Observers, EqualEnergyGivesOne) {
    // Both tables cover 380-780 nm: bands over that range hold all of them.
    for (int n : {4, 9, 18, 24}) {
        const Sampling s = makeSampling(n, 380, 780)->sampling;
        const std::vector<double> ee(static_cast<size_t>(n), 1.0);
        EXPECT_NEAR(scotopic(ee, s), 1, 1e-12) << n;
        EXPECT_NEAR(melanopic(ee, s), 1, 1e-12) << n;
    }
    // A narrower range loses the tails: V'(λ) has 0.07 % of its integral under 400 nm,
    // s_mel 0.1 %, both next to none over 700 nm.
    const Sampling narrow = makeSampling(10, 400, 700)->sampling;
    const std::vector<double> ee(10, 1.0);
    EXPECT_NEAR(scotopic(ee, narrow), 1, 0.002);
    EXPECT_LT(scotopic(ee, narrow), 1);
    EXPECT_NEAR(melanopic(ee, narrow), 1, 0.002);
    EXPECT_LT(melanopic(ee, narrow), 1);
    // RGB white.
    const Sampling rgb;
    const std::vector<double> white = {1, 1, 1};
    EXPECT_NEAR(scotopic(white, rgb), 1, 1e-12);
    EXPECT_NEAR(melanopic(white, rgb), 1, 1e-12);
}

TEST(Observers, CurvesPeakWhereTheyShould) {
    // V'(λ) peaks at 507 nm and s_mel at 490 nm: the band holding the peak outweighs
    // all others, and the melanopic curve sits bluer than the scotopic.
    const Sampling s = makeSampling(40, 380, 780)->sampling;  // 24 bands of 16.7 nm
    auto band = [&](int i) {
        std::vector<double> v(static_cast<size_t>(s.n), 0.0);
        v[size_t(i)] = 1;
        return v;
    };
    int bestS = 0, bestM = 0;
    for (int i = 1; i < s.n; ++i) {
        if (scotopic(band(i), s) > scotopic(band(bestS), s)) bestS = i;
        if (melanopic(band(i), s) > melanopic(band(bestM), s)) bestM = i;
    }
    EXPECT_NEAR(s.centre(bestS), 505, 10);
    EXPECT_NEAR(s.centre(bestM), 490, 10);
    EXPECT_GT(bestM, bestS);  // shorter wavelength, later sample
}

TEST(Observers, RgbIntegratesOverTheThreeChannelBands) {
    // n == 3: blue over 380-480 nm, green 480-588, red 588-780 (RADIANCE's spec_dot with
    // ncs == 3), against a fine sampling of the same three steps.
    const Sampling rgb;
    const Sampling fine{24, {780, 588, 480, 380}, {}};
    const std::vector<double> c = {0.2, 0.5, 1.3};
    std::vector<double> steps(24);
    // Bands of 16.67 nm: 380-480 is exactly 6 bands, 588 falls inside band 11 from the
    // top (580.0-596.7); compare channels whose bands line up instead.
    const std::vector<double> blueOnly = {0, 0, 1};
    for (int i = 0; i < 24; ++i) steps[size_t(i)] = fine.centre(i) < 480 ? 1 : 0;
    EXPECT_NEAR(scotopic(blueOnly, rgb), scotopic(steps, fine), 1e-12);
    EXPECT_NEAR(melanopic(blueOnly, rgb), melanopic(steps, fine), 1e-12);
    // Blue carries much of s_mel, little of V'(λ)'s red; the sum is linear.
    EXPECT_GT(melanopic(blueOnly, rgb), 0.3);
    const std::vector<double> redOnly = {1, 0, 0}, greenOnly = {0, 1, 0};
    EXPECT_LT(scotopic(redOnly, rgb), 0.1);
    EXPECT_NEAR(scotopic(c, rgb),
                0.2 * scotopic(redOnly, rgb) + 0.5 * scotopic(greenOnly, rgb) +
                    1.3 * scotopic(blueOnly, rgb),
                1e-12);
    EXPECT_NEAR(scotopic(redOnly, rgb) + scotopic(greenOnly, rgb) + scotopic(blueOnly, rgb), 1,
                1e-12);
}

// RADIANCE 6.1a, glows with `spectrum` modifiers seen straight on:
//   void spectrum flat 0 0 7 380 780 1 1 1 1 1
//   void spectrum rise 0 0 12 400 760 0.12 0.14 0.17 0.22 0.3 0.42 0.55 0.66 0.73 0.77
//   void spectrum fall 0 0 12 400 760 0.9 0.85 0.7 0.5 0.35 0.25 0.18 0.14 0.12 0.11
//   void spectrum bump 0 0 11 380 780 0.05 0.2 0.7 1 0.7 0.3 0.12 0.06 0.04
//   (each NAME glow gN 0 0 4 1 1 1 0, a unit polygon gN under the ray)
//   rtrace -h -ab 0 -cs 18 -pS (-pM, -pY) scene.oct, and without -cs 18 (RGB)
struct Case {
    const char* name;
    double wl0, wl1;
    std::vector<double> values;
    double s18, m18, y18;  // -cs 18 -pS, -pM, -pY
    double s3, m3;         // RGB (-cs 3) -pS, -pM
};
const std::vector<Case>& radianceCases() {
    static const std::vector<Case> cases = {
        {"flat", 380, 780, {1, 1, 1, 1, 1}, 412.0, 179.0, 179.0, 411.9512, 178.9627},
        {"rise",
         400,
         760,
         {0.12, 0.14, 0.17, 0.22, 0.3, 0.42, 0.55, 0.66, 0.73, 0.77},
         86.07372,
         33.85950,
         56.76147,
         92.45622,
         36.93303},
        {"fall",
         400,
         760,
         {0.9, 0.85, 0.7, 0.5, 0.35, 0.25, 0.18, 0.14, 0.12, 0.11},
         241.5984,
         115.1461,
         68.26237,
         221.8555,
         106.2733},
        {"bump",
         380,
         780,
         {0.05, 0.2, 0.7, 1, 0.7, 0.3, 0.12, 0.06, 0.04},
         312.3902,
         126.2791,
         133.6427,
         304.4519,
         122.4930},
    };
    return cases;
}

TEST(Observers, AgreeWithRadiance6) {
    const Sampling s18 = makeSampling(18, 380, 780)->sampling;
    const Sampling rgb;
    for (const Case& c : radianceCases()) {
        const std::vector<double> v = spectrumModifier(c.values, c.wl0, c.wl1, s18);
        // RADIANCE integrates its 16-bit cumulative tables between whole nanometres; its
        // CIE tables read ~1.5 nm toward the red. Measured: scotopic within 0.65 %,
        // melanopic 0.06 %, photopic 0.95 %.
        EXPECT_NEAR(kScotopicEfficacy * scotopic(v, s18), c.s18, 0.015 * c.s18) << c.name;
        EXPECT_NEAR(kMelanopicEfficacy * melanopic(v, s18), c.m18, 0.005 * c.m18) << c.name;
        EXPECT_NEAR(179 * photopic(v, s18), c.y18, 0.015 * c.y18) << c.name;  // -pY
        // RGB: the spectrum converted to RGB first (through the CIE observer), then the
        // three channel bands. Measured: within 0.8 % (scotopic) and 1.45 % (melanopic).
        const std::vector<double> w = spectrumModifier(c.values, c.wl0, c.wl1, rgb);
        EXPECT_NEAR(kScotopicEfficacy * scotopic(w, rgb), c.s3, 0.02 * c.s3) << c.name;
        EXPECT_NEAR(kMelanopicEfficacy * melanopic(w, rgb), c.m3, 0.02 * c.m3) << c.name;
    }
}

}  // namespace
}  // namespace rp::spectral
