// The ray variables in a modifier's own space (RADIANCE func.c chanvalue): unit
// directions whatever the transform's scale, distances and S in function units.
#include "material/function_space.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rp::material {

namespace {
void expectVec(const Vec3& v, double x, double y, double z, double tol = 1e-12) {
    SCOPED_TRACE(::testing::Message() << "vector " << v.x << " " << v.y << " " << v.z);
    EXPECT_NEAR(v.x, x, tol);
    EXPECT_NEAR(v.y, y, tol);
    EXPECT_NEAR(v.z, z, tol);
}
}  // namespace

// rect_fixture.rad's pattern transform: inches to metres, turned, moved to the ceiling.
TEST(FunctionSpace, ScaledTransformKeepsDirectionsUnit) {
    Transform forward = Transform::uniformScale(0.0254)
                            .then(Transform::rotateZ(90))
                            .then(Transform::translate(-4, 2.5, 3));
    PatternPoint at;
    at.dir = normalize(Vec3{1, 0, 1});  // up and along world +x
    at.normal = {0, 0, -1};
    at.point = {-4 + 0.0254, 2.5, 3};
    at.distance = 2;
    at.rdot = 1 + 1e-12;  // a rounding error above 1
    calc::RayContext c = functionSpace(at, forward.inverse());
    // World +x is the object's -y after the -rz 90 is undone; no factor 1/0.0254.
    const double h = std::sqrt(0.5);
    expectVec(c.D, 0, -h, h);
    expectVec(c.N, 0, 0, -1);
    expectVec(c.P, 0, -1, 0, 1e-9);  // one inch
    expectVec(c.I, 0, -1, 0);
    expectVec(c.J, 1, 0, 0);
    expectVec(c.K, 0, 0, 1);
    // Distances in inches; S is one world unit (a metre) in inches.
    EXPECT_NEAR(c.T, 2 / 0.0254, 1e-9);
    EXPECT_NEAR(c.Ts, 2 / 0.0254, 1e-9);
    EXPECT_NEAR(c.S, 1 / 0.0254, 1e-9);
    EXPECT_EQ(c.Rdot, 1);
    // The world origin seen from the object: undo the move, the turn and the scale.
    Vec3 o{4, -2.5, -3};
    expectVec(c.Tvec, o.y / 0.0254, -o.x / 0.0254, o.z / 0.0254, 1e-9);
}

TEST(FunctionSpace, IdentityPassesValuesThrough) {
    PatternPoint at;
    at.dir = {0, 0, -1};
    at.normal = {0, 1, 0};
    at.point = {1, 2, 3};
    at.distance = 4;
    at.rdot = -0.25;
    calc::RayContext c = functionSpace(at, Transform::identity());
    expectVec(c.D, 0, 0, -1);
    expectVec(c.N, 0, 1, 0);
    expectVec(c.P, 1, 2, 3);
    EXPECT_EQ(c.T, 4);
    EXPECT_EQ(c.S, 1);
    EXPECT_EQ(c.Rdot, -0.25);
}

}  // namespace rp::material
