// Function patterns: gensky's skyfunc at the zenith against the CIE formula, object-space
// transforms, chains multiplying, and unsupported patterns named at their line.
#include "material/pattern.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/reader.h"
#include "scene/scene_load.h"

namespace rp::material {

namespace {
std::vector<std::string> libPath() { return {std::string(RP_SOURCE_DIR) + "/lib"}; }

int32_t indexOf(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.prims.size(); ++i)
        if (s.prims[i].name == name) return int32_t(i);
    return -1;
}
}  // namespace

TEST(Pattern, DaylightSkyAtZenithMatchesCieClearSky) {
    Scene s = loadScene({std::string(RP_SHARED_DIR) + "/validation/daylight/scene.rad"});
    PatternSet set(s, libPath());
    int32_t glow = indexOf(s, "sky_glow");
    ASSERT_GE(glow, 0);
    int32_t mod = s.prims[glow].modifier;
    set.checkChain(mod);
    EXPECT_FALSE(set.directionalOnly(mod));  // skybright.cal could read P
    PatternEvaluator ev(set);
    PatternPoint at;
    at.dir = {0, 0, 1};
    Color c = ev.chainColor(mod, at);
    // skyfunc args: 1 8.79 20.0 0.526 | sun 0.153855 -0.727432 0.668708 (gensky +s).
    double zen = 8.79, ground = 20.0, norm = 0.526, cosg = 0.668708;
    double gamma = std::acos(cosg);
    double clear = zen * (0.91 + 10 * std::exp(-3 * gamma) + 0.45 * cosg * cosg) *
                   (1 - std::exp(-0.32)) / norm;
    double w = std::pow(2.01, 10);
    double expected = (w * clear + ground / w) / (w + 1 / w);
    EXPECT_NEAR(c.r, expected, 1e-9 * expected);
    EXPECT_EQ(c.r, c.g);
    EXPECT_EQ(c.g, c.b);
}

TEST(Pattern, TransformsMapWorldToObjectSpaceAndChainsMultiply) {
    Scene s = parseScene(
        "void colorfunc dirs 6 Dx Dy Dz . -rz 90 0 0\n"
        "dirs brightfunc twice 2 2 . 0 0\n"
        "twice plastic m 0 0 5 1 1 1 0 0\n",
        "p.rad");
    PatternSet set(s, libPath());
    int32_t mat = indexOf(s, "m");
    set.checkChain(s.prims[mat].modifier);
    EXPECT_TRUE(set.directionalOnly(s.prims[mat].modifier));
    PatternEvaluator ev(set);
    PatternPoint at;
    at.dir = {1, 0, 0};
    Color c = ev.chainColor(s.prims[mat].modifier, at);
    // Rotated +90 degrees about z, the world x axis is the object's -y axis; x 2.
    EXPECT_NEAR(c.r, 0, 1e-12);
    EXPECT_NEAR(c.g, -2, 1e-12);
    EXPECT_NEAR(c.b, 0, 1e-12);
}

TEST(Pattern, RealArgumentsAndPositionReachTheFunction) {
    Scene s = parseScene("void brightfunc f 6 A2*Px+A1 . -t 1 0 0 0 2 10 3\n", "a.rad");
    PatternSet set(s, libPath());
    EXPECT_FALSE(set.directionalOnly(0));
    PatternEvaluator ev(set);
    PatternPoint at;
    at.point = {5, 0, 0};  // object space: 4
    EXPECT_NEAR(ev.chainColor(0, at).r, 3 * 4 + 10, 1e-12);
}

TEST(Pattern, UnsupportedPatternsAndMissingFilesAreNamedAtTheirLine) {
    Scene s = parseScene("void texfunc wavy 4 dx dy dz . 0 0\nwavy plastic m 0 0 5 1 1 1 0 0\n",
                         "t.rad");
    PatternSet set(s, libPath());
    try {
        set.checkChain(s.prims[1].modifier);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().line, 1);
        EXPECT_NE(std::string(e.what()).find("not supported yet"), std::string::npos);
    }
    Scene missing = parseScene("\nvoid brightfunc f 2 x nothere.cal 0 0\n", "m.rad");
    try {
        PatternSet bad(missing, libPath());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().line, 2) << e.what();
        EXPECT_NE(std::string(e.what()).find("nothere.cal"), std::string::npos) << e.what();
    }
}

}  // namespace rp::material
