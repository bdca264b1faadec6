// Tests for genbox: byte-identical output to RADIANCE's genbox (tests/data/gen_radiance),
// corner geometry and outward/inward normals by Newell's method, the Cornell validation
// scene's genbox+xform polygons, bevelled and rounded variants (closure, convexity,
// radius), and one test per kind of bad input.
#include "gen/genbox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "gen/test_reference.h"
#include "util/error.h"
#include "util/shared_for_tests.h"

namespace rp::gen {
namespace {

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string s; in >> s;) w.push_back(s);
    return w;
}

Vec3 centroid(const std::vector<Vec3>& pts) {
    Vec3 c;
    for (const Vec3& p : pts) c += p;
    return c / double(pts.size());
}

// Closed, convex, consistently oriented polyhedron: area vectors sum to zero and every
// vertex lies behind every face plane (outward) or in front of it (inward).
void expectClosedConvex(const std::vector<GenSurface>& faces, bool inward) {
    Vec3 sum;
    for (const GenSurface& f : faces) sum += newellNormal(f.points);
    EXPECT_NEAR(length(sum), 0.0, 1e-9);
    for (const GenSurface& f : faces) {
        Vec3 n = normalize(newellNormal(f.points));
        Vec3 c = centroid(f.points);
        for (const GenSurface& g : faces)
            for (const Vec3& p : g.points) {
                double s = dot(p - c, n);
                if (inward)
                    EXPECT_GE(s, -1e-9) << f.name << " vs " << g.name;
                else
                    EXPECT_LE(s, 1e-9) << f.name << " vs " << g.name;
            }
    }
}

// Volume by the divergence theorem (positive for outward normals).
double volume(const std::vector<GenSurface>& faces) {
    double v = 0;
    for (const GenSurface& f : faces) v += dot(centroid(f.points), newellNormal(f.points)) / 2;
    return v / 3;
}

TEST(Genbox, SquareBoxFacesCornersAndNormals) {
    GenboxOptions opt = parseGenboxArgs({"genbox", "m", "b", "1", "2", "3"});
    auto faces = genboxSurfaces(opt);
    ASSERT_EQ(faces.size(), 6u);
    const char* names[6] = {"b.1540", "b.4620", "b.2310", "b.3267", "b.5137", "b.6457"};
    // Hand-worked outward normals: 1540 is y = 0, 4620 x = 0, 2310 z = 0, 3267 y = 2,
    // 5137 x = 1, 6457 z = 3.
    const Vec3 normals[6] = {{0, -1, 0}, {-1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(faces[i].name, names[i]);
        ASSERT_EQ(faces[i].points.size(), 4u);
        Vec3 n = newellNormal(faces[i].points);
        double area = length(n) / 2;
        EXPECT_NEAR(dot(n, normals[i]) / 2, area, 1e-12) << names[i];
    }
    // First face in RADIANCE's vertex order: corners 1, 5, 4, 0.
    EXPECT_EQ(faces[0].points[0], Vec3(1, 0, 0));
    EXPECT_EQ(faces[0].points[1], Vec3(1, 0, 3));
    EXPECT_EQ(faces[0].points[2], Vec3(0, 0, 3));
    EXPECT_EQ(faces[0].points[3], Vec3(0, 0, 0));
    expectClosedConvex(faces, false);
    EXPECT_NEAR(volume(faces), 6.0, 1e-12);
}

TEST(Genbox, MatchesRadianceByteForByte) {
    for (const char* file :
         {"genbox_square.rad", "genbox_inward.rad", "genbox_bevel.rad", "genbox_bevel_inward.rad",
          "genbox_bevel_n4.rad", "genbox_round.rad", "genbox_round_inward_n2.rad",
          "genbox_round_n4.rad", "genbox_round_inward_n3.rad"}) {
        auto ref = testing::readReferenceOutput(file);
        ASSERT_GE(ref.args.size(), 6u) << file;
        EXPECT_EQ(genbox(ref.args), ref.text) << file;
    }
}

// Outputs too big to store, by size and FNV-1a hash of RADIANCE's output for the same
// command: -i with -r tessellates with 32 facets per quarter circle (8582 polygons), and
// -n 8 on an unequal box.
TEST(Genbox, LargeTessellationsMatchRadiance) {
    std::string in = genbox({"genbox", "m", "b", "1", "2", "3", "-r", "0.1", "-i"});
    EXPECT_EQ(in.size(), 1721168u);
    EXPECT_EQ(testing::fnv1a64(in), 0xfdc59790be01a9bcULL);
    std::string n8 = genbox({"genbox", "m", "b", "2", "1", "0.5", "-r", "0.2", "-n", "8"});
    EXPECT_EQ(n8.size(), 126901u);
    EXPECT_EQ(testing::fnv1a64(n8), 0xd6bd212119ae9172ULL);
}

// RADIANCE compat: -i mirrors every corner through the box centre (the first polygon
// starts at (0, 2, 3) where the outward box starts at (1, 0, 0)), reversing orientation.
TEST(Genbox, InwardMirrorsTheBox) {
    auto out = genboxSurfaces(parseGenboxArgs({"genbox", "m", "b", "1", "2", "3"}));
    auto in = genboxSurfaces(parseGenboxArgs({"genbox", "m", "b", "1", "2", "3", "-i"}));
    ASSERT_EQ(in.size(), out.size());
    for (size_t i = 0; i < in.size(); ++i) {
        EXPECT_EQ(in[i].name, out[i].name);
        for (size_t k = 0; k < in[i].points.size(); ++k)
            EXPECT_EQ(in[i].points[k], Vec3(1, 2, 3) - out[i].points[k]);
    }
    EXPECT_EQ(in[0].points[0], Vec3(0, 2, 3));
    expectClosedConvex(in, true);
    EXPECT_NEAR(volume(in), -6.0, 1e-12);
}

// The Cornell scene pastes "genbox mirror_mat mbox 1.5 1.5 3.0 | xform -t -0.75 -0.75 0
// -rz 20 -t 1.5 3.6 0"; apply that transform by hand and compare every vertex.
TEST(Genbox, MatchesCornellValidationScene) {
    RP_REQUIRE_SHARED("validation/cornell/scene.rad");
    std::ifstream f(std::string(RP_SHARED_DIR) + "/validation/cornell/scene.rad");
    std::map<std::string, std::vector<Vec3>> ref;
    std::string line;
    while (std::getline(f, line)) {
        auto w = words(line);
        if (w.size() == 3 && w[1] == "polygon" && w[2].rfind("mbox.", 0) == 0) {
            std::string name = w[2];
            std::getline(f, line);
            std::getline(f, line);
            std::getline(f, line);  // "12"
            for (int k = 0; k < 4; ++k) {
                std::getline(f, line);
                auto v = words(line);
                ref[name].push_back({std::stod(v[0]), std::stod(v[1]), std::stod(v[2])});
            }
        }
    }
    ASSERT_EQ(ref.size(), 6u);
    auto faces =
        genboxSurfaces(parseGenboxArgs({"genbox", "mirror_mat", "mbox", "1.5", "1.5", "3.0"}));
    double c = std::cos(20 * kPi / 180), s = std::sin(20 * kPi / 180);
    for (const GenSurface& face : faces) {
        ASSERT_TRUE(ref.count(face.name)) << face.name;
        for (size_t k = 0; k < 4; ++k) {
            Vec3 p = face.points[k] - Vec3(0.75, 0.75, 0);
            Vec3 q(c * p.x - s * p.y + 1.5, s * p.x + c * p.y + 3.6, p.z);
            EXPECT_NEAR(length(q - ref[face.name][k]), 0.0, 1e-9) << face.name << " " << k;
        }
    }
}

TEST(Genbox, TextLayoutMatchesRadiance) {
    std::string out = genbox({"genbox", "m", "b", "1", "2", "3"});
    EXPECT_EQ(out.substr(0, out.find('\n') + 1), "# genbox m b 1 2 3\n");
    EXPECT_NE(out.find("\nm polygon b.1540\n0\n0\n12\n"
                       "\t                 1\t                 0\t                 0\n"),
              std::string::npos);
}

TEST(Genbox, BevelledBoxIsClosedAndConvex) {
    auto faces = genboxSurfaces(parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-b", "0.25"}));
    ASSERT_EQ(faces.size(), 6u + 12u + 8u);
    EXPECT_EQ(faces[0].name, "b.dhgc");  // RADIANCE's letters for corner codes 051 055 054 050
    EXPECT_EQ(faces[18].points.size(), 3u);
    expectClosedConvex(faces, false);
    double v = volume(faces);
    EXPECT_LT(v, 24.0);
    EXPECT_GT(v, 1.5 * 2.5 * 3.5);
    auto inward =
        genboxSurfaces(parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-b", "0.25", "-i"}));
    expectClosedConvex(inward, true);
}

TEST(Genbox, RoundedBoxUsesCylindersAndSpheres) {
    for (const char* n : {"1", "2"}) {  // -n 1 and -n 2 keep RADIANCE's exact rounding
        auto s = genboxSurfaces(
            parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-r", "0.5", "-n", n}));
        ASSERT_EQ(s.size(), 6u + 12u + 8u);
        EXPECT_EQ(s[6].kind, GenSurface::Kind::Cylinder);
        EXPECT_EQ(s[6].name, "b.st");  // corner codes 070 071 in RADIANCE's alphabet
        EXPECT_EQ(s[6].points[0], Vec3(0.5, 0.5, 0.5));
        EXPECT_EQ(s[6].points[1], Vec3(1.5, 0.5, 0.5));
        EXPECT_DOUBLE_EQ(s[6].radius, 0.5);
        EXPECT_EQ(s[25].kind, GenSurface::Kind::Sphere);
        EXPECT_EQ(s[25].name, "b.z");
        EXPECT_EQ(s[25].points[0], Vec3(1.5, 2.5, 3.5));
    }
}

TEST(Genbox, TessellatedRoundingLiesOnTheRoundedSurface) {
    double r = 0.5;
    for (const char* n : {"3", "4"}) {  // both round up to 4 facets per quarter circle
        GenboxOptions opt =
            parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-r", "0.5", "-n", n});
        EXPECT_EQ(genboxRoundingSegments(opt), 4);
        auto faces = genboxSurfaces(opt);
        // 12 edges of 4 strips, 8 corners split twice into four triangles, 6 faces
        ASSERT_EQ(faces.size(), 12u * 4u + 8u * 16u + 6u);
        EXPECT_EQ(faces.front().name, "b.1");
        EXPECT_EQ(faces.front().points.size(), 3u);
        EXPECT_EQ(faces.back().name, "b.182");
        EXPECT_EQ(faces.back().points.size(), 4u);  // the first shrunken face, now last
        expectClosedConvex(faces, false);
        for (size_t i = 0; i + 6 < faces.size(); ++i)
            for (const Vec3& p : faces[i].points) {
                Vec3 inner(std::clamp(p.x, r, 2 - r), std::clamp(p.y, r, 3 - r),
                           std::clamp(p.z, r, 4 - r));
                EXPECT_NEAR(length(p - inner), r, 1e-12) << faces[i].name;
            }
        // The exact rounded volume: inner box + slabs + quarter cylinders + sphere.
        double exact = 1 * 2 * 3 + 2 * r * (1 * 2 + 2 * 3 + 1 * 3) + kPi * r * r * (1 + 2 + 3) +
                       4.0 / 3.0 * kPi * r * r * r;
        EXPECT_LT(volume(faces), exact);
        EXPECT_GT(volume(faces), 0.97 * exact);
    }
    GenboxOptions in = parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-r", "0.5", "-i"});
    EXPECT_EQ(genboxRoundingSegments(in), 32);
    expectClosedConvex(genboxSurfaces(in), true);
    EXPECT_EQ(genboxRoundingSegments(
                  parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-r", "0.5", "-n", "5"})),
              8);
    EXPECT_EQ(genboxRoundingSegments(
                  parseGenboxArgs({"genbox", "m", "b", "2", "3", "4", "-b", "0.5", "-n", "5"})),
              0);
}

TEST(Genbox, BadInput) {
    using A = std::vector<std::string>;
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "-2", "3"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "0", "2", "3"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2x", "3"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-q"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-b"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-b", "0.5"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-b", "-0.1"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-r", ".1", "-b", ".1"}),
                 InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-r", ".1", "-s"}),
                 InputError);  // not supported yet
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-o"}), InputError);
    EXPECT_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-r", ".1", "-n", "0"}),
                 InputError);
    EXPECT_NO_THROW(parseGenboxArgs(A{"genbox", "m", "b", "1", "2", "3", "-n", "3"}));  // ignored
    try {
        parseGenboxArgs(A{"genbox", "m", "b", "1", "-2", "3"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "y size must be positive, got -2");
    }
}

}  // namespace
}  // namespace rp::gen
