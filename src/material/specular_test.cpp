// mirror, glass, dielectric/interface (specular.cpp): directions, backward weights and
// photon energy. Photon tolerances: 4 standard errors of the sample mean.
#include <gtest/gtest.h>

#include "material/detail.h"
#include "material/test_util.h"

namespace rp::material {
namespace {

using test::prim;
const Vec3 kUp{0, 0, 1};

TEST(Mirror, BothDirections) {
    MaterialParams m = makeMaterial(prim(PrimType::Mirror, {.9, .8, .7}));
    Vec3 d = test::incident(40, 10);
    Rng rng(1, RngDomain::Test, 0);
    BackwardResult r = shadeBackward(m, makeSurfacePoint(d, kUp, true), {}, rng);
    ASSERT_EQ(r.numRays, 1);
    EXPECT_NEAR(r.rays[0].dir.z, -d.z, 1e-12);
    EXPECT_NEAR(r.rays[0].dir.x, d.x, 1e-12);
    EXPECT_EQ(r.rays[0].weight, (Color{.9, .8, .7}));
    auto st = test::photonStats(m, 100000, 2, [&](Rng&) { return makeSurfacePoint(d, kUp, true); });
    test::expectMeanNear(st, {.9, .8, .7}, "mirror");
    EXPECT_EQ(st.counts[int(ScatterKind::SpecularReflection)] + st.counts[0], 100000);
    // Back is black.
    PhotonScatter s = scatterPhoton(m, makeSurfacePoint(d, kUp, false), rng);
    EXPECT_EQ(s.kind, ScatterKind::Absorbed);
    EXPECT_EQ(shadeBackward(m, makeSurfacePoint(d, kUp, false), {}, rng).numRays, 0);
}

// Thin pane by explicit summation of internal bounces (independent of glass.c's closed
// form): one polarisation with interface reflectance r and one-pass transmission d.
void paneSeries(double r, double d, double& R, double& T) {
    R = r;
    T = 0;
    double inside = (1 - r) * d;  // entered, crossed once
    for (int k = 0; k < 200; ++k) {
        T += inside * (1 - r);
        inside *= r * d;  // reflected back, crosses again
        R += inside * (1 - r);
        inside *= r * d;
    }
}

TEST(Glass, CoefficientsMatchBounceSeries) {
    GlassParams g = std::get<GlassParams>(makeMaterial(prim(PrimType::Glass, {.96, .8, .5, 1.6})));
    for (double theta : {0.0, 25.0, 50.0, 75.0}) {
        double ci = std::cos(theta * kPi / 180), n = 1.6;
        double st = std::sin(theta * kPi / 180) / n, ct = std::sqrt(1 - st * st);
        double rs = std::pow((ci - n * ct) / (ci + n * ct), 2);
        double rp = std::pow((ct - n * ci) / (ct + n * ci), 2);
        Color refl, trans;
        detail::glassCoefficients(g, ci, {1, 1, 1}, refl, trans);
        for (int c = 0; c < 3; ++c) {
            double d = std::pow(g.transmission[c], 1 / ct);  // path length 1/cos(refracted)
            double R1, T1, R2, T2;
            paneSeries(rs, d, R1, T1);
            paneSeries(rp, d, R2, T2);
            EXPECT_NEAR(refl[c], 0.5 * (R1 + R2), 1e-12) << theta;
            EXPECT_NEAR(trans[c], 0.5 * (T1 + T2), 1e-12) << theta;
        }
    }
    // Clear glass absorbs nothing: R + T = 1.
    GlassParams clear = std::get<GlassParams>(makeMaterial(prim(PrimType::Glass, {1, 1, 1})));
    Color refl, trans;
    detail::glassCoefficients(clear, 0.3, {1, 1, 1}, refl, trans);
    EXPECT_NEAR(refl.r + trans.r, 1, 1e-12);
}

TEST(Glass, BothDirections) {
    MaterialParams m = makeMaterial(prim(PrimType::Glass, {.9, .85, .8}));
    GlassParams g = std::get<GlassParams>(m);
    Vec3 d = test::incident(50);
    Color refl, trans;
    detail::glassCoefficients(g, -d.z, {1, 1, 1}, refl, trans);
    Rng rng(3, RngDomain::Test, 0);
    BackwardResult r = shadeBackward(m, makeSurfacePoint(d, kUp, false), {}, rng);
    ASSERT_EQ(r.numRays, 2);
    EXPECT_EQ(r.rays[0].dir, d);  // transmitted straight through
    EXPECT_EQ(r.rays[0].weight, trans);
    EXPECT_NEAR(r.rays[1].dir.z, -d.z, 1e-12);
    EXPECT_EQ(r.rays[1].weight, refl);
    auto st = test::photonStats(m, 200000, 4, [&](Rng&) { return makeSurfacePoint(d, kUp, true); });
    test::expectMeanNear(st, refl + trans, "glass R+T");
}

// glass.c: a texture bends the transmitted ray by 2 (1 - n) pert with the raw
// perturbation, and reflects about the perturbed normal (raynormal), which may have had its
// orientation fixed; the two differ once the fix applies.
TEST(Glass, TextureBendsTransmissionByTheRawPerturbation) {
    MaterialParams m = makeMaterial(prim(PrimType::Glass, {.9, .9, .9}));
    const Vec3 d = test::incident(50);
    SurfacePoint sp = makeSurfacePoint(d, kUp, true);
    const Vec3 pert{0.1, 0.05, 0};
    perturbSurface(sp, kUp, pert);
    Rng rng(3, RngDomain::Test, 0);
    BackwardResult r = shadeBackward(m, sp, {}, rng);
    ASSERT_EQ(r.numRays, 2);
    const Vec3 t = normalize(d + pert * (2 * (1 - 1.52)));
    EXPECT_NEAR(r.rays[0].dir.x, t.x, 1e-12);
    EXPECT_NEAR(r.rays[0].dir.y, t.y, 1e-12);
    EXPECT_NEAR(r.rays[0].dir.z, t.z, 1e-12);
    // From behind, the perturbation turns with the normal.
    SurfacePoint back = makeSurfacePoint(-d, -kUp, false);
    perturbSurface(back, kUp, pert);
    EXPECT_NEAR(back.perturbation.x, -0.1, 1e-15);
    EXPECT_LT(dot(back.normal, -d), 0);  // faces the ray, which travels up into the back
}

double fresnel(double n1, double n2, double ci) {
    double si = std::sqrt(1 - ci * ci), st = n1 / n2 * si;
    if (st >= 1) return 1;
    double ct = std::sqrt(1 - st * st);
    double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
    double rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
    return 0.5 * (rs * rs + rp * rp);
}

TEST(Dielectric, PhotonsConserveFluxAndSplitByFresnel) {
    MaterialParams m = makeMaterial(prim(PrimType::Dielectric, {.9, .9, .9, 1.5, 0}));
    for (double theta : {0.0, 30.0, 60.0, 80.0}) {
        Vec3 d = test::incident(theta, 45);
        auto st =
            test::photonStats(m, 100000, 5, [&](Rng&) { return makeSurfacePoint(d, kUp, true); });
        test::expectMeanNear(st, {1, 1, 1}, "R+T = 1");
        double R = fresnel(1, 1.5, std::cos(theta * kPi / 180));
        double fr = double(st.counts[int(ScatterKind::SpecularReflection)]) / 100000;
        EXPECT_NEAR(fr, R, 4 * std::sqrt(R * (1 - R) / 100000) + 1e-12) << theta;
    }
}

TEST(Dielectric, SnellAndTotalInternalReflection) {
    MaterialParams m = makeMaterial(prim(PrimType::Dielectric, {.9, .8, .7, 1.5, 0}));
    Rng rng(6, RngDomain::Test, 0);
    Vec3 d = test::incident(40, 20);
    BackwardResult r = shadeBackward(m, makeSurfacePoint(d, kUp, true), {}, rng);
    ASSERT_EQ(r.numRays, 2);
    const SpecularRay& t = r.rays[0];
    double sin1 = std::sqrt(1 - d.z * d.z), sin2 = std::sqrt(1 - t.dir.z * t.dir.z);
    EXPECT_NEAR(sin1, 1.5 * sin2, 1e-12);              // n1 sin1 = n2 sin2
    EXPECT_NEAR(dot(cross(d, kUp), t.dir), 0, 1e-12);  // plane of incidence
    double R = fresnel(1, 1.5, -d.z);
    EXPECT_NEAR(t.weight.r, (1 - R) / (1.5 * 1.5), 1e-12);  // radiance compression
    EXPECT_NEAR(r.rays[1].weight.r, R, 1e-12);
    EXPECT_EQ(t.medium.kind, MediumChange::Kind::Given);
    EXPECT_NEAR(t.medium.extinction.g, -std::log(0.8), 1e-12);
    // From inside beyond the critical angle (41.8 deg): only reflection.
    Vec3 din = test::incident(50);
    BackwardResult tir = shadeBackward(m, makeSurfacePoint(din, kUp, false), {}, rng);
    ASSERT_EQ(tir.numRays, 1);
    EXPECT_EQ(tir.rays[0].weight, Color::grey(1));
    EXPECT_EQ(tir.rays[0].medium.kind, MediumChange::Kind::Given);  // stays inside
    for (int i = 0; i < 100; ++i) {
        PhotonScatter s = scatterPhoton(m, makeSurfacePoint(din, kUp, false), rng);
        EXPECT_EQ(s.kind, ScatterKind::SpecularReflection);
        // The photon stays in the absorbing medium, as the backward ray does.
        EXPECT_EQ(s.mediumKind, MediumChange::Kind::Given);
        EXPECT_NEAR(s.extinction.g, -std::log(0.8), 1e-12);
    }
    // Leaving a dielectric below the critical angle enters the global medium.
    BackwardResult out =
        shadeBackward(m, makeSurfacePoint(test::incident(20), kUp, false), {}, rng);
    ASSERT_EQ(out.numRays, 2);
    EXPECT_EQ(out.rays[0].medium.kind, MediumChange::Kind::Global);
}

TEST(Interface, MediaAndIndices) {
    MaterialParams m = makeMaterial(prim(PrimType::Interface, {.9, .9, .9, 1.33, .5, .5, .5, 1.5}));
    Rng rng(7, RngDomain::Test, 0);
    // From outside (n = 1.5) into the inside (n = 1.33).
    Vec3 d = test::incident(30);
    BackwardResult r = shadeBackward(m, makeSurfacePoint(d, kUp, true), {}, rng);
    ASSERT_EQ(r.numRays, 2);
    double sin2 = std::sqrt(1 - r.rays[0].dir.z * r.rays[0].dir.z);
    EXPECT_NEAR(1.5 * std::sin(30 * kPi / 180), 1.33 * sin2, 1e-12);
    EXPECT_NEAR(r.rays[0].medium.extinction.r, -std::log(.9), 1e-12);
    EXPECT_NEAR(r.rays[1].medium.extinction.r, -std::log(.5), 1e-12);
}

}  // namespace
}  // namespace rp::material
