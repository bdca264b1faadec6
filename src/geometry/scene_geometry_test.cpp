// Closed-form hits for every traced primitive type (distance, point, normal orientation,
// front flag, u/v), grazing rays, holes, the modifier skip set and occlusion.
// Tolerances: 1e-12 relative for quadrics (double throughout); polygons too, since hits
// are recomputed in double against the exact plane.
#include "geometry/scene_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/test_scenes.h"
#include "util/rng.h"

namespace rp {
namespace {

using testing::SceneBuilder;

constexpr double kTol = 1e-12;

void expectVec(const Vec3& a, const Vec3& b, double tol = kTol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Axis-aligned square in z = z0, counter-clockwise seen from +z (normal +z) unless flip.
std::vector<double> square(double x0, double y0, double x1, double y1, double z0,
                           bool flip = false) {
    if (flip) return {x0, y0, z0, x0, y1, z0, x1, y1, z0, x1, y0, z0};
    return {x0, y0, z0, x1, y0, z0, x1, y1, z0, x0, y1, z0};
}

TEST(Polygon, HitFromFrontAndBack) {
    SceneBuilder b;
    int32_t mat = b.material("white");
    int32_t sq = b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 0), mat);
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{0.25, 0.5, 5}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5, kTol);
    expectVec(h->point, {0.25, 0.5, 0});
    expectVec(h->normal, {0, 0, 1});
    EXPECT_TRUE(h->front);
    EXPECT_EQ(h->prim, sq);
    EXPECT_EQ(h->modifier, mat);
    EXPECT_EQ(h->u, 0);  // RADIANCE uv: meshes only
    EXPECT_EQ(h->v, 0);  // RADIANCE uv: meshes only

    auto back = g.closestHit({{0.25, 0.5, -2}, {0, 0, 1}});
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->t, 2, kTol);
    expectVec(back->normal, {0, 0, 1});  // not flipped toward the ray
    EXPECT_FALSE(back->front);

    EXPECT_FALSE(g.closestHit({{1.5, 0, 5}, {0, 0, -1}}));     // outside
    EXPECT_FALSE(g.closestHit({{0, 0, 5}, {0, 0, 1}}));        // pointing away
    EXPECT_FALSE(g.closestHit({{0, 0, 5}, {0, 0, -1}, 4.9}));  // beyond tmax
}

TEST(Polygon, ClockwiseVerticesFaceDown) {
    SceneBuilder b;
    b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 0, /*flip=*/true));
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{0, 0.5, 1}, {0, 0, -1}});
    ASSERT_TRUE(h);
    expectVec(h->normal, {0, 0, -1});
    EXPECT_FALSE(h->front);
}

TEST(Polygon, ObliqueHitIsExact) {
    SceneBuilder b;
    // Plane x + y + z = 1 through the three unit points, normal (1,1,1)/sqrt(3).
    b.surface(PrimType::Polygon, {1, 0, 0, 0, 1, 0, 0, 0, 1});
    SceneGeometry g(b.scene());
    Vec3 d = normalize(Vec3{1, 2, 3});
    auto h = g.closestHit({{0, 0, 0}, d});
    ASSERT_TRUE(h);
    double t = 1 / dot(Vec3{1, 1, 1}, d);  // dot(n, o + t d) = offset
    EXPECT_NEAR(h->t, t, kTol);
    expectVec(h->normal, normalize(Vec3{1, 1, 1}));
    EXPECT_FALSE(h->front);
}

TEST(Polygon, GrazingAlongPlaneMisses) {
    SceneBuilder b;
    b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 0));
    SceneGeometry g(b.scene());
    // RADIANCE compat (o_face): a ray in the polygon's plane does not hit it.
    EXPECT_FALSE(g.closestHit({{-5, 0, 0}, {1, 0, 0}}));
    EXPECT_FALSE(g.closestHit({{-5, -1, 0}, {1, 0, 0}}));  // along an edge
    EXPECT_FALSE(g.occluded({-5, 0.3, 0}, {1, 0, 0}, 100));
}

TEST(Polygon, SharedEdgeOfTriangulationNeitherLeaksNorDoubleHits) {
    SceneBuilder b;
    int32_t sq = b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 0));
    int32_t floor = b.surface(PrimType::Polygon, square(-10, -10, 10, 10, -1));
    SceneGeometry g(b.scene());
    // The square is fanned from vertex 0: its diagonal y = x is shared by two triangles.
    for (int i = -50; i <= 50; ++i) {
        double s = i / 51.0;
        for (double e : {0.0, 1e-17, -1e-17, 1e-9, -1e-9}) {
            Vec3 d = normalize(Vec3{0.01 * i, -0.02, -1});
            Vec3 target{s + e, s, 0};
            auto h = g.closestHit({target - d * 3, d});
            ASSERT_TRUE(h) << "leak at s=" << s << " e=" << e;
            EXPECT_EQ(h->prim, sq);
            auto next = g.closestHit(spawnRay(*h, d));
            ASSERT_TRUE(next);
            EXPECT_EQ(next->prim, floor) << "double hit at s=" << s;
        }
    }
}

TEST(Polygon, SharedEdgeAndVertexBetweenPolygons) {
    SceneBuilder b;
    // Four unit squares meeting at the origin.
    b.surface(PrimType::Polygon, square(-1, -1, 0, 0, 0));
    b.surface(PrimType::Polygon, square(0, -1, 1, 0, 0));
    b.surface(PrimType::Polygon, square(0, 0, 1, 1, 0));
    b.surface(PrimType::Polygon, square(-1, 0, 0, 1, 0));
    SceneGeometry g(b.scene());
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{0, 0.5, 0}, Vec3{0.5, 0, 0}, Vec3{-0.3, 0, 0}}) {
        for (Vec3 d : {Vec3{0, 0, -1}, normalize(Vec3{1, 1, -1}), normalize(Vec3{-3, 1, -2})}) {
            auto h = g.closestHit({p - d * 2, d});
            ASSERT_TRUE(h) << p.x << " " << p.y;
            EXPECT_NEAR(h->t, 2, kTol);
            auto next = g.closestHit(spawnRay(*h, d));
            EXPECT_FALSE(next);
        }
    }
}

// A 10 x 3 m wall in the plane y = 0 with a 4 x 1.8 m window cut by RADIANCE's seam
// convention, and coplanar glass in the window. Rays through the window must reach the
// glass (the wall covers none of the hole, so there is no tie at equal distance), and
// rays beside it the wall, whatever else is in the scene. Cut with and without the
// seam's repeated return vertex, with slats behind the window or not.
std::vector<double> xz(std::initializer_list<std::pair<double, double>> pts) {
    std::vector<double> r;
    for (auto [x, z] : pts) r.insert(r.end(), {x, 0, z});
    return r;
}

TEST(Polygon, RaysThroughASeamCutWindowHitTheGlass) {
    for (bool returnVertex : {true, false})
        for (int clutter : {0, 1, 2}) {
            SceneBuilder b;
            int32_t wallMat = b.material("wall"), glassMat = b.material("glass");
            std::vector<double> wall = xz({{0, 0},
                                           {0, 3},
                                           {10, 3},
                                           {10, 0},
                                           {0, 0},
                                           {3, 0.9},
                                           {7, 0.9},
                                           {7, 2.7},
                                           {3, 2.7},
                                           {3, 0.9}});
            if (returnVertex) wall.insert(wall.end(), {0, 0, 0});
            int32_t wallId = b.surface(PrimType::Polygon, wall, wallMat);
            int32_t glassId = b.surface(PrimType::Polygon,
                                        xz({{3, 0.9}, {3, 2.7}, {7, 2.7}, {7, 0.9}}), glassMat);
            for (int k = 0; k < 20 * clutter; ++k) {  // blind slats 0.1 m behind the glass
                double z = 0.9 + 0.09 * k;
                b.surface(PrimType::Polygon,
                          {3, 0.1, z, 7, 0.1, z, 7, 0.15, z - 0.01, 3, 0.15, z - 0.01});
            }
            SceneGeometry g(b.scene());
            int wallHits = 0, glassHits = 0;
            for (int i = 0; i < 7; ++i)
                for (int j = 0; j < 7; ++j) {
                    Vec3 target{3 + 4 * (i + 0.5) / 7, 0, 0.9 + 1.8 * (j + 0.5) / 7};
                    Vec3 from{target.x - 0.3, -4, target.z + 0.2};
                    auto h = g.closestHit({from, normalize(target - from)});
                    ASSERT_TRUE(h);
                    wallHits += h->prim == wallId;
                    glassHits += h->prim == glassId;
                }
            EXPECT_EQ(glassHits, 49) << "return vertex " << returnVertex << ", clutter " << clutter;
            EXPECT_EQ(wallHits, 0);
            for (Vec3 beside :
                 {Vec3{1, 0, 1.5}, Vec3{8.5, 0, 2}, Vec3{5, 0, 0.4}, Vec3{5, 0, 2.85}}) {
                auto h = g.closestHit({beside - Vec3{0, 4, 0}, {0, 1, 0}});
                ASSERT_TRUE(h);
                EXPECT_EQ(h->prim, wallId);
            }
        }
}

TEST(Polygon, ConcaveNotchMisses) {
    SceneBuilder b;
    b.surface(PrimType::Polygon, {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0});
    SceneGeometry g(b.scene());
    EXPECT_TRUE(g.closestHit({{0.5, 1.5, 1}, {0, 0, -1}}));
    EXPECT_TRUE(g.closestHit({{1.5, 0.5, 1}, {0, 0, -1}}));
    EXPECT_FALSE(g.closestHit({{1.5, 1.5, 1}, {0, 0, -1}}));
}

TEST(Polygon, RayThroughHoleMisses) {
    SceneBuilder b;
    // RADIANCE-style: outline, seam in, hole clockwise, seam out (ray.html, Polygon).
    b.surface(PrimType::Polygon, {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 0, 0, 0,
                                  1, 1, 0, 1, 3, 0, 3, 3, 0, 3, 1, 0, 1, 1, 0});
    SceneGeometry g(b.scene());
    EXPECT_FALSE(g.closestHit({{2, 2, 1}, {0, 0, -1}}));
    EXPECT_FALSE(g.closestHit({{1.01, 2.99, 1}, {0, 0, -1}}));
    auto h = g.closestHit({{0.5, 2, 1}, {0, 0, -1}});
    ASSERT_TRUE(h);
    expectVec(h->normal, {0, 0, 1});
    EXPECT_TRUE(g.closestHit({{3.5, 3.5, 1}, {0, 0, -1}}));
    // Along the seam itself (x = y, between the outline and the hole): surface on both
    // sides, so the ray must not leak.
    EXPECT_TRUE(g.closestHit({{0.5, 0.5, 1}, {0, 0, -1}}));
}

TEST(Sphere, OutsideInsideTangent) {
    SceneBuilder b;
    int32_t s = b.surface(PrimType::Sphere, {1, 2, 3, 2});
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{1, 2, -7}, {0, 0, 1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, s);
    EXPECT_NEAR(h->t, 8, kTol);
    expectVec(h->point, {1, 2, 1});
    expectVec(h->normal, {0, 0, -1});
    EXPECT_TRUE(h->front);
    EXPECT_EQ(h->v, 0);  // RADIANCE uv: meshes only

    auto in = g.closestHit({{1, 2, 3}, {1, 0, 0}});
    ASSERT_TRUE(in);
    EXPECT_NEAR(in->t, 2, kTol);
    expectVec(in->normal, {1, 0, 0});
    EXPECT_FALSE(in->front);
    EXPECT_EQ(in->u, 0);  // RADIANCE uv: meshes only
    EXPECT_EQ(in->v, 0);  // RADIANCE uv: meshes only
    auto side = g.closestHit({{1, 2, 3}, {0, 1, 0}});
    ASSERT_TRUE(side);
    EXPECT_EQ(side->u, 0);  // RADIANCE uv: meshes only

    // Exactly tangent: a zero-measure graze counts as a miss; just inside it hits.
    EXPECT_FALSE(g.closestHit({{3, 2, -7}, {0, 0, 1}}));
    auto graze = g.closestHit({{3 - 1e-9, 2, -7}, {0, 0, 1}});
    ASSERT_TRUE(graze);
    EXPECT_NEAR(graze->t, 10, 1e-3);
    EXPECT_NEAR(graze->normal.x, 1, 1e-3);
    EXPECT_FALSE(g.closestHit({{3 + 1e-9, 2, -7}, {0, 0, 1}}));
}

TEST(Sphere, BubbleFacesInward) {
    SceneBuilder b;
    b.surface(PrimType::Bubble, {1, 2, 3, 2});
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{1, 2, -7}, {0, 0, 1}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 8, kTol);
    expectVec(h->normal, {0, 0, 1});
    EXPECT_FALSE(h->front);
    auto in = g.closestHit({{1, 2, 3}, {-1, 0, 0}});
    ASSERT_TRUE(in);
    expectVec(in->normal, {1, 0, 0});
    EXPECT_TRUE(in->front);
}

TEST(Cone, TruncatedAtBothEnds) {
    SceneBuilder b;
    // Axis (0,0,0) -> (0,0,2), radius 2 at the bottom, 1 at the top: slope -1/2.
    int32_t c = b.surface(PrimType::Cone, {0, 0, 0, 0, 0, 2, 2, 1});
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{5, 0, 1}, {-1, 0, 0}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, c);
    EXPECT_NEAR(h->t, 3.5, kTol);  // radius 1.5 at height 1
    expectVec(h->point, {1.5, 0, 1});
    expectVec(h->normal, normalize(Vec3{2, 0, 1}));  // outward, tilted up
    EXPECT_TRUE(h->front);
    EXPECT_EQ(h->v, 0);  // RADIANCE uv: meshes only

    auto in = g.closestHit({{0, 0, 1}, {1, 0, 0}});  // from inside
    ASSERT_TRUE(in);
    EXPECT_NEAR(in->t, 1.5, kTol);
    EXPECT_FALSE(in->front);

    EXPECT_FALSE(g.closestHit({{5, 0, 2.5}, {-1, 0, 0}}));   // above the top end
    EXPECT_FALSE(g.closestHit({{5, 0, -0.5}, {-1, 0, 0}}));  // below the bottom end
    EXPECT_FALSE(g.closestHit({{0.5, 0, 5}, {0, 0, -1}}));   // through both open ends
    // Oblique ray entering the top opening and leaving through the side.
    Vec3 d = normalize(Vec3{1, 0, -1});
    auto ob = g.closestHit({{0, 0, 3}, d});
    ASSERT_TRUE(ob);
    // x = s, z = 3 - s on r = 2 - z/2 -> s = 2 - (3 - s)/2 -> s = 1.
    expectVec(ob->point, {1, 0, 2}, 1e-12);
    ob = g.closestHit({{0, 0, 2.5}, d});  // x = s, z = 2.5 - s: s = 0.75 + s/2 -> 1.5
    ASSERT_TRUE(ob);
    expectVec(ob->point, {1.5, 0, 1}, 1e-12);
    EXPECT_FALSE(ob->front);
}

TEST(Cone, CupFacesInwardAndApexCone) {
    SceneBuilder b;
    b.surface(PrimType::Cup, {0, 0, 0, 0, 0, 2, 2, 1});
    b.surface(PrimType::Cone, {10, 0, 0, 10, 0, 1, 1, 0});  // comes to a point at z = 1
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{5, 0, 1}, {-1, 0, 0}});
    ASSERT_TRUE(h);
    expectVec(h->normal, -normalize(Vec3{2, 0, 1}));
    EXPECT_FALSE(h->front);
    auto apex = g.closestHit({{12, 0, 0.5}, {-1, 0, 0}});
    ASSERT_TRUE(apex);
    EXPECT_NEAR(apex->t, 1.5, kTol);  // radius 0.5 at half height
    expectVec(apex->normal, normalize(Vec3{1, 0, 1}));
}

TEST(Cylinder, CylinderAndTube) {
    SceneBuilder b;
    b.surface(PrimType::Cylinder, {0, 0, -1, 0, 0, 1, 1});
    b.surface(PrimType::Tube, {0, 10, -1, 0, 10, 1, 1});
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{3, 0, 0}, {-1, 0, 0}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2, kTol);
    expectVec(h->normal, {1, 0, 0});
    EXPECT_TRUE(h->front);
    EXPECT_EQ(h->v, 0);  // RADIANCE uv: meshes only
    auto t = g.closestHit({{3, 10, 0}, {-1, 0, 0}});
    ASSERT_TRUE(t);
    expectVec(t->normal, {-1, 0, 0});
    EXPECT_FALSE(t->front);

    EXPECT_FALSE(g.closestHit({{0.5, 0, -5}, {0, 0, 1}}));  // along the axis, inside
    EXPECT_FALSE(g.closestHit({{1, 0, -5}, {0, 0, 1}}));    // along the surface line
    Vec3 d = normalize(Vec3{1, 0, 0.5});
    auto ob = g.closestHit({{0, 0, 0}, d});
    ASSERT_TRUE(ob);
    EXPECT_NEAR(ob->t, std::sqrt(1.25), kTol);
    EXPECT_EQ(ob->v, 0);                                                // RADIANCE uv: meshes only
    EXPECT_FALSE(g.closestHit({{0, 0, 0}, normalize(Vec3{1, 0, 3})}));  // out the top
}

TEST(Ring, AnnulusAndDisk) {
    SceneBuilder b;
    int32_t r = b.surface(PrimType::Ring, {0, 0, 1, 0, 0, 2, 0.5, 1});
    b.surface(PrimType::Ring, {5, 0, 0, 0, 0, -1, 0, 1});  // a disk facing down
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{0.75, 0, 3}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, r);
    EXPECT_NEAR(h->t, 2, kTol);
    expectVec(h->normal, {0, 0, 1});
    EXPECT_TRUE(h->front);
    EXPECT_EQ(h->v, 0);  // RADIANCE uv: meshes only
    auto below = g.closestHit({{0, -0.75, -3}, {0, 0, 1}});
    ASSERT_TRUE(below);
    EXPECT_FALSE(below->front);
    EXPECT_FALSE(g.closestHit({{0.25, 0, 3}, {0, 0, -1}}));  // inner hole
    EXPECT_FALSE(g.closestHit({{1.5, 0, 3}, {0, 0, -1}}));   // outside
    EXPECT_FALSE(g.closestHit({{-5, 0, 1}, {1, 0, 0}}));     // in its plane
    auto disk = g.closestHit({{5, 0, -1}, {0, 0, 1}});
    ASSERT_TRUE(disk);
    expectVec(disk->normal, {0, 0, -1});
    EXPECT_TRUE(disk->front);
}

TEST(Query, SkipModifiersPassesThrough) {
    SceneBuilder b;
    int32_t top = b.material("top");
    int32_t ball = b.material("ball", PrimType::Antimatter);
    int32_t bottom = b.material("bottom");
    b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 2), top);
    int32_t sphere = b.surface(PrimType::Sphere, {0, 0, 1, 0.5}, ball);
    int32_t floor = b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 0), bottom);
    SceneGeometry g(b.scene());
    Ray down{{0, 0, 5}, {0, 0, -1}};
    ModifierSet skipTop{top};
    auto h = g.closestHit(down, &skipTop);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, sphere);
    ModifierSet skipBoth{top, ball};
    h = g.closestHit(down, &skipBoth);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, floor);
    ModifierSet skipAll{top, ball, bottom};
    EXPECT_FALSE(g.closestHit(down, &skipAll));
    ModifierSet empty;
    EXPECT_EQ(g.closestHit(down, &empty)->modifier, top);

    EXPECT_TRUE(g.occluded({0, 0, 5}, {0, 0, -1}, 10));
    EXPECT_TRUE(g.occluded({0, 0, 5}, {0, 0, -1}, 10, &skipBoth));
    EXPECT_FALSE(g.occluded({0, 0, 5}, {0, 0, -1}, 10, &skipAll));
    EXPECT_FALSE(g.occluded({0, 0, 1.2}, {0, 0, 1}, 0.5, &skipBoth));  // hole in skip
}

TEST(Query, OcclusionRespectsTmax) {
    SceneBuilder b;
    b.surface(PrimType::Polygon, square(-1, -1, 1, 1, 0));
    b.surface(PrimType::Sphere, {0, 0, 5, 1});
    SceneGeometry g(b.scene());
    EXPECT_TRUE(g.occluded({0, 0, -1}, {0, 0, 1}, 1.5));
    EXPECT_FALSE(g.occluded({0, 0, -1}, {0, 0, 1}, 0.5));
    EXPECT_FALSE(g.occluded({0, 0, 1}, {0, 0, 1}, 2.9));
    EXPECT_TRUE(g.occluded({0, 0, 1}, {0, 0, 1}, 3.1));
    EXPECT_TRUE(g.occluded({0, 0, 1}, {0, 0, -1}, HUGE_VAL));
    EXPECT_FALSE(g.occluded({3, 0, 1}, {0, 0, 1}, HUGE_VAL));
}

TEST(Query, NearestOfMixedShapes) {
    SceneBuilder b;
    int32_t ring = b.surface(PrimType::Ring, {0, 0, 4, 0, 0, 1, 0, 3});
    int32_t sph = b.surface(PrimType::Sphere, {0, 0, 2, 1});
    int32_t poly = b.surface(PrimType::Polygon, square(-3, -3, 3, 3, 0));
    SceneGeometry g(b.scene());
    EXPECT_EQ(g.closestHit({{0, 0, 10}, {0, 0, -1}})->prim, ring);
    EXPECT_EQ(g.closestHit({{0, 0, 3.5}, {0, 0, -1}})->prim, sph);
    EXPECT_EQ(g.closestHit({{0, 0, 0.5}, {0, 0, -1}})->prim, poly);
    EXPECT_EQ(g.closestHit({{0, 0, 0.5}, {0, 0, 1}})->prim, sph);
}

// Scenes with more analytic shapes than embree_accel.cpp tests directly (kDirectShapes = 4)
// give them to Embree as user geometry: five tiny spheres (or disks) far from everything.
void addFarShapes(SceneBuilder& b, PrimType type = PrimType::Sphere) {
    for (int i = 0; i < 5; ++i)
        b.surface(type, type == PrimType::Ring
                            ? std::vector<double>{100.0 + 3 * i, 100, 100, 0, 0, 1, 0, 0.5}
                            : std::vector<double>{100.0 + 3 * i, 100, 100, 0.5});
}

// A few analytic shapes are tested directly, many go through Embree's user geometry
// (embree_accel.cpp kDirectShapes): both must give the same hits, the same distances and
// the same occlusion, with and without a skipped modifier.
TEST(Query, DirectShapesAgreeWithEmbreeUserGeometry) {
    auto build = [](bool many) {
        SceneBuilder b;
        int32_t glass = b.material("glass");
        int32_t tube = b.material("tube");
        b.surface(PrimType::Polygon, square(-3, -3, 3, 3, 0));
        b.surface(PrimType::Sphere, {0.5, 0, 1, 0.8}, glass);
        b.surface(PrimType::Cone, {-1, -1, 0, -1, -1, 2, 0.6, 0.2}, tube);
        b.surface(PrimType::Ring, {1, 1, 1.5, 0, 0.6, 0.8, 0.2, 0.7});
        if (many) addFarShapes(b);
        return b.scene();
    };
    const Scene fewScene = build(false), manyScene = build(true);
    const SceneGeometry few(fewScene), many(manyScene);
    const ModifierSet skipGlass{0};
    Rng rng(17, RngDomain::Test, 0);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 o{6 * rng.uniform() - 3, 6 * rng.uniform() - 3, 3 * rng.uniform()};
        const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
        const double r = std::sqrt(1 - z * z);
        const Ray ray{o, {r * std::cos(phi), r * std::sin(phi), z}};
        const ModifierSet* skip = i % 2 ? &skipGlass : nullptr;
        const auto a = few.closestHit(ray, skip), b = many.closestHit(ray, skip);
        ASSERT_EQ(bool(a), bool(b)) << i;
        if (a) {
            ++hits;
            EXPECT_EQ(a->prim, b->prim) << i;
            EXPECT_EQ(a->t, b->t) << i;
        }
        const double tmax = 4 * rng.uniform();
        EXPECT_EQ(few.occluded(o, ray.dir, tmax, skip), many.occluded(o, ray.dir, tmax, skip)) << i;
    }
    EXPECT_GT(hits, 1000);
}

// A lone quadric in Embree's user geometry gets a never-hit stand-in primitive, a small box
// centred at max + (max - min) + (1,1,1) of its bounds, so that Embree's tree culls rays
// missing the shape's box (embree_accel.cpp). Rays through that box reach the stand-in's
// callback and must find nothing; the shape still hits. Far shapes of another family put
// the shape in Embree (addFarShapes).
TEST(Query, LoneShapeStandInIsNeverHit) {
    struct Case {
        PrimType type;
        std::vector<double> args;
        Ray hitting;
    };
    const Case cases[] = {
        {PrimType::Sphere, {1, 2, 3, 2}, {{1, 2, -7}, {0, 0, 1}}},
        {PrimType::Cone, {0, 0, 0, 0, 0, 2, 2, 1}, {{5, 0, 1}, {-1, 0, 0}}},
        {PrimType::Ring, {0, 0, 1, 0, 0, 2, 0.5, 1}, {{0.75, 0, 3}, {0, 0, -1}}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(primTypeName(c.type));
        SceneBuilder b;
        int32_t s = b.surface(c.type, c.args);
        const Bounds3 box = SceneGeometry(b.scene()).bounds();  // the lone shape's own box
        addFarShapes(b, c.type == PrimType::Sphere ? PrimType::Ring : PrimType::Sphere);
        SceneGeometry g(b.scene());
        const Vec3 standIn = box.max + (box.max - box.min) + Vec3{1, 1, 1};
        for (const Vec3& d : {Vec3{0, 0, -1}, Vec3{0, -1, 0}, Vec3{-1, 0, 0}}) {
            const Vec3 o = standIn - d * 10;
            EXPECT_FALSE(g.closestHit({o, d}));
            EXPECT_FALSE(g.occluded(o, d, 20));
        }
        auto h = g.closestHit(c.hitting);
        ASSERT_TRUE(h);
        EXPECT_EQ(h->prim, s);
        EXPECT_TRUE(g.occluded(c.hitting.origin, c.hitting.dir, 20));
    }
}

TEST(Query, EmptyScene) {
    Scene s;
    SceneGeometry g(s);
    EXPECT_FALSE(g.closestHit({{0, 0, 0}, {0, 0, 1}}));
    EXPECT_FALSE(g.occluded({0, 0, 0}, {0, 0, 1}, 1));
    EXPECT_TRUE(g.bounds().empty());
    EXPECT_EQ(g.sceneCube().size, 0);
}

}  // namespace
}  // namespace rp
