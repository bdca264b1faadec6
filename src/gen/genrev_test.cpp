// Tests for genrev: cylinder, cone, disc (ring) and inward (tube/cup) segments from
// simple profiles, the RADIANCE text layout, -e/-f definitions and the -s Phong records,
// and one test per kind of bad input.
#include "gen/genrev.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "util/error.h"

namespace rp::gen {
namespace {

std::vector<RevSegment> segments(const std::vector<std::string>& args) {
    GenrevOptions opt = parseGenrevArgs(args);
    GenFunctions funcs(opt.sources, {"."});
    return genrevSegments(opt, funcs);
}

std::string run(const std::vector<std::string>& args) {
    std::vector<std::string> warnings;
    return genrev(args, {"."}, warnings);
}

std::string errorOf(const std::vector<std::string>& args) {
    try {
        run(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Genrev, CylinderOfRadiusOne) {
    auto segs = segments({"genrev", "m", "c", "t", "1", "4"});
    ASSERT_EQ(segs.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(segs[i].kind, RevSegment::Kind::Cylinder);
        EXPECT_EQ(segs[i].index, i + 1);
        EXPECT_DOUBLE_EQ(segs[i].z0, i / 4.0);
        EXPECT_DOUBLE_EQ(segs[i].z1, (i + 1) / 4.0);
        EXPECT_DOUBLE_EQ(segs[i].r1, 1.0);
    }
    std::string out = run({"genrev", "m", "c", "t", "1", "1"});
    EXPECT_EQ(out,
              "# genrev m c t 1 1\n"
              "\nm cylinder c.1\n0\n0\n7\n"
              "\t0\t0\t                 0\n"
              "\t0\t0\t                 1\n"
              "\t                 1\n");
}

TEST(Genrev, ZFallingGivesTubesAndCups) {
    auto tube = segments({"genrev", "m", "c", "1-t", "2", "2"});
    ASSERT_EQ(tube.size(), 2u);
    EXPECT_EQ(tube[0].kind, RevSegment::Kind::Tube);
    EXPECT_DOUBLE_EQ(tube[0].z0, 1.0);
    EXPECT_DOUBLE_EQ(tube[0].z1, 0.5);
    auto cup = segments({"genrev", "m", "c", "-t", "1+t", "1"});
    ASSERT_EQ(cup.size(), 1u);
    EXPECT_EQ(cup[0].kind, RevSegment::Kind::Cup);
}

TEST(Genrev, ConeEndPointsAndRadii) {
    // A cone of height 2 from radius 1 to a point, in one segment.
    auto segs = segments({"genrev", "m", "k", "2*t", "1-t", "1"});
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_EQ(segs[0].kind, RevSegment::Kind::Cone);
    EXPECT_DOUBLE_EQ(segs[0].z0, 0);
    EXPECT_DOUBLE_EQ(segs[0].z1, 2);
    EXPECT_DOUBLE_EQ(segs[0].r0, 1);
    EXPECT_DOUBLE_EQ(segs[0].r1, 0);
    EXPECT_EQ(run({"genrev", "m", "k", "2*t", "1-t", "1"}),
              "# genrev m k 2*t 1-t 1\n"
              "\nm cone k.1\n0\n0\n8\n"
              "\t0\t0\t                 0\n"
              "\t0\t0\t                 2\n"
              "\t                 1\t                 0\n");
}

TEST(Genrev, DiscAsRingFacingUpWhenRadiusShrinks) {
    auto up = segments({"genrev", "m", "d", "3", "1-t", "1"});
    ASSERT_EQ(up.size(), 1u);
    EXPECT_EQ(up[0].kind, RevSegment::Kind::Ring);
    EXPECT_DOUBLE_EQ(up[0].z1, 3);
    EXPECT_DOUBLE_EQ(up[0].ringNormalZ, 1);
    EXPECT_EQ(run({"genrev", "m", "d", "3", "1-t", "1"}),
              "# genrev m d 3 1-t 1\n"
              "\nm ring d.1\n0\n0\n8\n"
              "\t0\t0\t                 3\n"
              "\t0\t0\t                 1\n"
              "\t                 1\t                 0\n");
    auto down = segments({"genrev", "m", "d", "0", "t", "1"});
    ASSERT_EQ(down.size(), 1u);
    EXPECT_DOUBLE_EQ(down[0].ringNormalZ, -1);
}

TEST(Genrev, StillSegmentsAreSkippedButNumbered) {
    // r and z constant over the middle third: segment 2 is left out, 3 keeps its name.
    auto segs = segments({"genrev", "m", "s", "if(t-.9,t,if(.2-t,t,.5))", "1", "3"});
    ASSERT_EQ(segs.size(), 2u);
    EXPECT_EQ(segs[0].index, 1);
    EXPECT_EQ(segs[1].index, 3);
}

TEST(Genrev, ExpressionsAndFilesDefineHelpers) {
    const std::string file = "genrev_test_profile.cal";
    { std::ofstream(file) << "rad(x) = 2*x;\n"; }
    auto segs = segments({"genrev", "m", "c", "h*t", "rad(1)", "1", "-e", "h = 3", "-f", file});
    std::remove(file.c_str());
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_DOUBLE_EQ(segs[0].z1, 3);
    EXPECT_DOUBLE_EQ(segs[0].r1, 2);
    // PI and the curve functions of RADIANCE's generators are predefined.
    auto b = segments({"genrev", "m", "c", "t", "bezier(0,1,1,0,.5)+PI-PI", "1"});
    EXPECT_DOUBLE_EQ(b[0].r0, 0.75);
}

TEST(Genrev, SmoothingWritesPhongTexfuncs) {
    std::string out = run({"genrev", "m", "c", "t", "1", "2", "-s"});
    // Cylinders: z varies (a linear fit of the normal's z part), r does not ("0 1").
    EXPECT_NE(out.find("\nm texfunc Phong\n4 rev_dx rev_dy rev_dz rev.cal\n0\n4\n"),
              std::string::npos);
    EXPECT_NE(out.find("\nPhong cylinder c.1\n"), std::string::npos);
    EXPECT_NE(out.find("\t0\t1\n"), std::string::npos);  // r constant, z rising: "0 1"
    EXPECT_EQ(out.find("\nm cylinder"), std::string::npos);
}

TEST(Genrev, BadInput) {
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "1"}),
              "usage: genrev mat name 'z(t)' 'r(t)' nseg [-e expr][-f file][-s]");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "1", "ten"}),
              "bad nseg 'ten': expected an integer");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "1", "0"}), "nseg must be positive, got 0");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "1", "4", "-q"}), "unknown option '-q'");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "1", "4", "-e"}), "option -e needs a value");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t*(", "1", "4"}), "z(t): syntax error: unexpected ';'");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "q", "4"}), "r(t): undefined variable 'q'");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "", "4"}), "r(t): empty expression");
    EXPECT_EQ(errorOf({"genrev", "m", "c", "t", "t-.5", "2"}),
              "r(t) is negative (-0.5) at t = 0: radii must be >= 0");
    EXPECT_NE(errorOf({"genrev", "m", "c", "t", "1", "4", "-f", "no_such_file.cal"}), "(no error)");
}

}  // namespace
}  // namespace rp::gen
