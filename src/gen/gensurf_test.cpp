// Tests for gensurf: a plane gives m*n quads with the right corners and (s,t) right-hand
// normals, a non-planar cell splits into triangles, valid(s,t) cuts holes, data files
// (z values and x y z triplets, at vertices or cell centres), -s Phong records, -o .OBJ
// text, and one test per kind of bad input.
#include "gen/gensurf.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "gen/gen_text.h"
#include "util/error.h"

namespace rp::gen {
namespace {

std::vector<SurfPolygon> polygons(const std::vector<std::string>& args,
                                  const SurfaceData* data = nullptr) {
    GensurfOptions opt = parseGensurfArgs(args);
    GenFunctions funcs(opt.sources, {"."});
    SurfGrid grid = sampleSurface(opt, funcs, data);
    return gensurfPolygons(opt, grid);
}

std::string run(const std::vector<std::string>& args, const std::string& stdinText = "") {
    std::istringstream in(stdinText);
    std::vector<std::string> warnings;
    return gensurf(args, {"."}, in, warnings);
}

std::string errorOf(const std::vector<std::string>& args, const std::string& stdinText = "") {
    try {
        run(args, stdinText);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Gensurf, PlaneGivesQuadsWithRightCornersAndNormal) {
    // x = 2s, y = 3t: cell (i,j) spans [i, i+1] x [j*1.5, (j+1)*1.5]; ds x dt = +z.
    auto polys = polygons({"gensurf", "m", "p", "2*s", "3*t", "1", "2", "2"});
    ASSERT_EQ(polys.size(), 4u);
    int k = 0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j, ++k) {
            const SurfPolygon& p = polys[k];
            EXPECT_EQ(p.name, "p." + std::to_string(k + 1));
            ASSERT_EQ(p.vertices.size(), 4u);
            Vec3 lo(i, 1.5 * j, 1), hi(i + 1, 1.5 * (j + 1), 1);
            Vec3 mn = p.vertices[0], mx = p.vertices[0];
            for (const Vec3& v : p.vertices) {
                mn = vmin(mn, v);
                mx = vmax(mx, v);
            }
            EXPECT_EQ(mn, lo);
            EXPECT_EQ(mx, hi);
            Vec3 n = newellNormal(p.vertices);
            EXPECT_NEAR(n.z, 3, 1e-12);  // Newell: twice the area 1.5, facing +z
            EXPECT_NEAR(n.x, 0, 1e-12);
            EXPECT_NEAR(n.y, 0, 1e-12);
        }
    // Swapping s and t flips the normal.
    for (const SurfPolygon& p : polygons({"gensurf", "m", "p", "t", "s", "0", "1", "1"}))
        EXPECT_LT(newellNormal(p.vertices).z, 0);
}

TEST(Gensurf, ExactTextOfOneQuad) {
    EXPECT_EQ(run({"gensurf", "m", "p", "s", "t", "0", "1", "1"}),
              "# gensurf m p s t 0 1 1\n"
              "\nm polygon p.1\n0\n0\n12\n"
              "                 1                  0                  0\n"
              "                 1                  1                  0\n"
              "                 0                  1                  0\n"
              "                 0                  0                  0\n");
}

TEST(Gensurf, NonPlanarCellSplitsIntoTriangles) {
    // A saddle z = s*t over one cell: two triangles, both facing +z.
    auto polys = polygons({"gensurf", "m", "h", "s", "t", "s*t", "1", "1"});
    ASSERT_EQ(polys.size(), 2u);
    for (const SurfPolygon& p : polys) {
        EXPECT_EQ(p.vertices.size(), 3u);
        EXPECT_GT(newellNormal(p.vertices).z, 0);
    }
    EXPECT_EQ(polys[1].name, "h.2");
}

TEST(Gensurf, ValidFunctionCutsHoles) {
    // Drop the corner vertex (s,t) = (1,1): its cell keeps one triangle.
    auto polys =
        polygons({"gensurf", "m", "p", "s", "t", "0", "2", "2", "-e", "valid(s,t) = 1.75 - s - t"});
    ASSERT_EQ(polys.size(), 4u);
    EXPECT_EQ(polys[3].vertices.size(), 3u);
    for (const SurfPolygon& p : polys)
        for (const Vec3& v : p.vertices) EXPECT_LT(v.x + v.y, 1.75);
}

TEST(Gensurf, HeightDataAtVerticesAndCentres) {
    const std::string file = "gensurf_test_height.dat";
    { std::ofstream(file) << "0 1 2\n3 4 5\n"; }  // (m+1)*(n+1) = 3*2 values, s fastest
    std::string out = run({"gensurf", "m", "g", "s*2", "t", file, "2", "1"});
    std::remove(file.c_str());
    // Corner (s,t) = (1,1) is x=2, y=1, z=5.
    EXPECT_NE(out.find("                 2                  1                  5\n"),
              std::string::npos);
    EXPECT_NE(out.find("                 0                  0                  0\n"),
              std::string::npos);

    std::istringstream in("1 2 3 4");  // m*n = 2*2 cell-centre values
    SurfaceData d = readSurfaceData(in, "c.dat", 2, 2, false);
    EXPECT_FALSE(d.atVertices);
    EXPECT_DOUBLE_EQ(d.value(0, 0.25, 0.25), 1);  // first cell centre
    EXPECT_DOUBLE_EQ(d.value(0, 0.75, 0.75), 4);
    EXPECT_DOUBLE_EQ(d.value(0, 0.5, 0.5), 2.5);
    EXPECT_DOUBLE_EQ(d.value(0, 0, 0.25), 0.5);  // extrapolated from the end cell
}

TEST(Gensurf, PointTripletsFromStandardInput) {
    std::string pts = "0 0 0  1 0 0\n0 1 0  1 1 1\n";
    std::string out = run({"gensurf", "m", "q", "-", "-", "-", "1", "1"}, pts);
    EXPECT_NE(out.find("q.2"), std::string::npos);  // non-planar: two triangles
    EXPECT_NE(out.find("                 1                  1                  1\n"),
              std::string::npos);
}

TEST(Gensurf, SmoothingWritesPhongTexfuncs) {
    std::string out = run({"gensurf", "m", "b", "s", "t", "s*s", "2", "2", "-s"});
    EXPECT_NE(out.find("\nm texfunc Phong\n4 surf_dx surf_dy surf_dz surf.cal\n0\n13\t2\n"),
              std::string::npos);
    EXPECT_NE(out.find("\nPhong polygon b.1\n0\n0\n12\n"), std::string::npos);
    // A plane needs no perturbation: every fitted normal equals the face normal.
    GensurfOptions opt = parseGensurfArgs({"gensurf", "m", "p", "s", "t", "0", "2", "2", "-s"});
    GenFunctions funcs(opt.sources, {"."});
    SurfGrid grid = sampleSurface(opt, funcs, nullptr);
    EXPECT_EQ(grid.at(1, 1).normal, Vec3(0, 0, 1));
    for (const SurfPolygon& p : gensurfPolygons(opt, grid)) {
        ASSERT_TRUE(p.phong);
        EXPECT_EQ(p.axis, 2);
        for (const Vec3& c : p.coef) EXPECT_NEAR(length(c), 0, 1e-12);
    }
}

TEST(Gensurf, PhongFitReproducesVertexNormals) {
    // On a curved surface the fitted normal, plus the face normal surf.cal adds back,
    // equals the averaged vertex normal at each corner of the polygon.
    GensurfOptions opt =
        parseGensurfArgs({"gensurf", "m", "b", "s", "t", "s*s+0.3*t*s", "3", "2", "-s"});
    GenFunctions funcs(opt.sources, {"."});
    SurfGrid grid = sampleSurface(opt, funcs, nullptr);
    auto polys = gensurfPolygons(opt, grid);
    ASSERT_FALSE(polys.empty());
    for (const SurfPolygon& p : polys) {
        ASSERT_TRUE(p.phong);
        Vec3 face = normalize(newellNormal(p.vertices));
        const int u = (p.axis + 1) % 3, v = (p.axis + 2) % 3;
        for (const Vec3& q : p.vertices) {
            Vec3 fit =
                p.coef[0] * (q[u] * q[v]) + p.coef[1] * q[u] + p.coef[2] * q[v] + p.coef[3] + face;
            Vec3 want;
            for (int i = 0; i <= 3; ++i)
                for (int j = 0; j <= 2; ++j)
                    if (length(grid.at(i, j).p - q) < 1e-12) want = grid.at(i, j).normal;
            EXPECT_NEAR(length(fit - want), 0, 1e-9) << p.name;
        }
    }
}

TEST(Gensurf, ObjOutput) {
    EXPECT_EQ(run({"gensurf", "wood", "p", "s", "t", "0", "1", "1", "-o"}),
              "# gensurf wood p s t 0 1 1 -o\n"
              "\nusemtl wood\n\no p\n\n"
              "v                  0                  0                  0\n\tvt 0 0\n"
              "v                  0                  1                  0\n\tvt 0 1\n"
              "v                  1                  0                  0\n\tvt 1 0\n"
              "v                  1                  1                  0\n\tvt 1 1\n"
              "f -2/-2/0 -1/-1/0 -3/-3/0 -4/-4/0\n");
    std::string smooth = run({"gensurf", "wood", "p", "s", "t", "0", "1", "1", "-o", "-s"});
    // RADIANCE compat: vt before vn, and an unchanged normal is written once and shared.
    EXPECT_NE(smooth.find("\tvt 0 0\n\tvn 0 0 1\n"), std::string::npos);
    EXPECT_EQ(smooth.find("\tvn", smooth.find("\tvn") + 1), std::string::npos);
    EXPECT_NE(smooth.find("f -2/-2/-1 -1/-1/-1 -3/-3/-1 -4/-4/-1\n"), std::string::npos);
}

TEST(Gensurf, BadInput) {
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "0", "2"}),
              "usage: gensurf mat name 'x(s,t)' 'y(s,t)' 'z(s,t)' m n [-e expr][-f file][-s][-o]");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "0", "2", "x"}),
              "bad n 'x': expected an integer");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "0", "0", "2"}), "m must be positive, got 0");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "0", "2", "2", "-x"}), "unknown option '-x'");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t+", "0", "2", "2"}),
              "y(s,t): syntax error: unexpected ';'");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "u", "2", "2"}),
              "z(s,t): undefined variable 'u'");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "-", "2", "2"}, "1 2 3"),
              "<stdin>: bad number of data points: expected 9 or 4 values, got 3");
    EXPECT_EQ(errorOf({"gensurf", "m", "p", "s", "t", "-", "1", "1"}, "1 2 x 4"),
              "<stdin>: garbled data value 'x'");
}

}  // namespace
}  // namespace rp::gen
