// Tests for genblinds: byte-identical output to RADIANCE's genblinds for flat and curved
// slats (-r and +r, both tilt signs; tests/data/gen_radiance), slat geometry (tilt,
// spacing, arcs on their circle, which way each curvature bends), and bad input.
#include "gen/genblinds.h"

#include <gtest/gtest.h>

#include <cmath>

#include "gen/test_reference.h"
#include "util/error.h"

namespace rp::gen {
namespace {

using A = std::vector<std::string>;

TEST(Genblinds, MatchesRadianceByteForByte) {
    for (const char* file :
         {"genblinds_flat_up.rad", "genblinds_flat_down.rad", "genblinds_minus_r_up.rad",
          "genblinds_minus_r_down.rad", "genblinds_plus_r_up.rad", "genblinds_plus_r_down.rad"}) {
        auto ref = testing::readReferenceOutput(file);
        ASSERT_GE(ref.args.size(), 8u) << file;
        EXPECT_EQ(genblinds(ref.args), ref.text) << file;
    }
}

// The manual's example, 25 curved slats of 20 facets: RADIANCE's output (132613 bytes,
// `genblinds white blind 1 46 88 25 15 -r 1`) by its FNV-1a hash.
TEST(Genblinds, ManualExampleMatchesRadiance) {
    std::string out =
        genblinds(A{"genblinds", "white", "blind", "1", "46", "88", "25", "15", "-r", "1"});
    EXPECT_EQ(out.size(), 132613u);
    EXPECT_EQ(testing::fnv1a64(out), 0x19346d8678f5213eULL);
}

TEST(Genblinds, FlatSlatsTiltAndStack) {
    auto s =
        genblindsSurfaces(parseGenblindsArgs(A{"genblinds", "m", "b", "2", "3", "8", "4", "30"}));
    ASSERT_EQ(s.size(), 4u);
    for (int n = 0; n < 4; ++n) {
        EXPECT_EQ(s[n].name, "b." + std::to_string(n + 1) + ".0");
        ASSERT_EQ(s[n].points.size(), 4u);
        double z0 = 8.0 * (n + 0.5) / 4;  // height/nslats/2 above the floor, then every 2
        EXPECT_NEAR(s[n].points[0].z, z0, 1e-12);
        EXPECT_EQ(s[n].points[1].y, 3);
        // the +x edge is lifted by depth sin(angle), moved in by depth (1 - cos(angle))
        EXPECT_NEAR(s[n].points[2].x, 2 * std::cos(kPi / 6), 1e-12);
        EXPECT_NEAR(s[n].points[2].z - z0, 2 * std::sin(kPi / 6), 1e-12);
        EXPECT_LT(newellNormal(s[n].points).z, 0);  // RADIANCE's vertex order faces down
    }
}

// A curved slat's facets lie on a circle of radius |rcurv|; its chord spans the depth at
// the blind angle; "-r" bends the slat below its chord (slopes rise along x), "+r" above.
TEST(Genblinds, CurvedSlatsFollowTheirArc) {
    for (const char* sign : {"-r", "+r"}) {
        auto s = genblindsSurfaces(
            parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "1", "1", "20", sign, "0.8"}));
        double theta = 2 * std::asin(1 / 1.6);
        ASSERT_EQ(s.size(), size_t(std::ceil(theta / (3 * kPi / 180))));
        double z0 = 0.5;
        Vec3 first = s.front().points[0], last = s.back().points[3];
        EXPECT_NEAR(first.x, 0, 1e-12);
        EXPECT_NEAR(first.z, z0, 1e-12);
        EXPECT_NEAR(std::hypot(last.x, last.z - z0), 1.0, 1e-9);
        EXPECT_NEAR(std::atan2(last.z - z0, last.x), 20 * kPi / 180, 1e-9);
        double prevSlope = std::string(sign) == "-r" ? -1e9 : 1e9;
        for (const GenSurface& f : s) {
            Vec3 a = f.points[0], b = f.points[3];
            EXPECT_EQ(f.points[1].y, 2);
            double slope = (b.z - a.z) / (b.x - a.x);
            if (std::string(sign) == "-r")
                EXPECT_GT(slope, prevSlope);
            else
                EXPECT_LT(slope, prevSlope);
            prevSlope = slope;
            EXPECT_NEAR(length(b - a), 2 * 0.8 * std::sin(theta / s.size() / 2), 1e-12);
        }
        // every facet edge point is 0.8 from one centre: the chord's perpendicular bisector
        Vec3 mid = 0.5 * (first + last), along = normalize(last - first);
        Vec3 perp(-along.z, 0, along.x);
        double off = std::sqrt(0.64 - 0.25);
        Vec3 centre = mid + perp * (std::string(sign) == "-r" ? off : -off);
        for (const GenSurface& f : s)
            for (int k : {0, 3}) {
                Vec3 p = f.points[k];
                p.y = 0;
                EXPECT_NEAR(length(p - centre), 0.8, 1e-9) << sign;
            }
    }
}

TEST(Genblinds, BadInput) {
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "3", "4"}), InputError);
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "3", "4", "5", "-r"}),
                 InputError);
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "3", "4", "5", "-x", "1"}),
                 InputError);
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2x", "3", "4", "5"}),
                 InputError);
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "0", "2", "3", "4", "5"}), InputError);
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "3", "0", "5"}), InputError);
    EXPECT_THROW(parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "3", "2.5", "5"}),
                 InputError);
    try {
        parseGenblindsArgs(A{"genblinds", "m", "b", "1", "2", "3", "4", "5", "+r", "0.4"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "curvature radius 0.4 is less than half the depth (1)");
    }
    try {
        parseGenblindsArgs(A{"genblinds", "m", "b"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "usage: genblinds mat name depth width height nslats angle [-r|+r rcurv]");
    }
}

}  // namespace
}  // namespace rp::gen
