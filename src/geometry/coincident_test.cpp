// Coincident surfaces (issue 43): which of two polygons in one plane a ray reports, against
// RADIANCE 5.4a's choice. The expected names are what `rtrace -h -ab 0 -oms` printed for
// the same scene and rays (oconv of the text below), in both directions through each pair.
#include "geometry/coincident.h"

#include <gtest/gtest.h>

#include <string>

#include "geometry/scene_geometry.h"
#include "scene/reader.h"

namespace rp {
namespace {

const char* kDoubled = R"(
void plastic upper_floor 0 0 5 .3 .3 .3 0 0
void plastic lower_ceiling 0 0 5 .8 .8 .8 0 0
void glass pane 0 0 3 .9 .9 .9
void plastic later 0 0 5 .5 .5 .5 0 0
upper_floor polygon floorA 0 0 12 0 0 3  4 0 3  4 4 3  0 4 3
lower_ceiling polygon ceilB 0 0 12 0 0 3  0 4 3  4 4 3  4 0 3
later polygon wallA 0 0 12 10 0 0  10 4 0  10 4 3  10 0 3
upper_floor polygon wallB 0 0 12 10 0 0  10 0 3  10 4 3  10 4 0
pane polygon glassC 0 0 12 20 0 0  24 0 0  24 4 0  20 4 0
later polygon opaqueC 0 0 12 20 0 0  20 4 0  24 4 0  24 0 0
void polygon voidD 0 0 12 30 0 0  34 0 0  34 4 0  30 4 0
later polygon matD 0 0 12 30 0 0  30 4 0  34 4 0  34 0 0
m polygon first 0 0 12 40 0 3  44 0 3  44 4 3  40 4 3
m polygon second 0 0 12 40 0 3  40 4 3  44 4 3  44 0 3
m polygon third 0 0 12 40 0 3  44 0 3  44 4 3  40 4 3
)";

std::string surfaceHit(const Scene& s, const SceneGeometry& g, Vec3 o, Vec3 d) {
    auto h = g.closestHit({o, normalize(d)});
    return h ? s.prims[size_t(h->prim)].name : "*";
}

TEST(Coincident, RadiancesChoiceFromBothSides) {
    Scene s = parseScene(std::string("void plastic m 0 0 5 .3 .3 .3 0 0\n") + kDoubled);
    SceneGeometry g(s);
    // Both opaque: the later modifier (lower_ceiling, defined after upper_floor), whichever
    // side the ray comes from and wherever it meets the pair.
    EXPECT_EQ(surfaceHit(s, g, {1, 1, 1}, {0, 0, 1}), "ceilB");
    EXPECT_EQ(surfaceHit(s, g, {3.5, 2.5, 5}, {0, 0, -1}), "ceilB");
    EXPECT_EQ(surfaceHit(s, g, {2, 2, 0}, {0.3, 0.2, 1}), "ceilB");
    // The later modifier wins though its surface comes first in the file.
    EXPECT_EQ(surfaceHit(s, g, {12, 2, 1}, {-1, 0, 0}), "wallA");
    EXPECT_EQ(surfaceHit(s, g, {8, 3, 2}, {1, 0, 0}), "wallA");
    // Opaque over transparent, a material over void.
    EXPECT_EQ(surfaceHit(s, g, {22, 2, 1}, {0, 0, -1}), "opaqueC");
    EXPECT_EQ(surfaceHit(s, g, {22, 2, -1}, {0, 0, 1}), "opaqueC");
    EXPECT_EQ(surfaceHit(s, g, {32, 2, 1}, {0, 0, -1}), "matD");
    EXPECT_EQ(surfaceHit(s, g, {32, 1, -1}, {0, 0, 1}), "matD");
    // One modifier: the last surface.
    EXPECT_EQ(surfaceHit(s, g, {41, 1, 1}, {0, 0, 1}), "third");
    EXPECT_EQ(surfaceHit(s, g, {43.5, 2.5, 5}, {0, 0, -1}), "third");
    EXPECT_EQ(surfaceHit(s, g, {40.1, 3.9, 5}, {0, 0, -1}), "third");
    // Many rays over the pair: never the other surface (Embree alone picks by position).
    for (int i = 0; i < 400; ++i) {
        const double x = 0.01 + 3.98 * ((i * 37) % 400) / 400.0, y = 0.01 + 3.98 * i / 400.0;
        ASSERT_EQ(surfaceHit(s, g, {x, y, 0}, {0, 0, 1}), "ceilB") << x << " " << y;
        ASSERT_EQ(surfaceHit(s, g, {x - 0.3, y + 0.15, 6}, {0.1, -0.05, -1}), "ceilB")
            << x << " " << y;
    }
}

// A pair is only a pair where both are: past the smaller one the other is hit alone;
// parallel planes 1 mm apart and neighbours that share an edge are no pairs.
TEST(Coincident, OnlyOverlappingPartsOfOnePlane) {
    Scene s = parseScene(R"(
void plastic a 0 0 5 .3 .3 .3 0 0
void plastic b 0 0 5 .3 .3 .3 0 0
a polygon big 0 0 12 0 0 0  4 0 0  4 4 0  0 4 0
b polygon small 0 0 12 1 1 0  1 2 0  2 2 0  2 1 0
a polygon near 0 0 12 10 0 0  14 0 0  14 4 0  10 4 0
b polygon far 0 0 12 10 0 .001  14 0 .001  14 4 .001  10 4 .001
a polygon left 0 0 12 20 0 0  22 0 0  22 4 0  20 4 0
b polygon right 0 0 12 22 0 0  24 0 0  24 4 0  22 4 0
)");
    SceneGeometry g(s);
    CoincidentPolygons c(s, g.shapes());
    EXPECT_EQ(c.pairCount(), 1u);
    EXPECT_EQ(surfaceHit(s, g, {1.5, 1.5, 1}, {0, 0, -1}), "small");
    EXPECT_EQ(surfaceHit(s, g, {3, 3, 1}, {0, 0, -1}), "big");
    EXPECT_EQ(surfaceHit(s, g, {12, 2, 1}, {0, 0, -1}), "far");
    EXPECT_EQ(surfaceHit(s, g, {12, 2, -1}, {0, 0, 1}), "near");
}

}  // namespace
}  // namespace rp
