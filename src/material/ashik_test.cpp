// ashik2 (ashik.cpp): parameters, RADIANCE's direct-light value, energy and reciprocity,
// backward rays and photon scattering.
#include <gtest/gtest.h>

#include "material/material.h"
#include "material/test_util.h"

namespace rp::material {
namespace {

using test::prim;

MaterialParams ashik(std::vector<double> r, int line = 7) {
    return makeMaterial(prim(PrimType::Ashik2, std::move(r), {"1", "1", "0", "."}, line));
}

SurfacePoint upFacing(const Vec3& dir, const Vec3& u = normalize(Vec3{1, 1, 0})) {
    SurfacePoint sp = makeSurfacePoint(dir, {0, 0, 1}, true);
    sp.uDir = u;
    return sp;
}

TEST(Ashik2, Params) {
    auto m = makeMaterial(prim(PrimType::Ashik2, {.3, .1, .05, .05, .05, .08, 5, 30},
                               {"ux", "uy", "uz", "a.cal", "-rz", "90"}));
    ASSERT_TRUE(std::holds_alternative<AshikParams>(m));
    const auto& a = std::get<AshikParams>(m);
    EXPECT_EQ(a.uExpr[2], "uz");
    EXPECT_EQ(a.funcFile, "a.cal");
    EXPECT_EQ(a.transform, (std::vector<std::string>{"-rz", "90"}));
    EXPECT_EQ(a.diffuse, (Color{.3, .1, .05}));
    EXPECT_EQ(a.specular, (Color{.05, .05, .08}));
    EXPECT_EQ(a.uPower, 5);
    EXPECT_EQ(a.vPower, 30);
    EXPECT_TRUE(storesPhotons(m));
    EXPECT_FALSE(storesPhotons(ashik({0, 0, 0, .9, .9, .9, 10, 10})));
}

TEST(Ashik2, NegativePowerIsAnErrorAtItsLine) {
    try {
        ashik({.3, .3, .3, .1, .1, .1, -2, 10}, 23);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind("test.rad:23: ", 0), 0u) << what;
        EXPECT_NE(what.find("ashik2 'm': u-power and v-power must not be negative"),
                  std::string::npos)
            << what;
    }
}

TEST(Ashik2, DirectValueMatchesRadiance) {
    // RADIANCE 5.4 (ashikhmin.c dirashik), a 20 m square in z = 0 with
    //   void ashik2 am  4 1 1 0 .  0  8 .3 .1 .05 .05 .05 .08 5 30
    // lit by `void light sun 0 0 3 1000 1000 1000` / `sun source s 0 0 4 .3 .2 .9 1`:
    //   echo "0 0.5 1  -0.2 0.1 -1" |
    //     rtrace -h -ab 0 -ss 0 -st 1 -av 0 0 0 -dj 0 -ds 0 -ov s.oct
    //   -> 2.524691e-02 1.110852e-02 9.997524e-03
    // (-st 1 keeps the sampled specular ray out; -av 0 the ambient.) The same with a black
    // specular colour gives the diffuse part alone: 2.120757e-02 7.069192e-03 3.534596e-03.
    const double omega = 2 * kPi * (1 - std::cos(0.5 * kPi / 180));  // 1 degree source
    const Vec3 l = normalize(Vec3{.3, .2, .9});
    const SurfacePoint sp = upFacing(normalize(Vec3{-.2, .1, -1}));
    const Color c = evaluate(ashik({.3, .1, .05, .05, .05, .08, 5, 30}), sp, l) * (1000 * omega);
    const Color want{2.524691e-02, 1.110852e-02, 9.997524e-03};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], want[i], 2e-6 * want[i]) << i;
    const Color d = evaluate(ashik({.3, .1, .05, 0, 0, 0, 5, 30}), sp, l) * (1000 * omega);
    const Color wantD{2.120757e-02, 7.069192e-03, 3.534596e-03};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(d[i], wantD[i], 2e-6 * wantD[i]) << i;
    // Light from behind gives nothing.
    EXPECT_EQ(evaluate(ashik({.3, .1, .05, .05, .05, .08, 5, 30}), sp, Vec3{0, 0, -1}), Color{});
}

TEST(Ashik2, SpecularLobeIsReciprocal) {
    // With a white specular colour Fresnel changes nothing, and the lobe over cos(light)
    // is symmetric in the two directions (max(n.l, n.v) and l.h are).
    const MaterialParams m = ashik({0, 0, 0, 1, 1, 1, 8, 50});
    Rng rng(3, RngDomain::Test, 0);
    for (int k = 0; k < 200; ++k) {
        Vec3 a = test::uniformSphere(rng), b = test::uniformSphere(rng);
        a.z = std::fabs(a.z) + 0.01;
        b.z = std::fabs(b.z) + 0.01;
        a = normalize(a);
        b = normalize(b);
        const double fab = evaluate(m, upFacing(-a), b).g / b.z;
        const double fba = evaluate(m, upFacing(-b), a).g / a.z;
        EXPECT_NEAR(fab, fba, 1e-9 * std::max(1.0, fab)) << k;
    }
}

// Directional albedo: the integral of evaluate() over the light hemisphere (stratified
// in cos^2 theta and phi), for a view at thetaDeg.
Color albedo(const MaterialParams& m, double thetaDeg) {
    const SurfacePoint sp = upFacing(test::incident(thetaDeg));
    const int n = 400;
    Color sum;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double z = std::sqrt((i + 0.5) / n), s = std::sqrt(1 - z * z);
            const double phi = 2 * kPi * (j + 0.5) / n;
            const Vec3 l{s * std::cos(phi), s * std::sin(phi), z};
            // d omega = d(z^2) d phi / (2 z): the uniform grid in z^2 and phi.
            sum += evaluate(m, sp, l) * (kPi / (z * n * n));
        }
    return sum;
}

TEST(Ashik2, EnergyBounded) {
    // Diffuse: rho_d (1 - 2/42) at any view (the integral of (1 - c)^5 c over c is 1/42).
    const Color d = albedo(ashik({.8, .5, .2, 0, 0, 0, 10, 10}), 40);
    EXPECT_NEAR(d.r, .8 * (1 - 2.0 / 42), 2e-3);
    EXPECT_NEAR(d.b, .2 * (1 - 2.0 / 42), 1e-3);
    // Specular alone and the sum stay at or below 1 (the model loses energy at grazing).
    for (double theta : {0.0, 30.0, 60.0, 80.0}) {
        const Color s = albedo(ashik({0, 0, 0, 1, 1, 1, 20, 200}), theta);
        EXPECT_LT(s.g, 1.02) << theta;
        EXPECT_GT(s.g, 0.5) << theta;
        const Color t = albedo(ashik({.5, .5, .5, .5, .5, .5, 20, 200}), theta);
        EXPECT_LT(t.g, 1.02) << theta;
    }
}

TEST(Ashik2, BackwardRaysAndAmbient) {
    const MaterialParams m = ashik({.3, .1, .05, .05, .05, .08, 5, 300});
    Rng rng(5, RngDomain::Test, 0);
    const SurfacePoint sp = upFacing(test::incident(30));
    const double f = std::pow(1 - std::cos(30 * kPi / 180), 5);
    double uu = 0, vv = 0;
    const Vec3 mirror = sp.dir + Vec3{0, 0, 2 * std::cos(30 * kPi / 180)};
    const Vec3 u = normalize(Vec3{1, 1, 0}), v = cross(Vec3{0, 0, 1}, u);
    for (int k = 0; k < 2000; ++k) {
        BackwardResult r = shadeBackward(m, sp, {}, rng);
        ASSERT_EQ(r.numRays, 1);
        EXPECT_TRUE(r.rays[0].sampled);
        EXPECT_GT(r.rays[0].dir.z, 0);
        EXPECT_NEAR(r.rays[0].weight.b, .08 + .92 * f, 1e-12);
        EXPECT_EQ(r.ambientReflect, (Color{.3, .1, .05}));
        const Vec3 off = r.rays[0].dir - mirror;
        uu += dot(off, u) * dot(off, u);
        vv += dot(off, v) * dot(off, v);
    }
    EXPECT_GT(uu, 4 * vv);  // the lobe is wide along u (power 5), narrow along v (300)

    ShadeOptions st;
    st.specThreshold = .1;  // above the specular brightness: into the ambient
    BackwardResult r = shadeBackward(m, sp, st, rng);
    EXPECT_EQ(r.numRays, 0);
    EXPECT_NEAR(r.ambientReflect.b, .05 + .08 + .92 * f, 1e-12);

    ShadeOptions nobv;
    nobv.backVisible = false;
    SurfacePoint back = sp;
    back.front = false;
    EXPECT_TRUE(shadeBackward(m, back, nobv, rng).transparent);
}

TEST(Ashik2, OrientationAlongNormalFallsBack) {
    // u along n: an arbitrary frame with the harmonic mean of the powers (ashikhmin.c).
    const MaterialParams m = ashik({0, 0, 0, 1, 1, 1, 10, 10});
    const Vec3 l = normalize(Vec3{.3, .2, .9});
    const Color a = evaluate(m, upFacing(normalize(Vec3{-.2, .1, -1}), {0, 0, 1}), l);
    const Color b = evaluate(m, upFacing(normalize(Vec3{-.2, .1, -1})), l);
    EXPECT_NEAR(a.g, b.g, 1e-5 * b.g);  // isotropic: any frame gives the same
}

TEST(Ashik2, PhotonFluxExpectation) {
    // Diffuse only: the expected flux is rho_d (1 - F(cos incidence)), all diffuse.
    const double f = std::pow(1 - std::cos(50 * kPi / 180), 5);
    auto st = test::photonStats(ashik({.6, .4, .2, 0, 0, 0, 10, 10}), 200000, 11,
                                [](Rng&) { return upFacing(test::incident(50)); });
    test::expectMeanNear(st, Color{.6, .4, .2} * (1 - f), "diffuse");
    EXPECT_EQ(st.counts[int(ScatterKind::SpecularReflection)], 0);
    // Specular: leaves above the surface, chosen with the Fresnel-raised colour.
    const MaterialParams m = ashik({.3, .3, .3, .2, .2, .2, 50, 50});
    Rng rng(13, RngDomain::Test, 0);
    long spec = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
        PhotonScatter s = scatterPhoton(m, upFacing(test::incident(50)), rng);
        EXPECT_TRUE(s.store);
        if (s.kind == ScatterKind::SpecularReflection) {
            ++spec;
            EXPECT_GT(s.dir.z, 0);
        }
    }
    const double ps = .2 + .8 * f;
    EXPECT_NEAR(double(spec) / n, ps, 4 * std::sqrt(ps * (1 - ps) / n));
}

}  // namespace
}  // namespace rp::material
