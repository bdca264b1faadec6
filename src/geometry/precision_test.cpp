// Robustness of secondary rays (spawnRay) far from the origin and at millimetre scale,
// and thread-safety of the queries (parallel answers identical to serial ones).
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <random>
#include <vector>

#include "geometry/scene_geometry.h"
#include "geometry/test_scenes.h"

namespace rp {
namespace {

using testing::SceneBuilder;

// Closed box [c - h, c + h]^3 of six polygons, normals facing inward.
void addBox(SceneBuilder& b, const Vec3& c, double h) {
    auto P = [&](double x, double y, double z) { return c + Vec3{x, y, z} * h; };
    auto quad = [&](Vec3 a, Vec3 bb, Vec3 cc, Vec3 d) {
        b.surface(PrimType::Polygon,
                  {a.x, a.y, a.z, bb.x, bb.y, bb.z, cc.x, cc.y, cc.z, d.x, d.y, d.z});
    };
    quad(P(-1, -1, -1), P(1, -1, -1), P(1, 1, -1), P(-1, 1, -1));  // floor, faces +z
    quad(P(-1, -1, 1), P(-1, 1, 1), P(1, 1, 1), P(1, -1, 1));      // ceiling, faces -z
    quad(P(-1, -1, -1), P(-1, 1, -1), P(-1, 1, 1), P(-1, -1, 1));  // x = -1, faces +x
    quad(P(1, -1, -1), P(1, -1, 1), P(1, 1, 1), P(1, 1, -1));      // x = +1, faces -x
    quad(P(-1, -1, -1), P(-1, -1, 1), P(1, -1, 1), P(1, -1, -1));  // y = -1, faces +y
    quad(P(-1, 1, -1), P(1, 1, -1), P(1, 1, 1), P(-1, 1, 1));      // y = +1, faces -y
}

Vec3 randomDir(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    for (;;) {
        Vec3 d{u(rng), u(rng), u(rng)};
        double l = lengthSquared(d);
        if (l > 1e-6 && l <= 1) return d / std::sqrt(l);
    }
}

// A direction on the side of n given by `sign`, biased toward grazing angles.
Vec3 leavingDir(std::mt19937_64& rng, const Vec3& n, double sign) {
    Vec3 d = randomDir(rng);
    std::uniform_real_distribution<double> u(0, 1);
    if (u(rng) < 0.3) d = normalize(d - n * dot(d, n) + n * 1e-4);  // nearly tangent
    return dot(d, n) * sign >= 0 ? d : d - n * (2 * dot(d, n));
}

// Bounces a ray around inside a closed box for many diffuse/grazing reflections: every
// next hit must be another wall (a planar wall cannot see itself) at positive distance,
// and the ray must never escape.
void bounceInBox(const Vec3& centre, double half) {
    SceneBuilder b;
    addBox(b, centre, half);
    SceneGeometry g(b.scene());
    std::mt19937_64 rng(7);
    Ray ray{centre, randomDir(rng)};
    int32_t last = -1;
    for (int i = 0; i < 100000; ++i) {
        auto h = g.closestHit(ray);
        ASSERT_TRUE(h) << "escaped after " << i << " bounces";
        ASSERT_NE(h->prim, last) << "self-intersection at bounce " << i;
        ASSERT_TRUE(h->front);
        Vec3 rel = h->point - centre;
        // In-plane position is only as good as Embree's float edge test: a few ulps.
        ASSERT_LE(maxAbs(rel), half * (1 + 1e-9) + std::ldexp(maxAbs(centre), -21));
        last = h->prim;
        ray = spawnRay(*h, leavingDir(rng, h->normal, +1));
    }
}

TEST(Precision, BounceInBoxOneKilometreAway) { bounceInBox({1000, -1000, 1000}, 0.5); }
TEST(Precision, BounceInMillimetreBoxNearOrigin) { bounceInBox({0.003, 0.002, 0.001}, 0.0005); }
TEST(Precision, BounceInMillimetreBoxOneMetreAway) { bounceInBox({1, 1, 1}, 0.0005); }

// Inside a sphere, every spawned ray must reach the far side, at the distance from its
// (offset) origin o to the sphere: -b + sqrt(b^2 - (|o-c|^2 - r^2)) with b = (o-c).d,
// checked to 1e-9 of the radius (double rounding at 1 km is ~1e-13 relative).
void bounceInSphere(const Vec3& c, double r, PrimType type) {
    SceneBuilder b;
    b.surface(type, {c.x, c.y, c.z, r});
    SceneGeometry g(b.scene());
    std::mt19937_64 rng(11);
    Ray ray{c, randomDir(rng)};
    for (int i = 0; i < 50000; ++i) {
        auto h = g.closestHit(ray);
        ASSERT_TRUE(h) << "escaped after " << i;
        if (i > 0) {
            Vec3 oc = ray.origin - c;
            double bb = dot(oc, ray.dir), cc = dot(oc, oc) - r * r;
            ASSERT_LT(cc, 0) << "spawned origin left the sphere at bounce " << i;
            double expect = -bb + std::sqrt(bb * bb - cc);
            ASSERT_NEAR(h->t, expect, 1e-9 * r) << "bounce " << i;
        }
        Vec3 inward = type == PrimType::Sphere ? -h->normal : h->normal;
        ray = spawnRay(*h, leavingDir(rng, inward, +1));
    }
}

TEST(Precision, BounceInsideSphereOneKilometreAway) {
    bounceInSphere({1000, 1000, -1000}, 1, PrimType::Sphere);
    bounceInSphere({-1000, 0, 1000}, 0.5, PrimType::Bubble);
}
TEST(Precision, BounceInsideMillimetreSphere) {
    bounceInSphere({0, 0.001, 0}, 0.0005, PrimType::Sphere);
}

// Leaving a surface outward must not re-hit it, at 1 km, for polygons and quadrics.
TEST(Precision, LeavingSurfaceOneKilometreAway) {
    SceneBuilder b;
    Vec3 c{1000, 1000, 1000};
    b.surface(PrimType::Polygon, {c.x - 1, c.y - 1, c.z, c.x + 1, c.y - 1, c.z + 0.3, c.x + 1,
                                  c.y + 1, c.z + 0.6, c.x - 1, c.y + 1, c.z + 0.3});
    b.surface(PrimType::Sphere, {c.x + 5, c.y, c.z, 1});
    b.surface(PrimType::Cylinder, {c.x - 5, c.y, c.z - 1, c.x - 5, c.y, c.z + 1, 1});
    SceneGeometry g(b.scene());
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-0.9, 0.9);
    for (int i = 0; i < 3000; ++i) {
        Vec3 target = i % 3 == 0   ? c + Vec3{u(rng), u(rng), 0}
                      : i % 3 == 1 ? c + Vec3{5, 0, 0}
                                   : c + Vec3{-5, 0, 0};
        Vec3 d = randomDir(rng);
        auto h = g.closestHit({target - d * 10, d});
        if (!h) continue;
        // Reflect back to the side we came from, and transmit through.
        Vec3 n = h->normal;
        Vec3 refl = d - n * (2 * dot(d, n));
        auto r = g.closestHit(spawnRay(*h, refl));
        EXPECT_TRUE(!r || r->prim != h->prim || h->prim != 0) << "polygon re-hit itself";
        if (r && r->prim == h->prim) {
            EXPECT_GT(r->t, 1e-3);  // quadrics: a real chord only
        }
        EXPECT_FALSE(g.occluded(spawnRay(*h, refl).origin, refl, 0.01 * std::fabs(dot(refl, n))));
        auto tr = g.closestHit(spawnRay(*h, d));
        if (tr && tr->prim == h->prim) {
            EXPECT_GT(tr->t, 1e-3);
        }
    }
}

// Two parallel plates 10 micrometres apart: a ray leaving the lower plate upward must
// hit the upper one at the right distance, not tunnel through the gap.
TEST(Precision, ThinGapAtMillimetreScale) {
    SceneBuilder b;
    double gap = 1e-5, w = 0.001;
    int32_t lower = b.surface(PrimType::Polygon, {0, 0, 0, w, 0, 0, w, w, 0, 0, w, 0});
    int32_t upper = b.surface(PrimType::Polygon, {0, 0, gap, 0, w, gap, w, w, gap, w, 0, gap});
    SceneGeometry g(b.scene());
    auto h = g.closestHit({{w / 2, w / 2, 0.01}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, upper);
    h = g.closestHit({{w / 2, w / 2, gap / 2}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, lower);
    std::mt19937_64 rng(5);
    for (int i = 0; i < 1000; ++i) {
        Vec3 d = leavingDir(rng, {0, 0, 1}, +1);
        if (d.z < 0.05) continue;  // long flat paths may leave the 1 mm plates sideways
        Ray leave = spawnRay(*h, d);
        ASSERT_GT(leave.origin.z, 0);
        ASSERT_LT(leave.origin.z, 1e-3 * gap);  // the offset is far below the gap
        auto up = g.closestHit(leave);
        double expect = (gap - leave.origin.z) / d.z;
        if (!up) {
            Vec3 p = leave.origin + d * expect;
            EXPECT_TRUE(p.x < 0 || p.x > w || p.y < 0 || p.y > w);
            continue;
        }
        EXPECT_EQ(up->prim, upper);
        EXPECT_NEAR(up->t, expect, 1e-9 * expect + 1e-12);
    }
}

// Many rays in parallel give bit-identical answers to the serial loop.
TEST(Threads, ParallelMatchesSerial) {
    SceneBuilder b;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int i = 0; i < 400; ++i) {
        Vec3 c{u(rng), u(rng), u(rng)};
        Vec3 e1 = randomDir(rng), e2 = normalize(cross(e1, randomDir(rng)));
        std::vector<double> v;
        for (int k = 0; k < 7; ++k) {
            double a = 2 * kPi * k / 7, r = k % 2 ? 0.5 : 1.0;  // concave heptagon-star
            Vec3 p = c + e1 * (r * std::cos(a)) + e2 * (r * std::sin(a));
            v.insert(v.end(), {p.x, p.y, p.z});
        }
        b.surface(PrimType::Polygon, v);
        Vec3 s{u(rng), u(rng), u(rng)};
        switch (i % 4) {
            case 0:
                b.surface(PrimType::Sphere, {s.x, s.y, s.z, 0.5});
                break;
            case 1:
                b.surface(PrimType::Cone, {s.x, s.y, s.z, s.x + 1, s.y, s.z + 1, 0.5, 0.2});
                break;
            case 2:
                b.surface(PrimType::Ring, {s.x, s.y, s.z, 1, 2, 3, 0.2, 0.6});
                break;
            default:
                b.surface(PrimType::Tube, {s.x, s.y, s.z, s.x, s.y + 1, s.z, 0.3});
                break;
        }
    }
    SceneGeometry g(b.scene());
    const int n = 20000;
    std::vector<Ray> rays(n);
    for (Ray& r : rays) r = {{u(rng), u(rng), u(rng)}, randomDir(rng)};
    struct Answer {
        bool hit = false, occluded = false;
        double t = 0;
        int32_t prim = -1;
        Vec3 normal;
    };
    auto answer = [&](const Ray& r) {
        Answer a;
        if (auto h = g.closestHit(r)) {
            a.hit = true;
            a.t = h->t;
            a.prim = h->prim;
            a.normal = h->normal;
        }
        a.occluded = g.occluded(r.origin, r.dir, 5);
        return a;
    };
    std::vector<Answer> serial(n), parallel(n);
    for (int i = 0; i < n; ++i) serial[i] = answer(rays[i]);
    tbb::parallel_for(0, n, [&](int i) { parallel[i] = answer(rays[i]); });
    int hits = 0;
    for (int i = 0; i < n; ++i) {
        ASSERT_EQ(serial[i].hit, parallel[i].hit) << i;
        ASSERT_EQ(serial[i].t, parallel[i].t) << i;
        ASSERT_EQ(serial[i].prim, parallel[i].prim) << i;
        ASSERT_EQ(serial[i].normal, parallel[i].normal) << i;
        ASSERT_EQ(serial[i].occluded, parallel[i].occluded) << i;
        hits += serial[i].hit;
        // Occlusion within 5 agrees with the closest hit.
        ASSERT_EQ(serial[i].occluded, serial[i].hit && serial[i].t < 5) << i;
    }
    EXPECT_GT(hits, n / 10);  // the scene is not trivially empty
}

}  // namespace
}  // namespace rp
