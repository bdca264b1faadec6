#include "render/colour_output.h"

#include <gtest/gtest.h>

#include <vector>

#include "render/spectral_passes.h"

namespace rp::render {
namespace {

std::vector<double> convert(const ColourOutput& c, const std::vector<double>& samples) {
    std::vector<double> out(size_t(c.components()));
    c.convert(samples, out);
    return out;
}

// An equal-energy spectrum of radiance 1: RADIANCE's white, 179 lm/W photopic.
TEST(ColourOutput, EqualEnergyIsWhiteInEveryOutput) {
    const spectral::Sampling s = spectral::makeSampling(18, 380, 780)->sampling;
    const std::vector<double> one(18, 1.0);
    ColourOutput c;
    c.resolve(s);
    EXPECT_FALSE(c.identity());
    std::vector<double> rgb = convert(c, one);
    ASSERT_EQ(rgb.size(), 3u);
    for (double v : rgb) EXPECT_NEAR(v, 1, 1e-3);
    c.setSpectral(true);
    c.resolve(s);
    EXPECT_EQ(convert(c, one), one);
    c.setChannel(ColourOutput::Channel::kPhotopic);
    c.resolve(s);
    EXPECT_NEAR(convert(c, one)[0], 179, 0.02);
    c.setChannel(ColourOutput::Channel::kAverage);
    EXPECT_DOUBLE_EQ(convert(c, one)[0], 1);
    c.setPrimaries(ColourOutput::Primaries::kXyz);
    c.resolve(s);
    for (double v : convert(c, one)) EXPECT_NEAR(v, 179, 0.1);
}

TEST(ColourOutput, OptionsCombineAsRadiance6s) {
    ColourOutput c;
    c.setChannel(ColourOutput::Channel::kPhotopic);
    c.setSpectral(!c.spectral());  // -co toggles to spectral, dropping the channel
    EXPECT_TRUE(c.spectral());
    c.setChannel(ColourOutput::Channel::kMelanopic);  // a channel after -co wins
    c.resolve(spectral::makeSampling(9, 380, 780)->sampling);
    EXPECT_EQ(c.components(), 1);
    // Spectral output of three samples is RGB.
    ColourOutput rgb;
    rgb.setSpectral(true);
    rgb.resolve(spectral::Sampling{});
    EXPECT_TRUE(rgb.identity());
    EXPECT_EQ(rgb.components(), 3);
    EXPECT_EQ(rgb.headerLines(2, 1), "NCOMP=7\n");
}

// -pc: the standard primaries are RGB; others keep white white (von Kries balance) and
// name themselves in the header.
TEST(ColourOutput, CustomPrimariesKeepWhite) {
    ColourOutput standard;
    standard.setCustomPrimaries(spectral::kStandardPrimaries);
    standard.resolve(spectral::Sampling{});
    EXPECT_TRUE(standard.identity());
    ColourOutput srgb;
    srgb.setCustomPrimaries({0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290});
    srgb.resolve(spectral::Sampling{});
    EXPECT_FALSE(srgb.identity());
    for (double v : convert(srgb, {1, 1, 1})) EXPECT_NEAR(v, 1, 1e-3);
    const std::vector<double> red = convert(srgb, {1, 0, 0});
    EXPECT_GT(red[0], red[1]);
    EXPECT_NE(srgb.headerLines(1, 0).find(
                  "PRIMARIES= 0.6400 0.3300 0.3000 0.6000 0.1500 0.0600 0.3127 0.3290\n"),
              std::string::npos);
}

TEST(SpectralPasses, MergeGathersEachPassesBands) {
    const spectral::Sampling s = spectral::makeSampling(7, 380, 780)->sampling;
    std::vector<RayResult> perPass(3);
    for (int p = 0; p < 3; ++p) {
        perPass[size_t(p)].value = {10.0 * p, 10.0 * p + 1, 10.0 * p + 2};
        perPass[size_t(p)].distance = p == 0 ? 4 : 5;
    }
    const RayResult r = mergePasses(perPass, spectral::passesOf(s));
    ASSERT_TRUE(r.samples);
    EXPECT_EQ(r.samples->value, (std::vector<double>{0, 1, 2, 10, 11, 12, 20}));
    EXPECT_EQ(r.distance, 4);  // geometry from the first pass
    EXPECT_EQ(r.samples->coefficient, std::vector<double>(7, 1.0));
}

// Ray trees of the passes merged node by node: the same shape gives each node the samples
// of all passes; a ray one pass did not trace (its weight there under -lw) shows, black in
// that pass's bands, in its place in the depth-first order.
TEST(SpectralPasses, RayTreesMergeNodeByNode) {
    const spectral::Sampling s = spectral::makeSampling(6, 380, 780)->sampling;
    const auto passes = spectral::passesOf(s);
    auto node = [](int depth, double v) {
        TracedRay t;
        t.depth = depth;
        t.result.value = Color::grey(v);
        t.result.coefficient = Color::grey(1);
        return t;
    };
    // Pass 0: root, child a with grandchild, child b. Pass 1: root, child a, child b
    // with a grandchild pass 0 did not trace.
    const std::vector<std::vector<TracedRay>> trees = {
        {node(0, 1), node(1, 2), node(2, 3), node(1, 4)},
        {node(0, 10), node(1, 20), node(1, 40), node(2, 50)}};
    const std::vector<TracedRay> merged = mergeTrees(trees, passes);
    ASSERT_EQ(merged.size(), 5u);
    const int depths[5] = {0, 1, 2, 1, 2};
    const std::vector<double> want[5] = {{1, 1, 1, 10, 10, 10},
                                         {2, 2, 2, 20, 20, 20},
                                         {3, 3, 3, 0, 0, 0},
                                         {4, 4, 4, 40, 40, 40},
                                         {0, 0, 0, 50, 50, 50}};
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(merged[size_t(k)].depth, depths[k]) << k;
        ASSERT_TRUE(merged[size_t(k)].result.samples) << k;
        EXPECT_EQ(merged[size_t(k)].result.samples->value, want[k]) << k;
    }
}

}  // namespace
}  // namespace rp::render
