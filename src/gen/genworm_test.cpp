// Tests for genworm: spheres at the curve points joined by cylinders (equal radii) or by
// cones tangent to both spheres, RADIANCE's names and layout, and bad input.
#include "gen/genworm.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace rp::gen {
namespace {

std::vector<WormPart> parts(const std::vector<std::string>& args) {
    GenwormOptions opt = parseGenwormArgs(args);
    GenFunctions funcs(opt.sources, {"."});
    return genwormParts(opt, funcs);
}

std::string errorOf(const std::vector<std::string>& args) {
    try {
        std::vector<std::string> warnings;
        genworm(args, {"."}, warnings);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Genworm, StraightLineOfEqualRadii) {
    auto p = parts({"genworm", "m", "w", "2*t", "0", "0", "0.1", "2"});
    ASSERT_EQ(p.size(), 5u);  // s0 c1 s1 c2 s2
    const char* names[] = {"w.s0", "w.c1", "w.s1", "w.c2", "w.s2"};
    for (int k = 0; k < 5; ++k) EXPECT_EQ(p[k].name, names[k]);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(p[2 * k].kind, WormPart::Kind::Sphere);
        EXPECT_EQ(p[2 * k].p0, Vec3(k, 0, 0));
        EXPECT_DOUBLE_EQ(p[2 * k].r0, 0.1);
    }
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(p[2 * k + 1].kind, WormPart::Kind::Cylinder);
        EXPECT_EQ(p[2 * k + 1].p0, Vec3(k, 0, 0));
        EXPECT_EQ(p[2 * k + 1].p1, Vec3(k + 1, 0, 0));
        EXPECT_DOUBLE_EQ(p[2 * k + 1].r0, 0.1);
    }
    std::vector<std::string> warnings;
    std::string out = genworm({"genworm", "m", "w", "t", "0", "0", "0.1", "1"}, {"."}, warnings);
    EXPECT_EQ(out,
              "# genworm m w t 0 0 0.1 1\n"
              "\nm sphere w.s0\n0\n0\n4"
              "                  0                  0                  0                0.1\n"
              "\nm cylinder w.c1\n0\n0\n7\n"
              "                 0                  0                  0\n"
              "                 1                  0                  0\n"
              "               0.1\n"
              "\nm sphere w.s1\n0\n0\n4"
              "                  1                  0                  0                0.1\n");
}

TEST(Genworm, ConeIsTangentToBothSpheres) {
    // Radius 0.5 at z=0 to 0.25 at z=1.
    auto p = parts({"genworm", "m", "w", "0", "0", "t", "0.5-t/4", "1"});
    ASSERT_EQ(p.size(), 3u);
    const WormPart& c = p[1];
    ASSERT_EQ(c.kind, WormPart::Kind::Cone);
    // Tangency: for each end, the cone's rim lies on its sphere and the cone's slant
    // line is perpendicular to the radius there.
    const double a = 0.25;  // (r0 - r1) / d
    EXPECT_NEAR(c.p0.z, 0.5 * a, 1e-12);
    EXPECT_NEAR(c.p1.z, 1 + 0.25 * a, 1e-12);
    EXPECT_NEAR(c.r0, 0.5 * std::sqrt(1 - a * a), 1e-12);
    EXPECT_NEAR(c.r1, 0.25 * std::sqrt(1 - a * a), 1e-12);
    EXPECT_NEAR(c.p0.z * c.p0.z + c.r0 * c.r0, 0.25, 1e-12);  // rim on sphere 0
    Vec3 slant(c.r1 - c.r0, 0, c.p1.z - c.p0.z);              // along the cone side
    Vec3 radius(c.r0, 0, c.p0.z);                             // centre to rim
    EXPECT_NEAR(dot(slant, radius), 0, 1e-12);
}

TEST(Genworm, CoincidentCentresGetNoJoint) {
    auto p = parts({"genworm", "m", "w", "0", "0", "0", "1+t", "1"});
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[1].name, "w.s1");
}

TEST(Genworm, BadInput) {
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "0", "1"}),
              "usage: genworm mat name 'x(t)' 'y(t)' 'z(t)' 'r(t)' nseg [-e expr][-f file]");
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "0", "1", "2x"}),
              "bad nseg '2x': expected an integer");
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "0", "1", "-3"}),
              "nseg must be positive, got -3");
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "0", "1", "3", "-s"}), "unknown option '-s'");
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "sin(", "1", "3"}),
              "z(t): syntax error: unexpected ';'");
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "0", "-1", "3"}),
              "r(t) is negative (-1) at t = 0: radii must be >= 0");
    EXPECT_EQ(errorOf({"genworm", "m", "w", "t", "0", "0", "1", "3", "-e", "a = = 2"}),
              "-e 'a = = 2': syntax error: unexpected '='");
}

}  // namespace
}  // namespace rp::gen
