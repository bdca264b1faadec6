// Antimatter in the backward pass: eye rays, shadow rays and the -dp pretest of mirror
// virtual sources see through a hole cut by antimatter, as RADIANCE does (the
// radiance-tests mirror model: sunlight through a portal in the end wall, onto walls
// and into a mirror). Truth is the sun's unshadowed irradiance L * omega.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "calc/search_path.h"
#include "geometry/scene_geometry.h"
#include "render/renderer.h"
#include "scene/reader.h"
#include "util/paths.h"

namespace rp::render {
namespace {

// An overhead sun (0.5 degree disk) over a roof slab z in [2, 2.2] of material `roof`
// with a round hole cut by antimatter (a sphere of radius 0.5 about the slab's middle,
// 0.49 wide where it meets the faces), and a floor of the same material below. The
// floor being the clipped material matters: the antimatter's first modifier is not
// void, and RADIANCE still passes a floor point's shadow rays (clip_set.h).
const std::string kRoof = R"(
void light sun 0 0 3 1000 1000 1000
sun source s 0 0 4 0 0 1 0.5
void plastic roof 0 0 5 .5 .5 .5 0 0
roof polygon under 0 0 12  -5 -5 2  -5 5 2  5 5 2  5 -5 2
roof polygon over 0 0 12  -5 -5 2.2  5 -5 2.2  5 5 2.2  -5 5 2.2
void antimatter hole 1 roof 0 0
hole sphere bore 0 0 4  0 0 2.1  0.5
)";
const std::string kFloor = "roof polygon floor 0 0 12  -5 -5 0  5 -5 0  5 5 0  -5 5 0\n";

const double kSunOmega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
const double kSunIrradiance = 1000 * kSunOmega;

struct Fixture {
    explicit Fixture(const std::string& text, RenderOptions o = {})
        : scene(parseScene(text, "t.rad")),
          geometry(scene),
          options(o),
          renderer(scene, geometry, options, calc::defaultSearchPath(projectLibDir())),
          ctx(renderer.makeContext()) {}
    double irradiance(const Vec3& p, const Vec3& n) {
        return renderer.irradiance(*ctx, p, n, ++index).value.r;
    }
    RayResult trace(const Vec3& p, const Vec3& d) { return renderer.trace(*ctx, p, d, ++index); }
    Scene scene;
    SceneGeometry geometry;
    RenderOptions options;
    Renderer renderer;
    Renderer::ContextPtr ctx;
    uint64_t index = 0;
};

TEST(Antimatter, EyeRaysSeeThroughTheHole) {
    Fixture f(kRoof + kFloor);
    // Up through the hole: the sun itself (entering the bore clips `roof`, leaving it
    // makes it visible again).
    EXPECT_NEAR(f.trace({0, 0, 1}, {0, 0, 1}).value.r, 1000, 1e-9);
    // Beside the hole: the roof's underside, unlit at -ab 0.
    RayResult beside = f.trace({1, 0, 1}, {0, 0, 1});
    ASSERT_TRUE(beside.hit);
    EXPECT_EQ(f.scene.prims[size_t(beside.prim)].name, "under");
    EXPECT_EQ(beside.value.r, 0);
    // From above, down through the hole onto the sunlit floor: rho / pi * E.
    RayResult down = f.trace({0.1, 0, 3}, {0, 0, -1});
    ASSERT_TRUE(down.hit);
    EXPECT_EQ(f.scene.prims[size_t(down.prim)].name, "floor");
    EXPECT_NEAR(down.value.r, 0.5 / kPi * kSunIrradiance, 1e-3 * kSunIrradiance);
}

TEST(Antimatter, ShadowRaysPassTheHoleOnly) {
    Fixture f(kRoof + kFloor);
    EXPECT_NEAR(f.irradiance({0, 0, 0}, {0, 0, 1}), kSunIrradiance, 1e-3 * kSunIrradiance);
    EXPECT_NEAR(f.irradiance({0.45, 0, 0}, {0, 0, 1}), kSunIrradiance, 1e-3 * kSunIrradiance);
    EXPECT_EQ(f.irradiance({0.6, 0, 0}, {0, 0, 1}), 0);
    EXPECT_EQ(f.irradiance({3, 0, 0}, {0, 0, 1}), 0);
    // An eye ray meeting the floor in the patch: its shadow rays start outside the bore.
    RayResult lit = f.trace({0.2, 0, 1}, {0, 0, -1});
    EXPECT_NEAR(lit.value.r, 0.5 / kPi * kSunIrradiance, 1e-3 * kSunIrradiance);
}

TEST(Antimatter, OnlyTheListedModifiersAreClipped) {
    // A lid of another material in the hole still shades its middle.
    Fixture f(kRoof + kFloor +
              "void plastic lidmat 0 0 5 .5 .5 .5 0 0\n"
              "lidmat ring lid 0 0 8  0 0 2.1  0 0 1  0 0.3\n");
    EXPECT_EQ(f.irradiance({0, 0, 0}, {0, 0, 1}), 0);
    EXPECT_NEAR(f.irradiance({0.4, 0, 0}, {0, 0, 1}), kSunIrradiance, 1e-3 * kSunIrradiance);
    EXPECT_EQ(f.scene.prims[size_t(f.trace({0, 0, 1}, {0, 0, 1}).prim)].name, "lid");
}

TEST(Antimatter, MirrorLitThroughTheHoleMakesAVirtualSource) {
    // A small mirror under the hole sees the sun only through it; the -dp pretest must
    // follow its rays through the antimatter or the virtual sun is dropped.
    const std::string mirror =
        "void mirror silver 0 0 3 .9 .9 .9\n"
        "silver polygon m 0 0 12  -0.2 -0.2 0  0.2 -0.2 0  0.2 0.2 0  -0.2 0.2 0\n";
    const double want = 0.9 * kSunIrradiance;
    Fixture f(kRoof + mirror);  // -dp 512
    EXPECT_NEAR(f.irradiance({0, 0, 1}, {0, 0, -1}), want, 1e-3 * want);
    RenderOptions noPretest;
    noPretest.direct.pretest = 0;
    Fixture g(kRoof + mirror, noPretest);
    EXPECT_NEAR(g.irradiance({0, 0, 1}, {0, 0, -1}), want, 1e-3 * want);
    // Without the hole the roof hides the sun from the mirror.
    std::string solid = kRoof.substr(0, kRoof.find("void antimatter"));
    Fixture h(solid + mirror);
    EXPECT_EQ(h.irradiance({0, 0, 1}, {0, 0, -1}), 0);
}

}  // namespace
}  // namespace rp::render
