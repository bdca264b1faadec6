// lib/surf.cal and lib/rev.cal, the textures that gensurf -s and genrev -s output names:
// at a gensurf vertex the smoothed normal N + (surf_dx, surf_dy, surf_dz) points along
// the analytic surface normal; genrev's smoothed normals are unit vectors on N's side.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "calc/program.h"
#include "gen/genrev.h"
#include "gen/gensurf.h"
#include "scene/reader.h"

namespace rp::gen {
namespace {

struct Smoothing {
    std::shared_ptr<const calc::Program> program;
    calc::Entry d[3];
};

Smoothing load(const std::string& file, const std::string& prefix) {
    calc::Builder b({std::string(RP_SOURCE_DIR) + "/lib"});
    b.loadFile("rayinit.cal");
    b.loadFile(file);
    Smoothing s{b.build(), {}};
    for (int i = 0; i < 3; ++i) s.d[i] = *s.program->variable(prefix + "_d" + "xyz"[i]);
    return s;
}

Vec3 smoothed(Smoothing& s, const Vec3& p, const Vec3& n, const std::vector<double>& args) {
    calc::Evaluator ev(s.program);
    calc::RayContext ctx;
    ctx.P = p;
    ctx.N = n;
    ctx.args = args;
    ev.setRay(ctx);
    return n + Vec3{ev.eval(s.d[0]), ev.eval(s.d[1]), ev.eval(s.d[2])};
}

Scene parseWithMaterial(const std::string& text) {
    return parseScene("void plastic m 0 0 5 .5 .5 .5 0 0\n" + text, "gen.rad");
}

TEST(SmoothingCal, GensurfVertexNormalsAreTheSurfaceNormals) {
    std::vector<std::string> warnings;
    std::istringstream none;
    Scene scene = parseWithMaterial(
        gensurf({"gensurf", "m", "s", "s", "t", "s*s+t*t", "3", "3", "-s"}, {}, none, warnings));
    Smoothing surf = load("surf.cal", "surf");
    int checked = 0;
    for (const Primitive& p : scene.prims) {
        if (p.type != PrimType::Polygon || p.modifier < 0) continue;
        const Primitive& tex = scene.prims[p.modifier];
        ASSERT_EQ(tex.type, PrimType::Texfunc);
        std::vector<Vec3> verts;
        for (size_t k = 0; k + 2 < p.rargs.size(); k += 3)
            verts.push_back({p.rargs[k], p.rargs[k + 1], p.rargs[k + 2]});
        Vec3 face = normalize(newellNormal(verts));
        for (const Vec3& v : verts) {
            Vec3 n = normalize(smoothed(surf, v, face, tex.rargs));
            Vec3 exact = normalize(Vec3{-2 * v.x, -2 * v.y, 1});
            if (dot(exact, face) < 0) exact = -exact;
            // gensurf's vertex normals come from differences over the grid, exact for
            // this paraboloid; the printed coefficients hold 9 digits.
            EXPECT_NEAR(dot(n, exact), 1, 1e-7) << "vertex " << v.x << " " << v.y;
            ++checked;
        }
    }
    EXPECT_GE(checked, 9 * 3);
}

TEST(SmoothingCal, GenrevNormalsAreUnitAndOnTheSurfaceSide) {
    std::vector<std::string> warnings;
    Scene scene =
        parseWithMaterial(genrev({"genrev", "m", "r", "t", "1+0.5*t*t", "4", "-s"}, {}, warnings));
    Smoothing rev = load("rev.cal", "rev");
    int checked = 0;
    for (const Primitive& p : scene.prims) {
        if (p.type != PrimType::Cone) continue;
        const Primitive& tex = scene.prims[p.modifier];
        ASSERT_EQ(tex.type, PrimType::Texfunc);
        // Halfway along the segment, on the +x side: the cone's outward normal there.
        Vec3 a{p.rargs[0], p.rargs[1], p.rargs[2]}, b{p.rargs[3], p.rargs[4], p.rargs[5]};
        double r0 = p.rargs[6], r1 = p.rargs[7];
        Vec3 point{(r0 + r1) / 2, 0, (a.z + b.z) / 2};
        Vec3 outward = normalize(Vec3{b.z - a.z, 0, r0 - r1});
        Vec3 n = smoothed(rev, point, outward, tex.rargs);
        EXPECT_NEAR(length(n), 1, 1e-9);
        EXPECT_GT(dot(n, outward), 0.9);  // smoothing tilts the normal only slightly
        ++checked;
    }
    EXPECT_EQ(checked, 4);
}

}  // namespace
}  // namespace rp::gen
