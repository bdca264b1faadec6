#include "render/rcontrib.h"

#include <gtest/gtest.h>

#include "scene/reader.h"
#include "util/dir_code.h"
#include "util/error.h"
#include "util/warning_capture_for_tests.h"

namespace rp::render {
namespace {

const char* kScene = R"(
void light lamp 0 0 3 10 20 40
lamp sphere bulb 0 0 4 0 0 2 0.1
void glow sky 0 0 4 1 1 1 0
sky source dome 0 0 4 0 0 1 180
void plastic wall 0 0 5 .5 .5 .5 0 0
)";

int32_t indexOf(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.prims.size(); ++i)
        if (s.prims[i].name == name) return int32_t(i);
    return -1;
}

ContribModifier mod(const std::string& name, const std::string& bin = "0", int bins = 1,
                    const std::string& params = "") {
    ContribModifier m;
    m.name = name;
    m.binExpr = bin;
    m.bins = bins;
    m.params = params;
    return m;
}

TEST(ContribTally, CoefficientsOrContributionsByModifierName) {
    Scene s = parseScene(kScene);
    const int32_t lamp = indexOf(s, "lamp"), wall = indexOf(s, "wall");
    for (bool contributions : {false, true}) {
        ContribTargets t(s, {mod("wall"), mod("lamp")}, {}, contributions);
        ContribTally tally(t);
        EXPECT_TRUE(tally.tracks(lamp));
        EXPECT_FALSE(tally.tracks(indexOf(s, "sky")));
        tally.add(lamp, Vec3{0, 0, 2}, Vec3{0, 0, 1}, Color{0.5, 0.5, 0.5}, Color{10, 20, 40});
        tally.add(lamp, Vec3{0, 0, 2}, Vec3{0, 0, 1}, Color{0.25, 0.25, 0.25}, Color{10, 20, 40});
        tally.add(wall, Vec3{}, Vec3{0, 0, 1}, Color{1, 1, 1}, Color{2, 2, 2});
        ASSERT_EQ(tally.values().size(), 2u);
        // Modifier order: wall, then lamp.
        EXPECT_EQ(tally.values()[1], contributions ? Color(7.5, 15, 30) : Color(0.75, 0.75, 0.75));
        EXPECT_EQ(tally.values()[0], contributions ? Color(2, 2, 2) : Color(1, 1, 1));
        tally.reset();
        EXPECT_EQ(tally.values()[1], Color{});
    }
}

TEST(ContribTally, BinsRoundNegativesDropAndTooLargeAreCounted) {
    // rcontrib.1: the bin value is rounded to the nearest integer; negative bins are
    // silently ignored, bins >= -bn are ignored with a warning.
    Scene s = parseScene(kScene);
    const int32_t sky = indexOf(s, "sky");
    ContribTargets t(s, {mod("sky", "Dx * 4", 4)}, {}, false);
    ContribTally tally(t);
    for (double dx : {0.0, 0.3, 0.4, 0.74, -0.1, -0.2, 0.9})
        tally.add(sky, Vec3{}, Vec3{dx, 0, 1}, Color{1, 1, 1}, Color{});
    // 0 -> 0, 1.2 -> 1, 1.6 -> 2, 2.96 -> 3, -0.4 -> 0 (rounds to 0), -0.8 dropped, 3.6 -> 4
    // dropped.
    EXPECT_EQ(tally.values()[0], Color(2, 2, 2));
    EXPECT_EQ(tally.values()[1], Color(1, 1, 1));
    EXPECT_EQ(tally.values()[2], Color(1, 1, 1));
    EXPECT_EQ(tally.values()[3], Color(1, 1, 1));
    EXPECT_EQ(t.badBins().count(), 1);
}

TEST(ContribTally, ParametersAndDefinitionsPerModifier) {
    // -p values apply to their modifier only; -e definitions to all.
    Scene s = parseScene(kScene);
    const int32_t sky = indexOf(s, "sky"), lamp = indexOf(s, "lamp");
    ContribTargets t(s, {mod("sky", "k", 8, "k=3"), mod("lamp", "k", 8, "k=5")},
                     {{false, "k = 1;"}}, false);
    ContribTally tally(t);
    tally.add(sky, Vec3{}, Vec3{0, 0, 1}, Color{1, 1, 1}, Color{});
    tally.add(lamp, Vec3{}, Vec3{0, 0, 1}, Color{1, 1, 1}, Color{});
    EXPECT_EQ(tally.values()[3], Color(1, 1, 1));
    EXPECT_EQ(tally.values()[8 + 5], Color(1, 1, 1));
}

TEST(ContribTally, BinExpressionThatDoesNotEvaluateIsAnError) {
    Scene s = parseScene(kScene);
    EXPECT_THROW(ContribTargets(s, {mod("sky", "Dx", 1000000000)}, {}, false), InputError);
    EXPECT_THROW(ContribTargets(s, {mod("sky", "nosuchname * 2", 4)}, {}, false), InputError);
    EXPECT_THROW(ContribTargets(s, {mod("sky", "Dx +", 4)}, {}, false), InputError);
}

TEST(ContribTally, PhotonContributionsBySourceMaterial) {
    // pmcontrib2.c: a photon counts for the modifier named like its source's material;
    // coefficients (-V-) are per unit radiance of that source.
    Scene s = parseScene(kScene);
    const std::vector<pmap::PhotonPrimary> primaries{{0}, {1}};
    for (bool contributions : {false, true}) {
        ContribTargets t(
            s, {mod("lamp")}, {}, contributions,
            {{{"lamp", {10, 20, 40}, false}, {"sky", {1, 1, 1}, true}}, primaries, {}, 1});
        ContribTally tally(t);
        tally.addPhoton(0, Color{1, 2, 4});
        tally.addPhoton(1, Color{5, 5, 5});  // the sky is not tracked
        EXPECT_EQ(tally.values()[0], contributions ? Color(1, 2, 4) : Color(0.1, 0.1, 0.1));
    }
    EXPECT_THROW(
        ContribTargets(s, {mod("wall")}, {}, true, {{{"lamp", {}, false}}, primaries, {}, 1}),
        InputError);
}

TEST(ContribTally, PhotonBinsNeedPrimaryRays) {
    // With primary rays (mkpmap -apCPD) a photon is binned by the direction back to its
    // source; a distant source's point is 0 (RADIANCE). Without them, binned photons are
    // dropped with RADIANCE's warnings.
    Scene s = parseScene(kScene);
    const std::vector<pmap::PhotonPrimary> primaries{{0}, {0}};
    std::vector<pmap::PrimaryRay> rays(2);
    rays[0] = {{5, 5, 5}, encodeDirection({0, 0.6, 0.8})};   // up
    rays[1] = {{5, 5, 5}, encodeDirection({0, 0.6, -0.8})};  // down
    const std::vector<PhotonSource> sky{{"sky", {1, 1, 1}, true}};
    const std::vector<ContribModifier> bins{mod("sky", "if(Dz, 1, 0) + if(Px*Px, 2, 0)", 4)};
    ContribTargets t(s, bins, {}, true, {sky, primaries, rays, 1});
    ContribTally tally(t);
    tally.addPhoton(0, Color{1, 1, 1});
    tally.addPhoton(1, Color{2, 2, 2});
    EXPECT_EQ(tally.values()[1], Color(1, 1, 1));
    EXPECT_EQ(tally.values()[0], Color(2, 2, 2));
    ContribTargets withoutRays(s, bins, {}, true, {sky, primaries, {}, 1});
    ContribTally dropped(withoutRays);
    WarningCapture w;
    dropped.addPhoton(0, Color{4, 4, 4});
    EXPECT_EQ(dropped.values()[0] + dropped.values()[1], Color(0, 0, 0));
    EXPECT_TRUE(w.any("no photon primary"));
}

TEST(ContribTally, PhotonBinsPastTheCountAreCountedWhenMet) {
    // RADIANCE counts a bin number past -bn at each photon binned, not once per primary.
    Scene s = parseScene(kScene);
    const std::vector<pmap::PhotonPrimary> primaries{{0}};
    std::vector<pmap::PrimaryRay> rays(1);
    rays[0] = {{0, 0, 0}, encodeDirection({0, 0, 1})};
    ContribTargets e(s, {mod("sky", "Dz * 7", 4)}, {}, true,
                     {{{"sky", {1, 1, 1}, true}}, primaries, rays, 1});
    EXPECT_EQ(e.badBins().count(), 0);
    ContribTally tally(e);
    for (int i = 0; i < 3; ++i) tally.addPhoton(0, Color{1, 1, 1});
    EXPECT_EQ(e.badBins().count(), 3);
    EXPECT_EQ(tally.values()[0] + tally.values()[3], Color(0, 0, 0));
}

}  // namespace
}  // namespace rp::render
