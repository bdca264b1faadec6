// Building shapes from Scene records: argument errors with locations, RADIANCE's
// degenerate-shape warnings and sign conventions, distant sources, bounds and the
// scene cube.
#include "geometry/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "geometry/test_scenes.h"
#include "util/warning_capture_for_tests.h"
#include "util/warnings.h"

namespace rp {
namespace {

using testing::SceneBuilder;

std::string errorOf(const Scene& s) {
    try {
        buildShapes(s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(Shapes, BadArgumentCountsNameTheLocation) {
    {
        SceneBuilder b;
        b.surface(PrimType::Polygon, {0, 0, 0, 1, 0, 0, 1, 1}, kVoid, "p");
        EXPECT_EQ(
            errorOf(b.scene()),
            "test.rad:1: polygon 'p': expected a multiple of 3 real arguments (at least 9), got 8");
    }
    {
        SceneBuilder b;
        b.surface(PrimType::Sphere, {0, 0, 0}, kVoid, "ball");
        EXPECT_EQ(errorOf(b.scene()),
                  "test.rad:1: sphere 'ball': expected 4 real arguments, got 3");
    }
    {
        SceneBuilder b;
        b.surface(PrimType::Cylinder, {0, 0, 0, 0, 0, 1, 1, 1}, kVoid, "c");
        EXPECT_EQ(errorOf(b.scene()), "test.rad:1: cylinder 'c': expected 7 real arguments, got 8");
    }
    {
        SceneBuilder b;
        b.surface(PrimType::Ring, {0, 0, 0, 0, 0, 1, -1, 2}, kVoid, "r");
        EXPECT_EQ(errorOf(b.scene()), "test.rad:1: ring 'r': negative radii");
    }
    {
        SceneBuilder b;
        b.surface(PrimType::Source, {0, 0, 1}, kVoid, "sun");
        EXPECT_EQ(errorOf(b.scene()), "test.rad:1: source 'sun': expected 4 real arguments, got 3");
    }
}

TEST(Shapes, InstancesAndMeshesArePlacementsNotShapes) {
    SceneBuilder b;
    b.surface(PrimType::Instance, {}, kVoid, "chair");
    b.surface(PrimType::Mesh, {}, kVoid, "m");
    ShapeSet s = buildShapes(b.scene());
    EXPECT_TRUE(s.polygons.empty() && s.spheres.empty() && s.cones.empty() && s.rings.empty());
    EXPECT_TRUE(s.bounds.empty());
}

TEST(Shapes, DegenerateShapesAreSkippedWithWarning) {
    WarningCapture w;
    SceneBuilder b;
    b.material("paint");                                                  // ignored
    b.surface(PrimType::Sphere, {0, 0, 0, 0}, kVoid, "dot");              // line 2
    b.surface(PrimType::Cylinder, {0, 0, 0, 0, 0, 0, 1}, kVoid, "flat");  // line 3
    b.surface(PrimType::Cone, {0, 0, 0, 0, 0, 1, 0, 0}, kVoid, "needle");
    b.surface(PrimType::Ring, {0, 0, 0, 0, 0, 1, 1, 1}, kVoid, "thin");
    b.surface(PrimType::Ring, {0, 0, 0, 0, 0, 0, 0, 1}, kVoid, "nodir");
    b.surface(PrimType::Polygon, {0, 0, 0, 1, 0, 0, 2, 0, 0}, kVoid, "line");
    b.surface(PrimType::Source, {0, 0, 0, 1}, kVoid, "nowhere");
    ShapeSet s = buildShapes(b.scene());
    EXPECT_TRUE(s.spheres.empty());
    EXPECT_TRUE(s.cones.empty());
    EXPECT_TRUE(s.rings.empty());
    EXPECT_TRUE(s.polygons.empty());
    EXPECT_TRUE(s.triangles.empty());
    EXPECT_TRUE(s.sources.empty());
    EXPECT_TRUE(w.any("test.rad:2: sphere 'dot': zero radius"));
    EXPECT_TRUE(w.any("test.rad:3: cylinder 'flat'"));
    EXPECT_TRUE(w.any("cone 'needle': illegal radii"));
    EXPECT_TRUE(w.any("ring 'thin': illegal radii"));
    EXPECT_TRUE(w.any("ring 'nodir'"));
    EXPECT_TRUE(w.any("polygon 'line': zero area"));
    EXPECT_TRUE(w.any("source 'nowhere'"));
    EXPECT_EQ(w.lines.size(), 7u);
}

TEST(Shapes, NegativeRadiiFlipOrientation) {
    WarningCapture w;
    SceneBuilder b;
    b.surface(PrimType::Sphere, {0, 0, 0, -1});
    b.surface(PrimType::Cylinder, {0, 0, 0, 0, 0, 1, -1});
    b.surface(PrimType::Cone, {0, 0, 0, 0, 0, 1, -2, -1});
    b.surface(PrimType::Ring, {0, 0, 0, 0, 0, 1, 2, 1});  // radii given outer first
    ShapeSet s = buildShapes(b.scene());
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_TRUE(s.spheres[0].inward);
    EXPECT_EQ(s.spheres[0].radius, 1);
    ASSERT_EQ(s.cones.size(), 2u);
    EXPECT_TRUE(s.cones[0].inward);
    EXPECT_TRUE(s.cones[1].inward);
    EXPECT_EQ(s.cones[1].r0, 2);
    ASSERT_EQ(s.rings.size(), 1u);
    EXPECT_EQ(s.rings[0].r0, 1);
    EXPECT_EQ(s.rings[0].r1, 2);
    EXPECT_EQ(w.lines.size(), 3u);
}

TEST(Shapes, NonPlanarPolygonWarns) {
    WarningCapture w;
    SceneBuilder b;
    b.surface(PrimType::Polygon, {0, 0, 0, 1, 0, 0, 1, 1, 0.1, 0, 1, 0}, kVoid, "warp");
    ShapeSet s = buildShapes(b.scene());
    EXPECT_EQ(s.polygons.size(), 1u);
    EXPECT_TRUE(w.any("polygon 'warp': non-planar vertex"));
}

// RADIANCE's tolerance is relative to the plane's distance from the origin (face.c):
// which of these warn is what RADIANCE 5.4a's `oconv` says of the same polygons
// (warnings for wall1e3, wall2e4 and floor5e5 only).
TEST(Shapes, NonPlanarToleranceIsRadiances) {
    WarningCapture w;
    SceneBuilder b;
    auto wall = [&](double off, const char* name) {
        b.surface(PrimType::Polygon, {0, 3, 0, 4, 3, 0, 4, 3 + off, 3, 0, 3, 3}, kVoid, name);
    };
    auto floor = [&](double off, const char* name) {
        b.surface(PrimType::Polygon, {0, 0, 0, 4, 0, 0, 4, 4, off, 0, 4, 0}, kVoid, name);
    };
    wall(7e-6, "wall7e6");
    wall(5e-5, "wall5e5");
    wall(2e-4, "wall2e4");
    wall(1e-3, "wall1e3");
    floor(5e-6, "floor5e6");
    floor(2e-5, "floor2e5");
    floor(5e-5, "floor5e5");
    buildShapes(b.scene());
    for (const char* quiet : {"wall7e6", "wall5e5", "floor5e6", "floor2e5"})
        EXPECT_FALSE(w.any(std::string("'") + quiet + "'")) << quiet;
    for (const char* loud : {"wall2e4", "wall1e3", "floor5e5"})
        EXPECT_TRUE(w.any(std::string("polygon '") + loud + "': non-planar vertex")) << loud;
}

TEST(Shapes, ModifiersAreIgnoredAndPrimIndicesKept) {
    SceneBuilder b;
    int32_t m = b.material("m");
    b.material("glass", PrimType::Glass);
    int32_t sph = b.surface(PrimType::Sphere, {0, 0, 0, 1}, m);
    ShapeSet s = buildShapes(b.scene());
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_EQ(s.spheres[0].prim, sph);
    EXPECT_EQ(s.spheres[0].modifier, m);
}

TEST(Sources, DirectionQueryUsesAngularRadius) {
    SceneBuilder b;
    b.surface(PrimType::Polygon, {0, 0, 0, 1, 0, 0, 0, 1, 0});
    b.surface(PrimType::Source, {0, 0, 2, 10}, kVoid, "sun");   // 10 degree disk
    b.surface(PrimType::Source, {0, 0, 1, 180}, kVoid, "sky");  // upper hemisphere
    SceneGeometry g(b.scene());
    ASSERT_EQ(g.sources().size(), 2u);
    const DistantSource& sun = g.sources()[0];
    EXPECT_EQ(sun.prim, 1);
    EXPECT_NEAR(sun.solidAngle, 2 * kPi * (1 - std::cos(5 * kPi / 180)), 1e-8);  // a float
    EXPECT_NEAR(g.sources()[1].solidAngle, 2 * kPi, 1e-6);
    auto at = [](double deg) {
        double a = deg * kPi / 180;
        return Vec3{std::sin(a), 0, std::cos(a)};
    };
    EXPECT_EQ(g.sourcesInDirection(at(0)), (std::vector<int32_t>{0, 1}));
    EXPECT_EQ(g.sourcesInDirection(at(4.99)), (std::vector<int32_t>{0, 1}));
    EXPECT_EQ(g.sourcesInDirection(at(5.01)), (std::vector<int32_t>{1}));
    EXPECT_EQ(g.sourcesInDirection(at(89.9)), (std::vector<int32_t>{1}));
    EXPECT_TRUE(g.sourcesInDirection(at(90.1)).empty());
    // Exactly along the horizon a 180 degree glow is seen, as in RADIANCE (issue 43:
    // `echo "0 0 0 1 0 0" | rtrace -h -ab 0` gives the glow's 10, not 0).
    EXPECT_EQ(g.sourcesInDirection(Vec3{1, 0, 0}), (std::vector<int32_t>{1}));
    EXPECT_EQ(g.sourcesInDirection(Vec3{0, -1, 0}), (std::vector<int32_t>{1}));
    // Sources are not surfaces: nothing to hit in their direction.
    EXPECT_FALSE(g.closestHit({{5, 5, 1}, {0, 0, 1}}));
}

TEST(Bounds, SceneBoundsAndRadianceCube) {
    SceneBuilder b;
    b.surface(PrimType::Polygon, {0, 0, 0, 2, 0, 0, 2, 1, 0});
    b.surface(PrimType::Sphere, {1, 0.5, 0.5, 0.5});
    b.surface(PrimType::Source, {0, 0, 1, 0.5});  // no extent
    SceneGeometry g(b.scene());
    EXPECT_EQ(g.bounds().min, (Vec3{0, 0, 0}));
    EXPECT_EQ(g.bounds().max, (Vec3{2, 1, 1}));
    SceneCube c = g.sceneCube();
    // oconv: margin 1e-5 each side, side = largest extent, centred.
    EXPECT_NEAR(c.size, 2 + 2e-5, 1e-15);
    EXPECT_NEAR(c.origin.x, -1e-5, 1e-15);
    EXPECT_NEAR(c.origin.y, -0.5 - 1e-5, 1e-15);
    EXPECT_NEAR(c.origin.z, -0.5 - 1e-5, 1e-15);
}

TEST(Bounds, ConeAndRingBoundsAreTight) {
    SceneBuilder b;
    b.surface(PrimType::Cylinder, {0, 0, 0, 0, 0, 2, 1});
    b.surface(PrimType::Ring, {5, 0, 0, 1, 0, 0, 0, 2});
    ShapeSet s = buildShapes(b.scene());
    Bounds3 cb = coneBounds(s.cones[0]);
    EXPECT_EQ(cb.min, (Vec3{-1, -1, 0}));
    EXPECT_EQ(cb.max, (Vec3{1, 1, 2}));
    Bounds3 rb = ringBounds(s.rings[0]);
    EXPECT_EQ(rb.min, (Vec3{5, -2, -2}));
    EXPECT_EQ(rb.max, (Vec3{5, 2, 2}));
}

}  // namespace
}  // namespace rp
