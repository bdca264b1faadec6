// WGMDfunc (wgmd.cpp): argument layout, the reduction to plastic/plastic2/trans2 where
// the models coincide, RADIANCE's direct-light values, reciprocity, backward rays and the
// energy of photon scattering against a numerical integral of the model.
#include <gtest/gtest.h>

#include "material/material.h"
#include "material/test_util.h"

namespace rp::material {
namespace {

using test::prim;

// "void" modifiers, constant expressions, function file ".".
MaterialParams wgmd(std::vector<double> r, const std::string& rs, const std::string& rsU,
                    const std::string& rsV, const std::string& ts, const std::string& tsU,
                    const std::string& tsV, const std::string& ux = "1", int line = 7) {
    return makeMaterial(
        prim(PrimType::WGMDfunc, std::move(r),
             {"void", rs, rsU, rsV, "void", ts, tsU, tsV, "void", ux, "0", "0", "."}, line));
}

SurfacePoint at(const Vec3& dir, const Vec3& facing = {0, 0, 1}) {
    return makeSurfacePoint(dir, facing, true);
}

TEST(Wgmdfunc, ParamsFollowRayHtmlLayout) {
    Primitive p = prim(PrimType::WGMDfunc, {.1, .2, .3, .4, .5, .6, .7, .8, .9, 42},
                       {"inherit", "rs", ".05", "rv", "pat", ".2", "0", "0", "void", "ux", "0", "1",
                        "w.cal", "-rz", "90"});
    p.modifierName = "pat";
    const auto m = std::get<WgmdParams>(makeMaterial(p));
    using M = WgmdParams::Mod;
    EXPECT_EQ(m.mod[WgmdParams::kRs], M::Main);  // inherit
    EXPECT_EQ(m.mod[WgmdParams::kTs], M::Main);  // the material's own modifier by name
    EXPECT_EQ(m.mod[WgmdParams::kTd], M::Void);
    EXPECT_EQ(m.expr[0], "rs");
    EXPECT_FALSE(m.constant[0].has_value());
    EXPECT_EQ(m.constant[1], .05);
    EXPECT_EQ(m.constant[3], .2);
    EXPECT_EQ(m.expr[6], "ux");
    EXPECT_EQ(m.constant[8], 1.0);
    EXPECT_EQ(m.funcFile, "w.cal");
    EXPECT_EQ(m.transform, (std::vector<std::string>{"-rz", "90"}));
    EXPECT_EQ(m.frontDiffuse, (Color{.1, .2, .3}));
    EXPECT_EQ(m.backDiffuse, (Color{.4, .5, .6}));
    EXPECT_EQ(m.diffuseTransmittance, (Color{.7, .8, .9}));
    EXPECT_EQ(m.rargs.size(), 10u);
    p.sargs[4] = "other";
    EXPECT_EQ(std::get<WgmdParams>(makeMaterial(p)).mod[WgmdParams::kTs], M::Named);
    EXPECT_TRUE(storesPhotons(makeMaterial(p)));
}

TEST(Wgmdfunc, NonFiniteRealIsAnErrorAtItsLine) {
    try {
        wgmd({.1, .1, NAN, 0, 0, 0, 0, 0, 0}, ".05", "0", "0", "0", "0", "0", "1", 31);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("test.rad:31: ", 0), 0u) << what;
    }
}

// plastic2 c s ur vr  ==  WGMDfunc rs=s, front/back diffuse c (1 - s); trans2 with a grey
// colour likewise (aniso.c's fractions as coefficients).
TEST(Wgmdfunc, ReducesToPlastic2AndTrans2) {
    const Color c{.5, .3, .2};
    const double s = .08, ur = .05, vr = .2;
    auto p2 =
        makeMaterial(prim(PrimType::Plastic2, {c.r, c.g, c.b, s, ur, vr}, {"1", "0", "0", "."}));
    const Color rd = c * (1 - s);
    auto w = wgmd({rd.r, rd.g, rd.b, rd.r, rd.g, rd.b, 0, 0, 0}, ".08", ".05", ".2", "0", "0", "0");
    // trans2 .6 grey, spec .05, ur .1 vr .15, trans .4, tspec .5
    const double g = .6, sp = .05, t = .4 * (1 - sp), tspec = t * .5, tdiff = t - tspec;
    const double rdiff = 1 - t - sp;
    auto t2 =
        makeMaterial(prim(PrimType::Trans2, {g, g, g, sp, .1, .15, .4, .5}, {"1", "0", "0", "."}));
    auto wt = wgmd({g * rdiff, g * rdiff, g * rdiff, g * rdiff, g * rdiff, g * rdiff, g * tdiff,
                    g * tdiff, g * tdiff},
                   ".05", ".1", ".15", std::to_string(g * tspec), ".1", ".15");
    Rng rng(3, RngDomain::Test, 0);
    for (int i = 0; i < 2000; ++i) {
        SurfacePoint pt = at(-test::uniformSphere(rng));
        if (pt.dir.z > -0.05) continue;
        pt.uDir = {1, 0, 0};
        const Vec3 l = test::uniformSphere(rng);
        const double omega = i % 3 ? 0 : 1e-3;
        pt.flat = i % 2;
        for (auto [a, b] : {std::pair{&p2, &w}, std::pair{&t2, &wt}}) {
            const Color x = evaluate(*a, pt, l, omega), y = evaluate(*b, pt, l, omega);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(y[k], x[k], 1e-9 * (1 + x[k])) << i;
        }
    }
}

// plastic c s 0 == WGMDfunc rs=s roughness 0, diffuse c (1 - s): the same Fresnel
// estimate on the mirror ray and both diffuse factors.
TEST(Wgmdfunc, SmoothReducesToPlastic) {
    auto pl = makeMaterial(prim(PrimType::Plastic, {.4, .5, .6, .05, 0}));
    auto w = wgmd({.38, .475, .57, 0, 0, 0, 0, 0, 0}, ".05", "0", "0", "0", "0", "0");
    Rng rng(5, RngDomain::Test, 0);
    ShadeOptions opt;
    for (double th : {0.0, 30.0, 60.0, 85.0}) {
        const SurfacePoint pt = at(test::incident(th));
        for (int i = 0; i < 50; ++i) {
            const Vec3 l = test::uniformSphere(rng);
            const Color x = evaluate(pl, pt, l), y = evaluate(w, pt, l);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(y[k], x[k], 1e-12) << th;
        }
        const BackwardResult a = shadeBackward(pl, pt, opt, rng),
                             b = shadeBackward(w, pt, opt, rng);
        ASSERT_EQ(a.numRays, 1);
        ASSERT_EQ(b.numRays, 1);
        EXPECT_NEAR(b.rays[0].weight.r, a.rays[0].weight.r, 1e-12);
        EXPECT_NEAR(dot(b.rays[0].dir, a.rays[0].dir), 1, 1e-12);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.ambientReflect[k], a.ambientReflect[k], 1e-12);
    }
}

TEST(Wgmdfunc, BackUsesBackDiffuseAndTransmissionIsTheOtherSide) {
    auto w = wgmd({.5, .5, .5, .1, .2, .3, .25, .25, .25}, "0", "0", "0", "0", "0", "0");
    SurfacePoint back = makeSurfacePoint({0, 0, 1}, {0, 0, -1}, false);
    const Color refl = evaluate(w, back, Vec3{0, 0, -1});
    EXPECT_NEAR(refl.g, .2 / kPi, 1e-12);
    const Color trans = evaluate(w, back, Vec3{0, 0, 1});
    EXPECT_NEAR(trans.g, .25 / kPi, 1e-12);
    Rng rng(1, RngDomain::Test, 0);
    const BackwardResult b = shadeBackward(w, back, ShadeOptions{}, rng);
    EXPECT_EQ(b.ambientReflect, (Color{.1, .2, .3}));
    EXPECT_EQ(b.ambientTransmit, (Color{.25, .25, .25}));
    ShadeOptions hidden;
    hidden.backVisible = false;
    EXPECT_TRUE(shadeBackward(w, back, hidden, rng).transparent);
}

TEST(Wgmdfunc, RaysAndSpecularThreshold) {
    Rng rng(2, RngDomain::Test, 0);
    const SurfacePoint pt = at(test::incident(40));
    // Ideal transmission .3 plus rough reflection .1 (a sampled ray).
    auto w = wgmd({.2, .2, .2, 0, 0, 0, 0, 0, 0}, ".1", ".1", ".1", ".3", "0", "0");
    BackwardResult b = shadeBackward(w, pt, ShadeOptions{}, rng);
    ASSERT_EQ(b.numRays, 2);
    EXPECT_EQ(b.rays[0].kind, ScatterKind::SpecularTransmission);
    EXPECT_EQ(b.rays[0].weight, (Color{.3, .3, .3}));
    EXPECT_NEAR(dot(b.rays[0].dir, pt.dir), 1, 1e-12);
    EXPECT_TRUE(b.rays[1].sampled);
    EXPECT_GT(b.rays[1].dir.z, 0);
    // -st above the rough reflection: no ray, the part joins the diffuse ambient.
    ShadeOptions st;
    st.specThreshold = .5;
    b = shadeBackward(w, pt, st, rng);
    EXPECT_EQ(b.numRays, 1);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.ambientReflect[k], .3, 1e-12);
    // ... but not where there is no diffuse part on that side (m_wgmdf.c).
    auto bare = wgmd({0, 0, 0, 0, 0, 0, 0, 0, 0}, ".1", ".1", ".1", "0", "0", "0");
    EXPECT_EQ(shadeBackward(bare, pt, st, rng).ambientReflect, Color{});
}

// f(i, o) = f(o, i) for the rough reflection and transmission (no texture), to 1e-5
// absolute: RADIANCE drops a lobe value below FTINY before its cosine factor.
TEST(Wgmdfunc, Reciprocal) {
    auto w = wgmd({.2, .1, .1, .2, .1, .1, .1, .1, .1}, ".1", ".08", ".25", ".3", ".12", ".2", "1");
    Rng rng(9, RngDomain::Test, 0);
    int checked = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 a = test::uniformSphere(rng), b = test::uniformSphere(rng);
        if (std::fabs(a.z) < .05 || std::fabs(b.z) < .05) continue;
        const Vec3 na{0, 0, a.z > 0 ? 1.0 : -1.0}, nb{0, 0, b.z > 0 ? 1.0 : -1.0};
        SurfacePoint va = makeSurfacePoint(-a, na, a.z > 0), vb = makeSurfacePoint(-b, nb, b.z > 0);
        const Color fab = evaluate(w, va, b) / std::fabs(b.z);
        const Color fba = evaluate(w, vb, a) / std::fabs(a.z);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(fab[k], fba[k], 1e-5 + 1e-9 * fab[k]) << a.z << " " << b.z;
        ++checked;
    }
    EXPECT_GT(checked, 3000);
}

// The directional albedo for a photon arriving along `dir`: the integral of evaluate()
// over all light directions (by reciprocity the flux scattered into them), on a grid in
// cos(theta) and phi per hemisphere, refined towards the specular peaks.
Color albedo(const MaterialParams& m, const SurfacePoint& sp) {
    constexpr int kT = 1200, kP = 600;
    Color sum;
    for (int side : {1, -1})
        for (int i = 0; i < kT; ++i) {
            // cos theta = 1 - s^2 concentrates samples near the pole (the peaks at normal
            // incidence) and keeps the grid's Jacobian smooth.
            const double s = (i + .5) / kT, ct = 1 - s * s, st = std::sqrt(1 - ct * ct);
            const double dw = 2 * s / kT * (2 * kPi / kP);
            for (int j = 0; j < kP; ++j) {
                const double ph = (j + .5) * 2 * kPi / kP;
                sum += evaluate(m, sp, Vec3{st * std::cos(ph), st * std::sin(ph), side * ct}) * dw;
            }
        }
    return sum;
}

void expectEnergy(const MaterialParams& m, double thetaDeg, const char* what,
                  const Color& delta = {}) {
    const SurfacePoint sp = at(test::incident(thetaDeg));
    const Color expect = albedo(m, sp) + delta;
    const test::FluxStats st = test::photonStats(m, 400000, 17, [&](Rng&) { return sp; });
    for (int c = 0; c < 3; ++c) {
        // 4 sigma of the photons' mean, plus 0.3 % for the quadrature.
        const double tol = 4 * st.stderr_[c] + 3e-3 * expect[c];
        EXPECT_NEAR(st.mean[c], expect[c], tol) << what << " at " << thetaDeg << " channel " << c;
    }
}

TEST(Wgmdfunc, PhotonFluxEqualsIntegratedModel) {
    auto refl = wgmd({.3, .2, .1, 0, 0, 0, 0, 0, 0}, ".15", ".2", ".2", "0", "0", "0");
    auto aniso = wgmd({.1, .1, .1, 0, 0, 0, 0, 0, 0}, ".4", ".1", ".3", "0", "0", "0");
    auto trans = wgmd({.1, .1, .1, 0, 0, 0, .2, .1, .05}, "0", "0", "0", ".5", ".15", ".1");
    auto smooth = wgmd({.4, .4, .4, 0, 0, 0, .1, .1, .1}, ".05", "0", "0", "0", "0", "0");
    for (double th : {0.0, 35.0, 70.0}) {
        expectEnergy(refl, th, "rough reflection");
        expectEnergy(aniso, th, "anisotropic reflection");
        expectEnergy(trans, th, "rough transmission");
    }
    // The ideal reflection is a delta (not in the integral): add its Fresnel weight.
    const SurfacePoint sp = at(test::incident(50));
    Rng rng(4, RngDomain::Test, 0);
    const Color mirror = shadeBackward(smooth, sp, ShadeOptions{}, rng).rays[0].weight;
    expectEnergy(smooth, 50, "smooth", mirror);
}

}  // namespace
}  // namespace rp::material
