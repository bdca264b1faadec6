// Ear clipping: coverage (triangle areas sum to the polygon's area), orientation, and
// holes joined by seams staying empty.
#include "geometry/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/polygon.h"

namespace rp {
namespace {

std::vector<Vec3> loop2d(std::initializer_list<std::pair<double, double>> xy, double z = 0) {
    std::vector<Vec3> v;
    for (auto [x, y] : xy) v.push_back({x, y, z});
    return v;
}

double triArea(const std::vector<Vec3>& v, const TriIndices& t, const Vec3& n) {
    return 0.5 * dot(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]), n);
}

// Every triangle counter-clockwise about n (positive area) and areas summing to the
// polygon's Newell area; tolerance: double rounding on unit-sized input.
void expectCovers(const std::vector<Vec3>& v, const Triangulation& tri, const Vec3& n) {
    double sum = 0;
    for (const TriIndices& t : tri.triangles) {
        double a = triArea(v, t, n);
        EXPECT_GT(a, 0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
        sum += a;
    }
    EXPECT_NEAR(sum, 0.5 * dot(newellNormal(v), n), 1e-12);
    EXPECT_TRUE(tri.clean);
}

bool insideAnyTriangle(const std::vector<Vec3>& v, const Triangulation& tri, double x, double y) {
    for (const TriIndices& t : tri.triangles) {
        auto side = [&](int a, int b) {
            const Vec3 &p = v[t[a]], &q = v[t[b]];
            return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
        };
        if (side(0, 1) > 0 && side(1, 2) > 0 && side(2, 0) > 0) return true;
    }
    return false;
}

const Vec3 kUp{0, 0, 1};

TEST(Triangulate, Triangle) {
    auto v = loop2d({{0, 0}, {1, 0}, {0, 1}});
    auto tri = triangulatePolygon(v, kUp);
    ASSERT_EQ(tri.triangles.size(), 1u);
    expectCovers(v, tri, kUp);
}

TEST(Triangulate, ConvexWithCollinearVertices) {
    auto v = loop2d({{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0.5, 1}, {0, 1}});
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);
}

TEST(Triangulate, ClockwiseSeenFromNormalSideIsMirroredCorrectly) {
    // Same square, but we look along -z: the loop is CCW about -z when reversed.
    auto v = loop2d({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    Vec3 down{0, 0, -1};
    auto tri = triangulatePolygon(v, down);
    expectCovers(v, tri, down);
}

TEST(Triangulate, ConcaveLShape) {
    auto v = loop2d({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
    auto tri = triangulatePolygon(v, kUp);
    EXPECT_EQ(tri.triangles.size(), 4u);
    expectCovers(v, tri, kUp);
    EXPECT_FALSE(insideAnyTriangle(v, tri, 1.5, 1.5));  // the notch
}

TEST(Triangulate, Star) {
    std::vector<Vec3> v;
    for (int i = 0; i < 10; ++i) {
        double a = 2 * kPi * i / 10, r = i % 2 ? 0.4 : 1.0;
        v.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    auto tri = triangulatePolygon(v, kUp);
    EXPECT_EQ(tri.triangles.size(), 8u);
    expectCovers(v, tri, kUp);
}

TEST(Triangulate, Comb) {
    // Five teeth: many reflex vertices that see each other.
    auto v = loop2d({{0, 0}, {9, 0}, {9, 3}, {8, 3}, {8, 1}, {7, 1}, {7, 3}, {6, 3}, {6, 1},
                     {5, 1}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1},
                     {1, 3}, {0, 3}});
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);
    EXPECT_NEAR(0.5 * newellNormal(v).z, 19.0, 1e-12);
    EXPECT_FALSE(insideAnyTriangle(v, tri, 1.5, 2));
    EXPECT_FALSE(insideAnyTriangle(v, tri, 7.5, 2.9));
}

// RADIANCE-style hole: outline CCW, seam to the hole, hole walked clockwise, seam back.
std::vector<Vec3> squareWithHole() {
    return loop2d({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0},  // outline and back to start
                   {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}}); // seam, hole (CW), seam
}

TEST(Triangulate, HoleJoinedBySeam) {
    auto v = squareWithHole();
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);  // 16 - 4 = 12
    EXPECT_NEAR(0.5 * newellNormal(v).z, 12.0, 1e-12);
    EXPECT_FALSE(insideAnyTriangle(v, tri, 2, 2));
    EXPECT_FALSE(insideAnyTriangle(v, tri, 1.1, 2.9));
    EXPECT_TRUE(insideAnyTriangle(v, tri, 0.5, 2));
    EXPECT_TRUE(insideAnyTriangle(v, tri, 3.6, 0.3));
}

TEST(Triangulate, TwoHolesAndFarFromOrigin) {
    // Two holes, each with its own seam, the whole thing 1 km away and tilted.
    auto flat = loop2d({{0, 0}, {6, 0}, {6, 3}, {0, 3}, {0, 0},
                        {1, 1}, {1, 2}, {2, 2}, {2, 1}, {1, 1},
                        {0, 0}, {4, 1}, {4, 2}, {5, 2}, {5, 1}, {4, 1}, {0, 0}});
    // drop the final duplicate of the first vertex (closing is implicit)
    flat.pop_back();
    std::vector<Vec3> v;
    Vec3 ex = normalize(Vec3{1, 1, 0}), ey = normalize(Vec3{-1, 1, 1});
    Vec3 n = normalize(cross(ex, ey)), base{1000, -1000, 500};
    for (const Vec3& p : flat) v.push_back(base + ex * p.x + ey * p.y);
    auto tri = triangulatePolygon(v, n);
    double sum = 0;
    for (const TriIndices& t : tri.triangles) {
        double a = triArea(v, t, n);
        EXPECT_GT(a, 0);
        sum += a;
    }
    EXPECT_NEAR(sum, 18 - 2, 1e-9);
    EXPECT_TRUE(tri.clean);
}

TEST(Triangulate, DegenerateInputDoesNotHang) {
    auto v = loop2d({{0, 0}, {1, 0}, {2, 0}, {1, 0}});  // zero area, folds back
    auto tri = triangulatePolygon(v, kUp);
    EXPECT_TRUE(tri.triangles.empty());
    auto bowtie = loop2d({{0, 0}, {1, 1}, {1, 0}, {0, 1}});  // self-intersecting
    auto t2 = triangulatePolygon(bowtie, kUp);
    EXPECT_LE(t2.triangles.size(), 2u);
}

}  // namespace
}  // namespace rp
