// Tests for genprism: names and order, orientation of ends and sides by Newell's method
// (clockwise vertices face outward, counter-clockwise inward), slanted extrusion, -c and
// -e, rounded corners, vertices from a stream, and bad input.
#include "gen/genprism.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace rp::gen {
namespace {

std::vector<GenSurface> prism(const std::vector<std::string>& args) {
    std::istringstream none;
    return genprismSurfaces(parseGenprismArgs(args, none));
}

Vec3 centroid(const std::vector<Vec3>& pts) {
    Vec3 c;
    for (const Vec3& p : pts) c += p;
    return c / double(pts.size());
}

TEST(Genprism, NamesOrderAndGeometry) {
    auto s = prism({"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1"});
    ASSERT_EQ(s.size(), 5u);
    const char* names[5] = {"p.b", "p.t", "p.1", "p.2", "p.3"};
    for (int i = 0; i < 5; ++i) EXPECT_EQ(s[i].name, names[i]);
    EXPECT_EQ(s[0].points, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(s[1].points, (std::vector<Vec3>{{0, 1, 1}, {1, 0, 1}, {0, 0, 1}}));
    // Side 1 joins vertex 1 to vertex 2: v1, v1 + l, v2 + l, v2.
    EXPECT_EQ(s[2].points, (std::vector<Vec3>{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}));
    EXPECT_EQ(s[4].points, (std::vector<Vec3>{{0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {0, 0, 0}}));
}

// Counter-clockwise (seen from +z) vertices with the default +z extrusion give inward
// normals; clockwise ones outward. Checked for every face against the solid's centroid.
TEST(Genprism, OrientationFollowsVertexOrder) {
    for (bool clockwise : {false, true}) {
        std::vector<std::string> args = {"genprism", "m", "p", "4"};
        std::vector<std::pair<const char*, const char*>> v = {
            {"0", "0"}, {"2", "0"}, {"2", "1"}, {"0", "1"}};
        if (clockwise) std::swap(v[1], v[3]);
        for (auto [x, y] : v) {
            args.push_back(x);
            args.push_back(y);
        }
        for (const char* w : {"-l", "0.5", "0.2", "3"}) args.push_back(w);
        auto s = prism(args);
        ASSERT_EQ(s.size(), 6u);
        Vec3 centre;
        for (const GenSurface& f : s) centre += centroid(f.points);
        centre = centre / 6.0;
        Vec3 total;
        for (const GenSurface& f : s) {
            Vec3 n = newellNormal(f.points);
            total += n;
            double side = dot(n, centroid(f.points) - centre);
            if (clockwise)
                EXPECT_GT(side, 0) << f.name;
            else
                EXPECT_LT(side, 0) << f.name;
        }
        EXPECT_NEAR(length(total), 0, 1e-12);  // closed
        // Top face lies on the extruded plane.
        for (const Vec3& p : s[1].points) EXPECT_DOUBLE_EQ(p.z, 3);
    }
}

TEST(Genprism, OpenAndEndlessVariants) {
    auto noEnds = prism({"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1", "-e"});
    ASSERT_EQ(noEnds.size(), 3u);
    EXPECT_EQ(noEnds[0].name, "p.1");
    auto open = prism({"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1", "-c"});
    ASSERT_EQ(open.size(), 4u);
    EXPECT_EQ(open.back().name, "p.2");
}

TEST(Genprism, RoundedCorners) {
    // Clockwise square (outward normals): every corner is convex, so each end gets a
    // sphere and a cylinder per vertex and each side its edge cylinder.
    auto s =
        prism({"genprism", "m", "p", "4", "0", "0", "0", "2", "2", "2", "2", "0", "-r", "0.25"});
    ASSERT_EQ(s.size(), 1u + 8u + 1u + 8u + 8u);
    EXPECT_EQ(s[0].name, "p.b");
    EXPECT_EQ(s[1].name, "p.bc1");
    EXPECT_EQ(s[1].kind, GenSurface::Kind::Sphere);
    EXPECT_EQ(s[2].name, "p.be1");
    // The bottom face shrinks by the radius.
    EXPECT_NEAR(s[0].points[0].x, 0.25, 1e-12);
    EXPECT_NEAR(s[0].points[0].y, 0.25, 1e-12);
    EXPECT_NEAR(s[1].points[0].z, 0.25, 1e-12);
    std::string text = formatGenprismSurface("m", s[1]);
    EXPECT_EQ(text,
              "\nm sphere p.bc1\n0\n0\n4               0.25               0.25"
              "               0.25               0.25\n");
    EXPECT_EQ(s[9].name, "p.t");
    EXPECT_EQ(s[18].name, "p.1");
    EXPECT_EQ(s[19].name, "p.e1");
}

TEST(Genprism, VerticesFromStream) {
    std::istringstream in("0 0\n1 0\n0.5 0.866\n");
    GenprismOptions o = parseGenprismArgs({"genprism", "m", "p", "-"}, in);
    ASSERT_EQ(o.vertices.size(), 3u);
    EXPECT_DOUBLE_EQ(o.vertices[2][1], 0.866);
    std::istringstream none;
    std::string out = genprism({"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1"}, none);
    EXPECT_EQ(out.substr(0, out.find('\n')), "# genprism m p 3 0 0 1 0 0 1");
}

TEST(Genprism, BadInput) {
    using A = std::vector<std::string>;
    auto message = [](const A& a) {
        std::istringstream none;
        try {
            parseGenprismArgs(a, none);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(A{"genprism", "m", "p", "2", "0", "0", "1", "0"}),
              "not enough vertices (need at least 3)");
    EXPECT_EQ(message(A{"genprism", "m", "p", "3", "0", "0", "1", "0", "0"}).substr(0, 20),
              "expected 3 vertices ");
    EXPECT_EQ(
        message(A{"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1", "-l", "0", "0", "0"}),
        "zero extrusion vector");
    EXPECT_EQ(message(A{"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1", "-r", "2"}),
              "rounding greater than height");
    EXPECT_EQ(message(A{"genprism", "m", "p", "3", "0", "0", "1", "0", "0", "1", "-x"}),
              "unknown option '-x'");
    EXPECT_EQ(message(A{"genprism", "m", "p", "/nonexistent/verts"}),
              "/nonexistent/verts: cannot open vertex file");
    std::istringstream none;
    EXPECT_THROW(
        genprismSurfaces(parseGenprismArgs(
            A{"genprism", "m", "p", "3", "0", "0", "0", "0", "1", "1", "-r", "0.1"}, none)),
        InputError);  // degenerate side
}

}  // namespace
}  // namespace rp::gen
