#include "util/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace rp::spectral {
namespace {

TEST(Spectrum, SamplingIsRadiance6s) {
    EXPECT_FALSE(makeSampling(2, 380, 780));
    EXPECT_FALSE(makeSampling(9, 500, 540));  // under 50 nm
    auto rgb = makeSampling(3, 380, 780);
    ASSERT_TRUE(rgb);
    EXPECT_TRUE(rgb->tuned);
    EXPECT_EQ(rgb->sampling, Sampling{});

    // 18 bands of 22.2 nm from 780 nm: the centres nearest 607, 553 and 469 nm are bands
    // 7 (613.3), 10 (546.7) and 13 (480.0, nearer than 457.8).
    auto s18 = makeSampling(18, 780, 380);
    ASSERT_TRUE(s18);
    EXPECT_TRUE(s18->tuned);
    EXPECT_EQ(s18->sampling.n, 18);
    EXPECT_EQ(s18->sampling.wl, (std::array<double, 4>{780, 588, 480, 380}));
    EXPECT_EQ(s18->sampling.rgb, (std::array<int, 3>{7, 10, 13}));

    // A range that misses the blue peak is split in thirds.
    auto red = makeSampling(6, 500, 800);
    ASSERT_TRUE(red);
    EXPECT_FALSE(red->tuned);
    EXPECT_EQ(red->sampling.wl, (std::array<double, 4>{800, 700, 600, 500}));
    EXPECT_EQ(red->sampling.rgb, (std::array<int, 3>{0, 2, 4}));

    EXPECT_EQ(makeSampling(40, 380, 780)->sampling.n, kMaxSamples);
}

TEST(Spectrum, RgbSpreadsOverTheBandsOfItsChannels) {
    const Sampling s = makeSampling(8, 380, 780)->sampling;  // 50 nm bands
    std::vector<double> v(8);
    fromRgb({0.5, 0.25, 0.125}, s, v);
    // Centres 755 705 655 605 | 555 505 | 455 405.
    EXPECT_EQ(v, (std::vector<double>{0.5, 0.5, 0.5, 0.5, 0.25, 0.25, 0.125, 0.125}));
    const Color back = bandAverages(v, s);
    EXPECT_DOUBLE_EQ(back.r, 0.5);
    EXPECT_DOUBLE_EQ(back.g, 0.25);
    EXPECT_DOUBLE_EQ(back.b, 0.125);
}

// A sampling is rendered three bands at a time; an RGB colour gives each band the
// primary whose range holds its centre, as fromRgb does for all bands at once.
TEST(Spectrum, PassesCoverTheBandsThreeAtATime) {
    const Sampling s = makeSampling(8, 380, 780)->sampling;  // red 0-3, green 4-5, blue 6-7
    const std::vector<Pass> passes = passesOf(s);
    ASSERT_EQ(passes.size(), 3u);
    EXPECT_EQ(passes[0].primary, (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(passes[1].primary, (std::array<int, 3>{0, 1, 1}));
    EXPECT_EQ(passes[2].first, 6);
    EXPECT_EQ(passes[2].band(2), 7);  // the last pass repeats its last band
    EXPECT_EQ(passes[2].primary, (std::array<int, 3>{2, 2, 2}));
    const Color rgb{0.5, 0.25, 0.125};
    std::vector<double> all(8);
    fromRgb(rgb, s, all);
    for (const Pass& p : passes) {
        const Color c = p.ofRgb(rgb), fromSamples = p.ofSamples(all);
        for (int j = 0; j < 3; ++j) {
            EXPECT_EQ(c[j], all[size_t(p.band(j))]);
            EXPECT_EQ(fromSamples[j], c[j]);
        }
    }
    // RGB rendering is one pass that changes nothing.
    const std::vector<Pass> rgbPasses = passesOf(Sampling{});
    ASSERT_EQ(rgbPasses.size(), 1u);
    EXPECT_EQ(rgbPasses[0].ofRgb(rgb), rgb);
}

TEST(Spectrum, ResamplingAveragesOverEachBand) {
    // Source 400..800 in 4 bands of 100 nm (ascending): 1 2 3 4.
    const std::vector<double> src = {1, 2, 3, 4};
    std::vector<double> dst(2);
    resample(dst, 800, 600, src, 400, 800);  // the two longest source bands, reversed
    EXPECT_DOUBLE_EQ(dst[0], 4);
    EXPECT_DOUBLE_EQ(dst[1], 3);
    resample(dst, 850, 350, src, 400, 800);  // 250 nm bands, 50 nm outside each end
    EXPECT_DOUBLE_EQ(dst[0], (50 * 0 + 100 * 4 + 100 * 3) / 250.0);  // 850..600 nm
    EXPECT_DOUBLE_EQ(dst[1], (100 * 2 + 100 * 1 + 50 * 0) / 250.0);  // 600..350 nm
    // The integral is kept where the source lies inside.
    std::vector<double> fine(16);
    resample(fine, 800, 400, src, 800, 400);
    EXPECT_NEAR(std::accumulate(fine.begin(), fine.end(), 0.0) * 25, 1000, 1e-9);
}

TEST(Spectrum, EqualEnergyIsWhite) {
    // The observer's integrals are normalised: an equal-energy spectrum has X=Y=Z=1 and
    // RADIANCE RGB (1,1,1), up to the observer's tails outside 380..780 nm (z-bar's
    // below 380 nm is 4.7e-4 of its integral).
    for (int n : {4, 9, 18, 24}) {
        const Sampling s = makeSampling(n, 380, 780)->sampling;
        std::vector<double> one(size_t(n), 1.0);
        const Color xyz = toXyz(one, s), rgb = toRgb(one, s);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(xyz[c], 1, 5e-4) << n;
            EXPECT_NEAR(rgb[c], 1, 1e-3) << n;
        }
        EXPECT_NEAR(photopic(one, s), 1, 1e-4);
    }
}

TEST(Spectrum, MonochromaticLightIsOutOfGamutAndClipped) {
    // A 10 nm band at 500..510 nm (40 bands from 780 nm down): saturated blue-green,
    // red negative before clipping.
    std::vector<double> src(40, 0.0);
    src[27] = 1;
    double out[3];
    toWorking(src, 780, 380, Sampling{}, std::span<double>(out, 3));
    const Color rgb{out[0], out[1], out[2]};
    EXPECT_GE(rgb.min(), 0);
    EXPECT_NEAR(rgb.min(), 0, 1e-12);  // pulled to the gamut's face
    EXPECT_GT(rgb.g, rgb.b);
}

TEST(Spectrum, ClipNegativeKeepsLuminance) {
    const Color c = clipNegative({-0.5, 1, 2}, 0.5);
    EXPECT_NEAR(c.r, 0, 1e-15);
    // Desaturated towards grey 0.5 by the factor that takes red to 0: 0.5.
    EXPECT_NEAR(c.g, 0.75, 1e-15);
    EXPECT_NEAR(c.b, 1.25, 1e-15);
    EXPECT_EQ(clipNegative({1, 2, 3}, -1), Color{});
    EXPECT_EQ(clipNegative({1, 2, 3}, 2), (Color{1, 2, 3}));
}

}  // namespace
}  // namespace rp::spectral
