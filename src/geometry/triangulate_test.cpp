// Triangulation against RADIANCE's point-in-polygon rule (even-odd crossings, face.c
// inface): random points must be covered by exactly one triangle where the rule says
// inside and by none where it says outside, for hand-made cases, CAD-style walls with
// windows cut by seams, and thousands of random loops (self-intersecting included).
#include "geometry/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/polygon.h"

namespace rp {
namespace {

std::vector<Vec3> loop2d(const std::vector<std::pair<double, double>>& xy, double z = 0) {
    std::vector<Vec3> v;
    for (auto [x, y] : xy) v.push_back({x, y, z});
    return v;
}

double triArea(const Triangulation& tri, const TriIndices& t, const Vec3& n) {
    const auto& v = tri.vertices;
    return 0.5 * dot(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]), n);
}

// Every triangle counter-clockwise about n (positive area) and areas summing to the
// polygon's Newell area (right for loops that do not cross themselves); tolerance:
// double rounding on input of size ~10.
void expectCovers(const std::vector<Vec3>& v, const Triangulation& tri, const Vec3& n,
                  double tol = 1e-12) {
    double sum = 0;
    for (const TriIndices& t : tri.triangles) {
        double a = triArea(tri, t, n);
        EXPECT_GT(a, 0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
        sum += a;
    }
    EXPECT_NEAR(sum, 0.5 * dot(newellNormal(v), n), tol);
}

// 2D view of a loop in the xy plane for the reference tests.
struct P {
    double x, y;
};

// Even-odd crossing count along +x, as face.c inface counts it.
bool evenOddInside(const std::vector<P>& p, double x, double y) {
    bool in = false;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
        if ((p[i].y > y) != (p[j].y > y)) {
            double xc = p[j].x + (y - p[j].y) * (p[i].x - p[j].x) / (p[i].y - p[j].y);
            if (xc > x) in = !in;
        }
    }
    return in;
}

double distToSegment(const P& a, const P& b, double x, double y) {
    double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / l2, 0.0, 1.0) : 0;
    return std::hypot(a.x + t * dx - x, a.y + t * dy - y);
}

double distToLoop(const std::vector<P>& p, double x, double y) {
    double d = HUGE_VAL;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
        d = std::fmin(d, distToSegment(p[j], p[i], x, y));
    return d;
}

// Number of triangles containing (x, y): strictly (each edge function above +eps) and
// loosely (above -eps), in the xy projection, with eps a distance.
struct Cover {
    int strict = 0, loose = 0;
};

Cover coverAt(const Triangulation& tri, double x, double y, double eps, double sign) {
    Cover c;
    for (const TriIndices& t : tri.triangles) {
        double dmin = HUGE_VAL;
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = tri.vertices[t[k]];
            const Vec3& b = tri.vertices[t[(k + 1) % 3]];
            double ex = b.x - a.x, ey = b.y - a.y;
            double d = sign * (ex * (y - a.y) - ey * (x - a.x)) / std::hypot(ex, ey);
            dmin = std::fmin(dmin, d);
        }
        if (dmin > eps) ++c.strict;
        if (dmin >= -eps) ++c.loose;
    }
    return c;
}

// Random points in the loop's bounding box, away from its edges by `margin`: inside
// points covered exactly once, outside points not at all. Returns points checked.
int checkAgainstEvenOdd(const std::vector<Vec3>& v, const Vec3& n, std::mt19937& rng, int samples,
                        double margin, const std::string& what) {
    Triangulation tri = triangulatePolygon(v, n);
    std::vector<P> p;
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (const Vec3& q : v) {
        p.push_back({q.x, q.y});
        x0 = std::fmin(x0, q.x), x1 = std::fmax(x1, q.x);
        y0 = std::fmin(y0, q.y), y1 = std::fmax(y1, q.y);
    }
    double sign = n.z > 0 ? 1 : -1;
    for (const TriIndices& t : tri.triangles) EXPECT_GT(triArea(tri, t, n), 0) << what;
    std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1);
    int checked = 0;
    for (int s = 0; s < samples; ++s) {
        double x = ux(rng), y = uy(rng);
        if (distToLoop(p, x, y) < margin) continue;
        ++checked;
        bool in = evenOddInside(p, x, y);
        Cover c = coverAt(tri, x, y, 1e-6 * margin, sign);
        if (in) {
            EXPECT_GE(c.loose, 1) << what << ": inside point (" << x << ", " << y << ") lost";
            EXPECT_LE(c.strict, 1) << what << ": point (" << x << ", " << y << ") covered twice";
        } else {
            EXPECT_EQ(c.strict, 0) << what << ": outside point (" << x << ", " << y << ") covered";
        }
        if (::testing::Test::HasFailure()) return checked;
    }
    return checked;
}

// No triangle vertex lies inside another triangle's edge: rays cannot slip through
// cracks where one triangle's edge meets two of a neighbour.
void expectNoTJunctions(const Triangulation& tri, double tol) {
    for (const TriIndices& t : tri.triangles)
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = tri.vertices[t[k]];
            const Vec3& b = tri.vertices[t[(k + 1) % 3]];
            double len = length(b - a);
            for (size_t i = 0; i < tri.vertices.size(); ++i) {
                if (i == t[k] || i == t[(k + 1) % 3]) continue;
                const Vec3& q = tri.vertices[i];
                double s = dot(q - a, b - a) / (len * len);
                if (s <= 1e-9 || s >= 1 - 1e-9) continue;
                if (length(q - (a + (b - a) * s)) > tol) continue;
                // A vertex strictly inside an edge is a T-junction only if it is a
                // corner of some triangle, which every vertex is.
                ADD_FAILURE() << "vertex " << i << " on edge " << t[k] << "-" << t[(k + 1) % 3];
                return;
            }
        }
}

const Vec3 kUp{0, 0, 1};

TEST(Triangulate, Triangle) {
    auto v = loop2d({{0, 0}, {1, 0}, {0, 1}});
    auto tri = triangulatePolygon(v, kUp);
    ASSERT_EQ(tri.triangles.size(), 1u);
    expectCovers(v, tri, kUp);
}

TEST(Triangulate, ConvexWithCollinearVerticesIsAFanOfTheLoop) {
    auto v = loop2d({{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0.5, 1}, {0, 1}});
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);
    ASSERT_EQ(tri.vertices.size(), v.size());
    for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(tri.vertices[i].x, v[i].x);
}

TEST(Triangulate, ClockwiseSeenFromNormalSideIsMirroredCorrectly) {
    // Same square, but we look along -z: the loop is CCW about -z when reversed.
    auto v = loop2d({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    Vec3 down{0, 0, -1};
    auto tri = triangulatePolygon(v, down);
    expectCovers(v, tri, down);
    auto l = loop2d({{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}});  // an L, clockwise
    expectCovers(l, triangulatePolygon(l, down), down);
}

TEST(Triangulate, ConcaveLShape) {
    auto v = loop2d({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);
    EXPECT_EQ(coverAt(tri, 1.5, 1.5, 0, 1).loose, 0);  // the notch
    expectNoTJunctions(tri, 1e-12);
}

TEST(Triangulate, Star) {
    std::vector<Vec3> v;
    for (int i = 0; i < 10; ++i) {
        double a = 2 * kPi * i / 10, r = i % 2 ? 0.4 : 1.0;
        v.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);
    expectNoTJunctions(tri, 1e-12);
}

TEST(Triangulate, Comb) {
    auto v =
        loop2d({{0, 0}, {9, 0}, {9, 3}, {8, 3}, {8, 1}, {7, 1}, {7, 3}, {6, 3}, {6, 1}, {5, 1},
                {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);
    EXPECT_NEAR(0.5 * newellNormal(v).z, 19.0, 1e-12);
    EXPECT_EQ(coverAt(tri, 1.5, 2, 0, 1).loose, 0);
    EXPECT_EQ(coverAt(tri, 7.5, 2.9, 0, 1).loose, 0);
    expectNoTJunctions(tri, 1e-12);
}

// RADIANCE-style hole: outline CCW, seam to the hole, hole walked clockwise, seam back.
TEST(Triangulate, HoleJoinedBySeam) {
    auto v =
        loop2d({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
    auto tri = triangulatePolygon(v, kUp);
    expectCovers(v, tri, kUp);  // 16 - 4 = 12
    EXPECT_NEAR(0.5 * newellNormal(v).z, 12.0, 1e-12);
    EXPECT_EQ(coverAt(tri, 2, 2, 0, 1).loose, 0);
    EXPECT_EQ(coverAt(tri, 1.1, 2.9, 0, 1).loose, 0);
    EXPECT_EQ(coverAt(tri, 0.3, 2.1, 1e-9, 1).strict, 1);
    EXPECT_EQ(coverAt(tri, 3.6, 0.3, 1e-9, 1).strict, 1);
    // Points along the seam (0,0)-(1,1) are covered: no crack between its two sides.
    for (double s : {0.1, 0.37, 0.5, 0.93}) EXPECT_GE(coverAt(tri, s, s, 0, 1).loose, 1);
    expectNoTJunctions(tri, 1e-12);
}

TEST(Triangulate, TwoHolesAndFarFromOrigin) {
    // Two holes, each with its own seam, the whole thing 1 km away and tilted.
    auto flat = loop2d({{0, 0},
                        {6, 0},
                        {6, 3},
                        {0, 3},
                        {0, 0},
                        {1, 1},
                        {1, 2},
                        {2, 2},
                        {2, 1},
                        {1, 1},
                        {0, 0},
                        {4, 1},
                        {4, 2},
                        {5, 2},
                        {5, 1},
                        {4, 1}});
    std::vector<Vec3> v;
    Vec3 ex = normalize(Vec3{1, 1, 0}), ey = normalize(Vec3{-1, 1, 1});
    Vec3 n = normalize(cross(ex, ey)), base{1000, -1000, 500};
    for (const Vec3& p : flat) v.push_back(base + ex * p.x + ey * p.y);
    auto tri = triangulatePolygon(v, n);
    double sum = 0;
    for (const TriIndices& t : tri.triangles) {
        double a = triArea(tri, t, n);
        EXPECT_GT(a, 0);
        sum += a;
    }
    EXPECT_NEAR(sum, 18 - 2, 1e-9);
    // New corners lie in the polygon's plane.
    double off = dot(n, v[0]);
    for (const Vec3& p : tri.vertices) EXPECT_NEAR(dot(n, p), off, 1e-9);
}

TEST(Triangulate, DegenerateInputDoesNotHang) {
    auto v = loop2d({{0, 0}, {1, 0}, {2, 0}, {1, 0}});  // zero area, folds back
    EXPECT_TRUE(triangulatePolygon(v, kUp).triangles.empty());
    // A bowtie: even-odd covers both lobes (RADIANCE's inface says both are inside).
    auto bowtie = loop2d({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
    auto t2 = triangulatePolygon(bowtie, kUp);
    double sum = 0;
    for (const TriIndices& t : t2.triangles) sum += std::fabs(triArea(t2, t, kUp));
    EXPECT_NEAR(sum, 0.5, 1e-12);
    EXPECT_GE(coverAt(t2, 0.1, 0.5, 0, 1).loose + coverAt(t2, 0.1, 0.5, 0, -1).loose, 1);
}

// A wall 10 x 3 with windows cut by seams, in the ways CAD exporters and hand editing
// write them: with and without the repeated return vertex, two windows on one seam
// chain or on seams of their own, a seam along the floor line (collinear with the
// outline), and windows touching each other.
std::vector<std::vector<Vec3>> cadWalls() {
    std::vector<std::vector<std::pair<double, double>>> w = {
        // seam from the first corner, return vertex repeated
        {{0, 0}, {10, 0}, {10, 3}, {0, 3}, {0, 0}, {2, 1}, {2, 2.8}, {6, 2.8}, {6, 1}, {2, 1}},
        // return vertex not repeated: the loop closes from the hole straight back
        {{0, 0}, {10, 0}, {10, 3}, {0, 3}, {0, 0}, {2, 1}, {2, 2.8}, {6, 2.8}, {6, 1}},
        // seam from a corner to the hole, then on around the outline
        {{0, 0}, {10, 0}, {2, 1}, {2, 2.8}, {6, 2.8}, {6, 1}, {2, 1}, {10, 0}, {10, 3}, {0, 3}},
        // two windows chained on one seam
        {{0, 0},
         {10, 0},
         {10, 3},
         {0, 3},
         {0, 0},
         {1, 1},
         {1, 2},
         {4, 2},
         {4, 1},
         {1, 1},
         {6, 0.5},
         {6, 2.5},
         {9, 2.5},
         {9, 0.5},
         {6, 0.5},
         {1, 1}},
        // seam running along the floor line, then up to a window (collinear seam edges)
        {{0, 0},
         {10, 0},
         {10, 3},
         {0, 3},
         {0, 0},
         {5, 0},
         {5, 1},
         {3, 1},
         {3, 2},
         {7, 2},
         {7, 1},
         {5, 1},
         {5, 0}},
        // two windows sharing a mullion line, each on its own seam from the corner
        {{0, 0},
         {10, 0},
         {10, 3},
         {0, 3},
         {0, 0},
         {2, 1},
         {2, 2},
         {5, 2},
         {5, 1},
         {2, 1},
         {0, 0},
         {5, 1},
         {5, 2},
         {8, 2},
         {8, 1},
         {5, 1}},
        // a door reaching the floor: the outline itself dips (no seam)
        {{0, 0}, {4, 0}, {4, 2.1}, {5, 2.1}, {5, 0}, {10, 0}, {10, 3}, {0, 3}},
    };
    std::vector<std::vector<Vec3>> out;
    for (auto& l : w) out.push_back(loop2d(l));
    return out;
}

TEST(Triangulate, CadWallsWithWindows) {
    std::mt19937 rng(7);
    for (size_t i = 0; i < cadWalls().size(); ++i) {
        auto v = cadWalls()[i];
        SCOPED_TRACE("wall " + std::to_string(i));
        Triangulation tri = triangulatePolygon(v, kUp);
        expectNoTJunctions(tri, 1e-9);
        EXPECT_GT(checkAgainstEvenOdd(v, kUp, rng, 4000, 1e-6, "wall"), 3000);
        // Seen from the other side (normal flipped, loop reversed) it is the same set.
        std::vector<Vec3> r(v.rbegin(), v.rend());
        EXPECT_GT(checkAgainstEvenOdd(r, -kUp, rng, 2000, 1e-6, "reversed wall"), 1500);
    }
}

// Random loops: an outline with random radii around a centre, holes of the same kind
// joined by seams (with or without the return vertex), and fully random vertex
// sequences that cross themselves. The triangles must match the even-odd rule.
std::vector<std::pair<double, double>> starLoop(std::mt19937& rng, double cx, double cy, double r0,
                                                int n, bool clockwise) {
    std::uniform_real_distribution<double> ur(0.3, 1.0);
    std::vector<std::pair<double, double>> p;
    for (int i = 0; i < n; ++i) {
        double a = 2 * kPi * (clockwise ? n - i : i) / n, r = r0 * ur(rng);
        p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return p;
}

TEST(Triangulate, RandomSeamPolygonsMatchEvenOdd) {
    std::mt19937 rng(2026);
    std::uniform_int_distribution<int> nv(3, 40), nh(1, 3), coin(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        auto outer = starLoop(rng, 0, 0, 10, nv(rng), false);
        std::vector<std::pair<double, double>> loop = outer;
        int holes = nh(rng);
        for (int h = 0; h < holes; ++h) {
            // Small holes near the centre, where every outline radius (>= 3) leaves room.
            double cx = (h - 1) * 1.9, cy = (trial % 3 - 1) * 0.5;
            auto hole = starLoop(rng, cx, cy, 0.9, nv(rng), true);
            std::pair<double, double> from = coin(rng) ? outer[0] : loop.back();
            loop.push_back(from);
            loop.insert(loop.end(), hole.begin(), hole.end());
            loop.push_back(hole[0]);
            if (coin(rng)) loop.push_back(from);  // the repeated return vertex
        }
        SCOPED_TRACE("trial " + std::to_string(trial));
        checkAgainstEvenOdd(loop2d(loop), kUp, rng, 60, 1e-7, "seam polygon");
        if (::testing::Test::HasFailure()) return;
    }
}

TEST(Triangulate, RandomSelfIntersectingLoopsMatchEvenOdd) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> nv(3, 25);
    std::uniform_real_distribution<double> u(-5, 5);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<std::pair<double, double>> loop(nv(rng));
        for (auto& p : loop) p = {u(rng), u(rng)};
        auto v = loop2d(loop);
        Vec3 n = newellNormal(v).z >= 0 ? kUp : -kUp;
        SCOPED_TRACE("trial " + std::to_string(trial));
        checkAgainstEvenOdd(v, n, rng, 60, 1e-7, "random loop");
        if (::testing::Test::HasFailure()) return;
    }
}

TEST(Triangulate, ThousandsOfVerticesStaySmall) {
    // A concave outline of 4000 vertices (a gear) with a seam hole: the triangle count
    // stays linear in the vertex count.
    std::vector<std::pair<double, double>> l;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        double a = 2 * kPi * i / n, r = i % 2 ? 9 : 10;
        l.push_back({r * std::cos(a), r * std::sin(a)});
    }
    l.push_back(l[0]);
    for (int i = 0; i < 4; ++i)
        l.push_back({i == 0 || i == 1 ? -1.0 : 1.0, i == 0 || i == 3 ? -1.0 : 1.0});
    l.push_back({-1, -1});
    auto v = loop2d(l);
    Triangulation tri = triangulatePolygon(v, kUp);
    EXPECT_LT(tri.triangles.size(), size_t(20 * n));
    std::mt19937 rng(3);
    EXPECT_GT(checkAgainstEvenOdd(v, kUp, rng, 3000, 1e-7, "gear"), 2000);
}

}  // namespace
}  // namespace rp
