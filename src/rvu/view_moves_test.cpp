// rvu's view changes against RADIANCE (fvect.c spinvector/geodesic, rv3.c zoomview and
// moveview, rv2.c getrotate/getorigin): rotations are right-handed and keep lengths,
// zooms follow each view type's projection, move/pivot keep the point of interest on the
// view axis with clipping and focal distance updated, and origin picks a new up vector
// only when the direction would be parallel to it.
#include "rvu/view_moves.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rp::rvu {
namespace {

constexpr double kDeg = kPi / 180;
constexpr double kEps = 1e-12;     // pure vector math
constexpr double kDegEps = 1e-10;  // angles in degrees (values up to 360)

void expectVec(const Vec3& got, const Vec3& want, double tol = kEps) {
    EXPECT_NEAR(got.x, want.x, tol) << "x";
    EXPECT_NEAR(got.y, want.y, tol) << "y";
    EXPECT_NEAR(got.z, want.z, tol) << "z";
}

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(length(cross(a, b)), dot(a, b));
}

// Distance from `p` to the line through `origin` along `dir`.
double distanceToLine(const Vec3& p, const Vec3& origin, const Vec3& dir) {
    return length(cross(p - origin, normalize(dir)));
}

View lookingY(double focal = 1) {
    View v;  // point 0, up +z, perspective 45 x 45
    v.direction = {0, focal, 0};
    return v;
}

TEST(ViewMovesSpin, RightHandedAboutAxis) {
    expectVec(spinVector({1, 0, 0}, {0, 0, 1}, kPi / 2), {0, 1, 0});
    expectVec(spinVector({0, 1, 0}, {1, 0, 0}, kPi / 2), {0, 0, 1});
    expectVec(spinVector({1, 0, 0}, {0, 0, 1}, -kPi / 2), {0, -1, 0});
    // The component along the axis stays, the rest turns; the length is kept.
    const Vec3 r = spinVector({2, 0, 3}, {0, 0, 1}, 30 * kDeg);
    expectVec(r, {2 * std::cos(30 * kDeg), 2 * std::sin(30 * kDeg), 3});
    EXPECT_NEAR(length(r), std::sqrt(13.0), kEps);
    const Vec3 v{0.3, -1.2, 0.7}, axis = normalize(Vec3{1, 2, -2});
    expectVec(spinVector(spinVector(v, axis, 1.1), axis, -1.1), v);
    EXPECT_EQ(spinVector(v, axis, 0), v);
}

TEST(ViewMovesGeodesic, TurnsByTheAngleTowardsTarget) {
    expectVec(geodesic({1, 0, 0}, {0, 5, 0}, 30 * kDeg),
              {std::cos(30 * kDeg), std::sin(30 * kDeg), 0});
    expectVec(geodesic({3, 0, 0}, {0, 0, 1}, 45 * kDeg),
              {3 * std::sqrt(0.5), 0, 3 * std::sqrt(0.5)});
    // Past the target it keeps going along the great circle (RADIANCE GEOD_RAD).
    expectVec(geodesic({1, 0, 0}, {0, 1, 0}, 120 * kDeg), {-0.5, std::sqrt(0.75), 0});
    // General case: length kept, turned by exactly the angle, in the plane of v and target,
    // and that much closer to the target.
    const Vec3 v{1, 2, -0.5}, t{-1, 0.5, 2};
    const Vec3 g = geodesic(v, t, 0.4);
    EXPECT_NEAR(length(g), length(v), kEps);
    EXPECT_NEAR(angleBetween(v, g), 0.4, kEps);
    EXPECT_NEAR(dot(g, normalize(cross(v, t))), 0, kEps);
    EXPECT_NEAR(angleBetween(g, t), angleBetween(v, t) - 0.4, kEps);
    // Parallel, opposite, zero angle or zero target: unchanged.
    EXPECT_EQ(geodesic(v, v * 3, 0.4), v);
    EXPECT_EQ(geodesic(v, -v, 0.4), v);
    EXPECT_EQ(geodesic(v, t, 0), v);
    EXPECT_EQ(geodesic(v, Vec3{}, 0.4), v);
}

View zoomed(ViewType type, double h, double v, double f) {
    View view;
    view.type = type, view.horizontal = h, view.vertical = v;
    zoomView(view, f);
    return view;
}

double tanZoom(double deg, double f) { return 2 * std::atan(std::tan(deg * kDeg / 2) / f) / kDeg; }

TEST(ViewMovesZoom, PerspectiveDividesHalfAngleTangent) {
    const View v = zoomed(ViewType::kPerspective, 45, 30, 2);
    EXPECT_NEAR(v.horizontal, 2 * std::atan(std::tan(22.5 * kDeg) / 2) / kDeg, kDegEps);
    EXPECT_NEAR(v.horizontal, 23.4018, 1e-4);  // not simply 22.5
    EXPECT_NEAR(v.vertical, tanZoom(30, 2), kDegEps);
    const View out = zoomed(ViewType::kPerspective, 45, 30, 0.5);
    EXPECT_NEAR(out.horizontal, tanZoom(45, 0.5), kDegEps);
    EXPECT_LT(out.horizontal, 180);
    EXPECT_NEAR(zoomed(ViewType::kPerspective, 45, 30, 1).horizontal, 45, kDegEps);
}

TEST(ViewMovesZoom, ParallelDividesSizesAngularCappedAt360) {
    const View p = zoomed(ViewType::kParallel, 10, 6, 2);
    EXPECT_DOUBLE_EQ(p.horizontal, 5);
    EXPECT_DOUBLE_EQ(p.vertical, 3);
    EXPECT_DOUBLE_EQ(zoomed(ViewType::kParallel, 10, 6, 0.025).horizontal, 400);  // no cap
    const View a = zoomed(ViewType::kAngular, 180, 120, 2);
    EXPECT_DOUBLE_EQ(a.horizontal, 90);
    EXPECT_DOUBLE_EQ(a.vertical, 60);
    const View out = zoomed(ViewType::kAngular, 180, 120, 0.25);
    EXPECT_DOUBLE_EQ(out.horizontal, 360);
    EXPECT_DOUBLE_EQ(out.vertical, 360);
}

TEST(ViewMovesZoom, HemisphericalDividesSineWith180Cap) {
    const View v = zoomed(ViewType::kHemispherical, 180, 120, 2);
    EXPECT_NEAR(v.horizontal, 60, kDegEps);  // sin 90 / 2 = sin 30
    EXPECT_NEAR(v.vertical, 2 * std::asin(std::sin(60 * kDeg) / 2) / kDeg, kDegEps);
    const View out = zoomed(ViewType::kHemispherical, 120, 60, 0.5);
    EXPECT_DOUBLE_EQ(out.horizontal, 180);    // sin 60 / .5 > 1
    EXPECT_NEAR(out.vertical, 180, kDegEps);  // sin 30 / .5 = 1
}

TEST(ViewMovesZoom, PlanisphereIsStereographic) {
    // Image radius goes as tan(angle/4) for the full angle: 4 atan(tan(a/4) / f).
    const View v = zoomed(ViewType::kPlanisphere, 180, 90, 2);
    EXPECT_NEAR(v.horizontal, 4 * std::atan(std::tan(45 * kDeg) / 2) / kDeg, kDegEps);
    EXPECT_NEAR(v.vertical, 4 * std::atan(std::tan(22.5 * kDeg) / 2) / kDeg, kDegEps);
    View round = zoomed(ViewType::kPlanisphere, 200, 100, 3);
    zoomView(round, 1.0 / 3);
    EXPECT_NEAR(round.horizontal, 200, kDegEps);
    EXPECT_NEAR(round.vertical, 100, kDegEps);
}

TEST(ViewMovesZoom, CylindricalAngularAcrossPerspectiveUp) {
    const View v = zoomed(ViewType::kCylindrical, 360, 45, 2);
    EXPECT_DOUBLE_EQ(v.horizontal, 180);
    EXPECT_NEAR(v.vertical, tanZoom(45, 2), kDegEps);
    const View out = zoomed(ViewType::kCylindrical, 300, 45, 0.5);
    EXPECT_DOUBLE_EQ(out.horizontal, 360);
    EXPECT_NEAR(out.vertical, tanZoom(45, 0.5), kDegEps);
}

TEST(ViewMovesRotate, LeftAboutUpThenElevUpAndAimKeepsFocus) {
    View v = lookingY(2);
    v.point = {1, 2, 3};
    const View left = rotateView(v, 90, 0, 1);
    expectVec(left.direction, {-2, 0, 0});
    EXPECT_EQ(left.point, v.point);
    EXPECT_EQ(left.up, v.up);
    EXPECT_DOUBLE_EQ(left.horizontal, 45);
    expectVec(rotateView(v, -90, 0, 1).direction, {2, 0, 0});
    const View up = rotateView(v, 0, 30, 1);
    EXPECT_NEAR(dot(normalize(up.direction), Vec3{0, 0, 1}), 0.5, kEps);
    EXPECT_NEAR(length(up.direction), 2, kEps);
    expectVec(up.direction, {0, 2 * std::cos(30 * kDeg), 1});
    // A non-unit up vector is only a direction.
    v.up = {0, 0, 7};
    expectVec(rotateView(v, 90, 30, 1).direction, {-2 * std::cos(30 * kDeg), 0, 1});
    const View zoom = rotateView(v, 0, 0, 2);
    EXPECT_NEAR(zoom.horizontal, tanZoom(45, 2), kDegEps);
    expectVec(zoom.direction, v.direction);
    // aim: the point and focal distance stay.
    v.point = {1, 1, 1};
    const View a = aimView(v, normalize(Vec3{1, 0, 1}), 2);
    expectVec(a.direction, Vec3{1, 0, 1} * std::sqrt(2.0));
    EXPECT_EQ(a.point, v.point);
    EXPECT_NEAR(a.horizontal, tanZoom(45, 2), kDegEps);
}

TEST(ViewMovesMove, MagnificationMovesCloserAlongAxis) {
    const Vec3 c{0, 4, 0};
    const View m = moveView(lookingY(), 0, 0, 2, c);
    expectVec(m.point, {0, 2, 0});
    expectVec(m.direction, {0, 0.5, 0});  // vdist /= mag
    const View away = moveView(lookingY(), 0, 0, 0.5, c);
    expectVec(away.point, {0, -4, 0});
    expectVec(away.direction, {0, 2, 0});
    // An off-axis center is put on the axis at distance |vp - center| / mag.
    const View off = moveView(lookingY(), 0, 0, 1, {3, 4, 0});
    expectVec(off.point, {3, -1, 0});
    expectVec(off.direction, {0, 1, 0});
}

TEST(ViewMovesMove, PivotKeepsCenterOnAxisAndDistance) {
    const Vec3 c{0, 4, 0};
    const View back = moveView(lookingY(), 180, 0, 1, c);
    expectVec(back.point, {0, 8, 0});
    expectVec(back.direction, {0, -1, 0});
    View v = lookingY(2);
    v.point = {1, -1, 0.5};
    const Vec3 c2{2, 3, 1};
    const double dist = length(c2 - v.point);
    for (double angle : {90.0, -45.0, 180.0}) {
        const View p = moveView(v, angle, 0, 1, c2);
        EXPECT_NEAR(distanceToLine(c2, p.point, p.direction), 0, 1e-12) << angle;
        EXPECT_NEAR(length(c2 - p.point), dist, 1e-12) << angle;
        EXPECT_GT(dot(c2 - p.point, p.direction), 0) << angle;  // looking at it
        EXPECT_NEAR(length(p.direction), 2, kEps) << angle;
    }
    expectVec(moveView(lookingY(), 90, 0, 1, c).point, {4, 4, 0});  // left about up
}

TEST(ViewMovesMove, ElevationRaisesViewPointToLookDown) {
    const View e = moveView(lookingY(), 0, 30, 1, {0, 4, 0});
    expectVec(e.point, {0, 4 - 4 * std::cos(30 * kDeg), 2});
    expectVec(e.direction, {0, std::cos(30 * kDeg), -0.5});
    EXPECT_NEAR(distanceToLine({0, 4, 0}, e.point, e.direction), 0, kEps);
}

TEST(ViewMovesMove, ParallelMagnifiesInstead) {
    View v = lookingY(3);
    v.type = ViewType::kParallel;
    v.horizontal = 10, v.vertical = 8;
    v.fore = 1, v.aft = 10;
    const View m = moveView(v, 0, 0, 2, {2, 5, 1});
    EXPECT_DOUBLE_EQ(m.horizontal, 5);
    EXPECT_DOUBLE_EQ(m.vertical, 4);
    expectVec(m.point, {2, 0, 1});            // the center's depth is 5: no closer
    expectVec(m.direction, {0, 3, 0});        // focal distance unchanged
    EXPECT_TRUE(m.fore == 1 && m.aft == 10);  // not moved: clipping unchanged
}

TEST(ViewMovesMove, ClippingFollowsAsRadiance) {
    // rv3.c moveview: d = |vp - vc| / mag; fore and aft (when set) += d - d*mag.
    View v = lookingY();
    v.fore = 3, v.aft = 10;
    View m = moveView(v, 0, 0, 2, {0, 4, 0});  // d = 2: planes 2 closer
    EXPECT_DOUBLE_EQ(m.fore, 1);
    EXPECT_DOUBLE_EQ(m.aft, 8);
    v.fore = 1;
    m = moveView(v, 0, 0, 2, {0, 4, 0});
    EXPECT_DOUBLE_EQ(m.fore, 0);  // clamped
    EXPECT_DOUBLE_EQ(m.aft, 8);
    v.aft = 1.5;
    m = moveView(v, 0, 0, 2, {0, 4, 0});
    EXPECT_DOUBLE_EQ(m.aft, 0);  // would be -0.5 <= fore: dropped
    v.fore = 0, v.aft = 10;
    m = moveView(v, 0, 0, 0.5, {0, 4, 0});  // d = 8: planes 4 further
    EXPECT_DOUBLE_EQ(m.fore, 0);            // unset stays unset
    EXPECT_DOUBLE_EQ(m.aft, 14);
}

TEST(ViewMovesOrigin, AdvanceAlongUnitDirection) {
    View v = lookingY();
    v.point = {1, 1, 1}, v.direction = {0, 0, -5}, v.up = {0, 1, 0};
    expectVec(advanceView(v, 2).point, {1, 1, -1});
    expectVec(advanceView(v, -0.5).point, {1, 1, 1.5});
    EXPECT_EQ(advanceView(v, 2).direction, v.direction);
}

TEST(ViewMovesOrigin, PlaceReplacesUpOnlyWhenParallel) {
    View v = lookingY(2);
    v.up = {0, 0, 2};
    const View side = placeView(v, {1, 2, 3}, {1, 0, 0});
    EXPECT_EQ(side.point, (Vec3{1, 2, 3}));
    expectVec(side.direction, {2, 0, 0});
    EXPECT_EQ(side.up, (Vec3{0, 0, 2}));  // kept as given
    // Straight down: z is too aligned (1 >= .34), y is not: up y.
    EXPECT_EQ(placeView(v, {}, {0, 0, -1}).up, (Vec3{0, 1, 0}));
    // Scanning z, y, x: z² = .64 and y² = .36 are both >= .34, so x.
    v.up = {0, 0.6, 0.8};
    EXPECT_EQ(placeView(v, {}, {0, 0.6, 0.8}).up, (Vec3{1, 0, 0}));
    v.up = {0, 1, 0};
    EXPECT_EQ(placeView(v, {}, {0, -1, 0}).up, (Vec3{0, 0, 1}));
    // RADIANCE's test: d² >= 1 - 2 FTINY, with FTINY 1e-6.
    v.up = {0, 0, 1};
    const double s1 = std::sqrt(1.5e-6), s2 = std::sqrt(2.5e-6);  // sin² either side of 2e-6
    EXPECT_EQ(placeView(v, {}, {s1, 0, std::sqrt(1 - s1 * s1)}).up, (Vec3{0, 1, 0}));
    EXPECT_EQ(placeView(v, {}, {s2, 0, std::sqrt(1 - s2 * s2)}).up, (Vec3{0, 0, 1}));
}

}  // namespace
}  // namespace rp::rvu
