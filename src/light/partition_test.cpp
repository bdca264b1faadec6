// Tests for partition.h and aperture.h: partition counts versus -ds, exact coverage
// (areas sum to the shape's area), the cone integral against brute-force Monte Carlo,
// and the cos-weighted cone sampler's mean.
#include "light/partition.h"

#include <gtest/gtest.h>

#include "light/aperture.h"
#include "light/light_test_util.h"

namespace rp::light {
namespace {

using testing::Builder;
using testing::Stats;

double totalArea(const std::vector<Partition>& parts) {
    double a = 0;
    for (const Partition& p : parts) a += p.area;
    return a;
}

TEST(Partition, PolygonCountsFollowDs) {
    Builder b;
    b.squareZ(b.light("l", 1, 1, 1), 0, 1, 0, 1, 0);
    SceneGeometry geom(b.scene());
    double cube = geom.sceneCube().size;  // 1 + 2e-5 (oconv margin)
    // Each of the 2 triangles (area 1/2) is bisected into 2^k with 0.5/2^k <= (ds cube)^2.
    for (double ds : {0.5, 0.1, 0.05, 0.01}) {
        double p2 = ds * cube * ds * cube;
        size_t k = size_t(std::ceil(std::log2(0.5 / p2) - 1e-12));
        auto parts = partitionShape(geom.shapes(), EmitterShape::Polygon, 0, ds * cube);
        EXPECT_EQ(parts.size(), 2u << k) << "ds " << ds;
        EXPECT_NEAR(totalArea(parts), 1.0, 1e-12);
        for (const Partition& p : parts) EXPECT_LE(p.area, p2 * (1 + 1e-12));
    }
}

TEST(Partition, ConcavePolygonSphereRingConeCoverTheirArea) {
    Builder b;
    int32_t l = b.light("l", 1, 1, 1);
    // L shape: 2x2 square minus its upper-right 1x1 quadrant, area 3.
    b.add(PrimType::Polygon, "L", {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0}, l);
    b.add(PrimType::Sphere, "s", {0, 0, 5, 0.5}, l);
    b.add(PrimType::Ring, "r", {3, 3, 3, 0, 0, 1, 0.25, 1}, l);
    b.add(PrimType::Cone, "c", {0, 3, 0, 0, 3, 2, 0.5, 0.25}, l);
    SceneGeometry geom(b.scene());
    const ShapeSet& s = geom.shapes();
    for (double edge : {0.5, 0.1, 0.03}) {
        EXPECT_NEAR(totalArea(partitionShape(s, EmitterShape::Polygon, 0, edge)), 3, 1e-12);
        EXPECT_NEAR(totalArea(partitionShape(s, EmitterShape::Sphere, 0, edge)), kPi, 1e-12);
        EXPECT_NEAR(totalArea(partitionShape(s, EmitterShape::Ring, 0, edge)), kPi * (1 - 0.0625),
                    1e-12);
        double slant = std::sqrt(4 + 0.25 * 0.25);
        EXPECT_NEAR(totalArea(partitionShape(s, EmitterShape::Cone, 0, edge)),
                    kPi * (0.5 + 0.25) * slant, 1e-12);
    }
    // Sphere: N = ceil(pi / 0.01) = 315 cells wanted; nTheta = round(sqrt(2N/pi)) = 14,
    // nPhi = ceil(315/14) = 23.
    EXPECT_EQ(partitionShape(s, EmitterShape::Sphere, 0, 0.1).size(), 14u * 23u);
    // Ring: ceil(0.75/0.1) = 8 bands x ceil(2 pi/0.1) = 63 sectors.
    EXPECT_EQ(partitionShape(s, EmitterShape::Ring, 0, 0.1).size(), 8u * 63u);
    // Cube: 6 faces of (1/ds)^2 cells, one record each.
    auto faces = partitionCube(0.01);
    ASSERT_EQ(faces.size(), 6u);
    EXPECT_EQ(faces[0].cells, 10000u);
}

TEST(Partition, SampledPointsLieOnTheShape) {
    Builder b;
    int32_t l = b.light("l", 1, 1, 1);
    b.add(PrimType::Sphere, "s", {1, 2, 3, 0.5}, l);
    b.add(PrimType::Cone, "c", {0, 3, 0, 0, 3, 2, 0.5, 0.25}, l);
    SceneGeometry geom(b.scene());
    const ShapeSet& s = geom.shapes();
    Rng rng(7, RngDomain::Test, 0);
    for (const Partition& p : partitionShape(s, EmitterShape::Sphere, 0, 0.2)) {
        EmissionPoint e = samplePartition(s, geom.sceneCube(), p, rng);
        EXPECT_NEAR(length(e.point - Vec3{1, 2, 3}), 0.5, 1e-12);
        EXPECT_NEAR(dot(e.normal, normalize(e.point - Vec3{1, 2, 3})), 1, 1e-12);
    }
    for (const Partition& p : partitionShape(s, EmitterShape::Cone, 0, 0.2)) {
        EmissionPoint e = samplePartition(s, geom.sceneCube(), p, rng);
        const Vec3 normal = coneNormal(s.cones[0], e.point);
        EXPECT_NEAR(dot(normal, e.normal), 1, 1e-9);
        double h = e.point.y == 3 ? 0 : e.point.z;
        double r = std::hypot(e.point.x, e.point.y - 3);
        EXPECT_NEAR(r, 0.5 - 0.125 * h, 1e-12);
    }
}

// Brute force: Omega * E[max(0, w.n)] over uniform cone directions; 4 sigma.
TEST(Aperture, ProjectedSolidAngleMatchesMonteCarlo) {
    struct Case {
        Vec3 axis;
        double halfDeg;
        Vec3 n;
    };
    Vec3 z{0, 0, 1};
    Case cases[] = {{z, 90, z},
                    {z, 10, z},
                    {normalize(Vec3{1, 0, 1}), 30, z},    // wholly above
                    {normalize(Vec3{1, 0, 0.3}), 40, z},  // straddles the horizon
                    {Vec3{0, 0, -1}, 120, z},             // mostly below
                    {normalize(Vec3{0, 1, 1}), 90, Vec3{0, -1, 0}},
                    {z, 180, normalize(Vec3{1, 2, 3})}};
    // Closed forms.
    EXPECT_NEAR(projectedSolidAngle(z, 0, z), kPi, 1e-12);
    double s10 = std::sin(10 * kPi / 180);
    EXPECT_NEAR(projectedSolidAngle(z, std::cos(10 * kPi / 180), z), kPi * s10 * s10, 1e-14);
    EXPECT_NEAR(projectedSolidAngle(z, -1, normalize(Vec3{1, 2, 3})), kPi, 1e-9);
    for (const Case& c : cases) {
        Cone cone{c.axis, std::cos(c.halfDeg * kPi / 180)};
        Rng rng(11, RngDomain::Test, 1);
        Stats st;
        for (int i = 0; i < 400000; ++i)
            st.add(std::fmax(0.0, dot(sampleUniformCone(cone, rng), c.n)) * cone.solidAngle());
        double exact = projectedSolidAngle(cone, c.n);
        EXPECT_NEAR(exact, st.mean(), 4 * st.sigmaOfMean() + 1e-12) << c.halfDeg;
    }
}

// The flat-source shortcut (frame computed once) draws exactly the directions of the
// general sampler, so maps do not change with it.
TEST(Aperture, CosineHemisphereWithGivenFrameMatchesProjectedCone) {
    for (const Vec3& n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, normalize(Vec3{0.3, -0.8, 0.2}),
                          normalize(Vec3{-1, 0.001, 0})}) {
        Vec3 u, v;
        coneFrame(n, u, v);
        Rng a(8, RngDomain::Test, 1), b(8, RngDomain::Test, 1);
        for (int i = 0; i < 1000; ++i) {
            const Vec3 w = sampleCosineHemisphere(n, u, v, a);
            ASSERT_EQ(w, sampleProjectedCone(Cone{n, 0}, n, b)) << i;
            ASSERT_GT(dot(w, n), 0);
        }
    }
}

// Density proportional to max(0, w.n) in the cone: the mean of w.n is
// integral((w.n)^2) / integral(w.n), estimated independently with uniform samples.
TEST(Aperture, ProjectedConeSamplerHasCosineDensity) {
    Vec3 z{0, 0, 1};
    Cone cones[] = {{z, 0},
                    {normalize(Vec3{1, 0, 0.3}), std::cos(40 * kPi / 180)},
                    {normalize(Vec3{0.2, 0, 1}), std::cos(5 * kPi / 180)}};
    for (const Cone& c : cones) {
        Rng rng(3, RngDomain::Test, 2);
        Stats sampled, num, den;
        for (int i = 0; i < 400000; ++i) {
            Vec3 w = sampleProjectedCone(c, z, rng);
            ASSERT_GE(dot(w, c.axis), c.cosHalf - 1e-12);
            ASSERT_GT(dot(w, z), 0);
            sampled.add(w.z);
            Vec3 u = sampleUniformCone(c, rng);
            double cu = std::fmax(0.0, u.z);
            num.add(cu * cu);
            den.add(cu);
        }
        double expected = num.mean() / den.mean();
        double sigma = std::hypot(
            sampled.sigmaOfMean(),
            expected * (num.sigmaOfMean() / num.mean() + den.sigmaOfMean() / den.mean()));
        EXPECT_NEAR(sampled.mean(), expected, 4 * sigma);
    }
    // A narrow cone about the normal (Malley's method in a disc of radius sin 30 deg):
    // sin^2 uniform in [0, 1/4], so its mean is 1/8; unit directions inside the cone.
    {
        Rng r(6, RngDomain::Test, 4);
        Stats sin2;
        const Cone narrow{z, std::cos(kPi / 6)};
        for (int i = 0; i < 400000; ++i) {
            const Vec3 w = sampleProjectedCone(narrow, z, r);
            ASSERT_NEAR(length(w), 1.0, 1e-12);
            ASSERT_GE(w.z, narrow.cosHalf - 1e-12);
            sin2.add(1 - w.z * w.z);
        }
        EXPECT_NEAR(sin2.mean(), 0.125, 4 * sin2.sigmaOfMean());
    }
    // Hemisphere: mean cos = 2/3 exactly.
    Rng rng(5, RngDomain::Test, 3);
    Stats st;
    for (int i = 0; i < 1000000; ++i) st.add(sampleProjectedCone(Cone{z, 0}, z, rng).z);
    EXPECT_NEAR(st.mean(), 2.0 / 3, 4 * st.sigmaOfMean());
}

TEST(Aperture, DirectionTableIntegratesCosine) {
    Vec3 z{0, 0, 1};
    DirectionTable t(Cone{z, 0}, 1000, [&](const Vec3& w) { return Color::grey(w.z); });
    EXPECT_NEAR(t.integral().r, kPi, kPi * 1e-3);
    DirectionTable t2(Cone{z, 0}, 1000, [&](const Vec3& w) { return Color::grey(w.z * w.z); });
    EXPECT_NEAR(t2.integral().g, 2 * kPi / 3, 1e-3);
}

}  // namespace
}  // namespace rp::light
