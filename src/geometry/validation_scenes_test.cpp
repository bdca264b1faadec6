// Every reference scene in ../shared/validation loads and builds traceable geometry,
// and a few rays give the answers the scenes' READMEs imply.
#include <gtest/gtest.h>

#include <string>

#include "geometry/scene_geometry.h"
#include "scene/scene_load.h"
#include "util/shared_for_tests.h"

namespace rp {

namespace {
std::string validationScene(const std::string& name) {
    return std::string(RP_SHARED_DIR) + "/validation/" + name + "/scene.rad";
}
}  // namespace

class ValidationScene : public ::testing::TestWithParam<const char*> {};

TEST_P(ValidationScene, LoadsAndBuilds) {
    RP_REQUIRE_SHARED("validation");
    Scene scene = loadScene({validationScene(GetParam())});
    SceneGeometry geometry(scene);
    EXPECT_FALSE(geometry.bounds().empty());
    EXPECT_GT(geometry.sceneCube().size, 0);
}

INSTANTIATE_TEST_SUITE_P(All, ValidationScene,
                         ::testing::Values("furnace", "cornell", "caustic", "daylight", "mist",
                                           "contrib"));

TEST(ValidationScene, CornellFloorAndGlassBall) {
    RP_REQUIRE_SHARED("validation/cornell");
    Scene scene = loadScene({validationScene("cornell")});
    SceneGeometry g(scene);
    // Straight down from the box centre: the floor (z = 0), seen from its front.
    auto h = g.closestHit(Ray{{2.75, 1.0, 2.75}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2.75, 1e-12);
    EXPECT_TRUE(h->front);
    EXPECT_EQ(scene.prims[h->prim].name, "floor");
    EXPECT_EQ(scene.prims[h->modifier].name, "white");
    // Down onto the glass ball (centre 3.9 2.0 0.8, r 0.8): top at z = 1.6.
    h = g.closestHit(Ray{{3.9, 2.0, 5.0}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->point.z, 1.6, 1e-12);
    EXPECT_EQ(scene.prims[h->prim].name, "glass_ball");
    // The lamp hangs 5 mm below the ceiling and faces down.
    h = g.closestHit(Ray{{2.75, 2.75, 1.0}, {0, 0, 1}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->point.z, 5.495, 1e-12);
    EXPECT_EQ(scene.prims[h->prim].name, "lamp");
    EXPECT_TRUE(h->front);
}

TEST(ValidationScene, DaylightHasDistantSources) {
    RP_REQUIRE_SHARED("validation/daylight");
    Scene scene = loadScene({validationScene("daylight")});
    SceneGeometry g(scene);
    EXPECT_EQ(g.sources().size(), 3u);  // sun, sky, ground glows (gensky output)
}

}  // namespace rp
