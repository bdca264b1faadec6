#include "scene/scene_bbox.h"

#include <gtest/gtest.h>

#include <fstream>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp {
namespace {

BoundingBox boxOf(const std::string& text) {
    TempDir dir;
    const std::string f = dir.file("s.rad");
    std::ofstream(f) << text;
    return sceneBoundingBox({f}, {});
}

TEST(SceneBbox, SurfacesAsRadianceBoundsThem) {
    // RADIANCE 5.4 getbbox on the same text: "0.5 1.5 1.5 2.5 2.5 3.5" for the sphere; a
    // cone's ends are disks, a ring only its outer circle.
    EXPECT_EQ(formatBoundingBox(boxOf("void plastic m 0 0 5 1 1 1 0 0\n"
                                      "m sphere s 0 0 4 1 2 3 .5\n"),
                                true),
              "     xmin      xmax      ymin      ymax      zmin      zmax\n"
              "      0.5       1.5       1.5       2.5       2.5       3.5\n");
    EXPECT_EQ(formatBoundingBox(boxOf("void plastic m 0 0 5 1 1 1 0 0\n"
                                      "m cone c 0 0 8 0 0 0 0 0 2 1 .5\n"
                                      "m ring r 0 0 8 5 0 0 1 0 0 .5 2\n"),
                                false),
              "       -1         5        -2         2        -2         2\n");
}

TEST(SceneBbox, ModifiersAloneLeaveTheBoxEmpty) {
    EXPECT_EQ(formatBoundingBox(boxOf("void plastic m 0 0 5 1 1 1 0 0\n"), false),
              "    1e+10    -1e+10     1e+10    -1e+10     1e+10    -1e+10\n");
}

TEST(SceneBbox, AnOctreeIsNotASceneDescription) {
    TempDir dir;
    const std::string f = dir.file("x.oct");
    std::ofstream(f) << "#?RADIANCE\nFORMAT=Radiance_octree\n\n";
    EXPECT_THROW(sceneBoundingBox({f}, {}), InputError);
}

}  // namespace
}  // namespace rp
