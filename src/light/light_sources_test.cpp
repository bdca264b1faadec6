// Tests for light_sources.h: which primitives emit photons, ports, and the validation
// scenes' emitters (daylight: sun, sky, ground; cornell: the lamp).
#include "light/light_sources.h"

#include <gtest/gtest.h>

#include "light/light_test_util.h"
#include "scene/scene_load.h"
#include "util/shared_for_tests.h"

namespace rp::light {
namespace {

using testing::Builder;

TEST(LightSources, RulesForLightGlowSpotIllum) {
    Builder b;
    int32_t lit = b.light("lit", 1, 1, 1);
    int32_t dark = b.light("dark", 0, 0, 0);
    int32_t glow0 = b.add(PrimType::Glow, "glow0", {1, 1, 1, 0});
    int32_t glowR = b.add(PrimType::Glow, "glowR", {1, 1, 1, 2.5});
    int32_t glowNeg = b.add(PrimType::Glow, "glowNeg", {1, 1, 1, -1});
    int32_t illum = b.add(PrimType::Illum, "ill", {1, 1, 1});
    int32_t spot = b.add(PrimType::Spotlight, "spot", {1, 1, 1, 20, 0, 0, -1});
    int32_t plastic = b.add(PrimType::Plastic, "pl", {0.5, 0.5, 0.5, 0, 0});
    int32_t s1 = b.squareZ(lit, 0, 1, 0, 1, 0);
    b.squareZ(dark, 0, 1, 0, 1, 1);
    b.add(PrimType::Sphere, "g0", {5, 5, 5, 1}, glow0);
    int32_t s4 = b.add(PrimType::Sphere, "gR", {5, 5, 8, 1}, glowR);
    b.add(PrimType::Sphere, "gN", {5, 8, 5, 1}, glowNeg);
    b.squareZ(illum, 0, 1, 0, 1, 2);
    int32_t s7 = b.squareZ(spot, 0, 1, 0, 1, 3, /*down=*/true);
    b.squareZ(spot, 0, 1, 0, 1, 4, /*down=*/false);  // cone wholly behind: skipped
    b.squareZ(plastic, 0, 1, 0, 1, 5);
    int32_t sky = b.add(PrimType::Source, "sky", {0, 0, 1, 180}, glow0);  // distant glow
    SceneGeometry geom(b.scene());
    std::vector<LightSource> src = findLightSources(b.scene(), geom);
    ASSERT_EQ(src.size(), 4u);
    EXPECT_EQ(src[0].prim, s1);
    EXPECT_EQ(src[1].prim, s4);
    EXPECT_DOUBLE_EQ(src[1].maxDistance, 2.5);
    EXPECT_EQ(src[2].prim, s7);
    EXPECT_TRUE(src[2].spotlight());
    EXPECT_EQ(src[3].prim, sky);
    EXPECT_TRUE(src[3].distant());
    EXPECT_EQ(src[3].maxDistance, 0);

    LightSearchOptions withIllum;
    withIllum.illumEmits = true;
    EXPECT_EQ(findLightSources(b.scene(), geom, withIllum).size(), 5u);
}

TEST(LightSources, ModifiedSourceRecordsPattern) {
    Builder b;
    int32_t pat = b.add(PrimType::Brightfunc, "f", {}, kVoid, {"cosfunc", "."});
    int32_t mat = b.light("lamp", 1, 1, 1, pat);
    b.squareZ(mat, 0, 1, 0, 1, 0);
    SceneGeometry geom(b.scene());
    auto src = findLightSources(b.scene(), geom);
    ASSERT_EQ(src.size(), 1u);
    EXPECT_TRUE(src[0].modified());
    EXPECT_EQ(src[0].patternModifier, pat);
    EXPECT_EQ(src[0].material, mat);
}

TEST(LightSources, Ports) {
    Builder b;
    int32_t glass = b.add(PrimType::Glass, "win", {0.9, 0.9, 0.9});
    int32_t lamp = b.light("win2", 1, 1, 1);
    int32_t w = b.squareZ(glass, 0, 1, 0, 1, 0);
    b.squareZ(lamp, 0, 1, 0, 1, 1);
    SceneGeometry geom(b.scene());
    auto ports = findPhotonPorts(b.scene(), geom, {PortSpec{"win"}, PortSpec{"win2"}});
    ASSERT_EQ(ports.size(), 1u);  // a light is never a port
    EXPECT_EQ(ports[0].prim, w);
    EXPECT_THROW(findPhotonPorts(b.scene(), geom, {PortSpec{"nothing"}}), InputError);
}

// Port names are matched whole: a name ending in '+', '-' or '0' (Honeybee's
// "skylight_45_59c8c160", a "win0") is a name, not a direction (issue 43).
TEST(LightSources, PortNamesEndingInDirectionCharacters) {
    Builder b;
    int32_t glass = b.add(PrimType::Glass, "win0", {0.9, 0.9, 0.9});
    int32_t other = b.add(PrimType::Glass, "win", {0.9, 0.9, 0.9});
    int32_t w = b.squareZ(glass, 0, 1, 0, 1, 0);
    b.squareZ(other, 0, 1, 0, 1, 1);
    SceneGeometry geom(b.scene());
    auto ports = findPhotonPorts(b.scene(), geom, {PortSpec{"win0", PortDirection::Backward}});
    ASSERT_EQ(ports.size(), 1u);
    EXPECT_EQ(ports[0].prim, w);
    EXPECT_EQ(ports[0].direction, PortDirection::Backward);
}

std::string validationScene(const std::string& name) {
    return std::string(RP_SHARED_DIR) + "/validation/" + name + "/scene.rad";
}

TEST(LightSources, DaylightSceneSunSkyGroundAndPort) {
    RP_REQUIRE_SHARED("validation/daylight");
    Scene scene = loadScene({validationScene("daylight")});
    SceneGeometry geom(scene);
    auto src = findLightSources(scene, geom);
    ASSERT_EQ(src.size(), 3u);
    EXPECT_EQ(src[0].name, "sun");
    EXPECT_EQ(src[0].params.kind, material::LightParams::Kind::Light);
    EXPECT_FALSE(src[0].modified());
    EXPECT_NEAR(src[0].params.radiance.g, 6.69e6, 1);
    EXPECT_EQ(src[1].name, "sky");
    EXPECT_EQ(src[2].name, "ground");
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(src[size_t(i)].distant());
    for (int i = 1; i < 3; ++i) {
        EXPECT_EQ(src[size_t(i)].params.kind, material::LightParams::Kind::Glow);
        ASSERT_TRUE(src[size_t(i)].modified());
        EXPECT_EQ(scene.prims[size_t(src[size_t(i)].patternModifier)].name, "skyfunc");
    }
    auto ports = findPhotonPorts(scene, geom, {PortSpec{"window_glass"}});
    ASSERT_EQ(ports.size(), 1u);
    EXPECT_EQ(scene.prims[size_t(ports[0].prim)].name, "window");
}

}  // namespace
}  // namespace rp::light
