// plastic/metal/trans and plastic2/metal2/trans2 in both directions (ward.cpp): photon
// energy conservation, diffuse direction distribution, reciprocity of evaluate(), and
// consistency of the forward and backward diffuse parts. Tolerances: 4 standard errors
// of the sample mean (computed from the samples) unless stated.
#include <gtest/gtest.h>

#include "material/detail.h"
#include "material/test_util.h"

namespace rp::material {
namespace {

using test::prim;

const Vec3 kUp{0, 0, 1};

SurfacePoint at(const Vec3& dir) { return makeSurfacePoint(dir, kUp, true); }

// Expected total scattered flux factor for a Ward material at cos(incidence) `ci`,
// written out from ray.html/normal.c independently of ward.cpp.
Color expectedAlbedo(const Color& c, double spec, double rough, double T, double Ts, bool metal,
                     double ci) {
    double rspec = spec, fest = 0;
    if (rough * rough <= 1e-6 && spec >= 0.017999) {
        fest = std::exp(-5.85 * ci) - 0.00202943064;
        rspec = spec + fest * (1 - spec);
    }
    double trans = T * (1 - rspec), rdiff = 1 - trans - rspec;
    Color s = !metal ? Color::grey(rspec)
                     : (fest > 1e-6 ? Color::grey(fest) + c * (spec * (1 - fest)) : c * rspec);
    return c * rdiff + s + c * trans;
}

TEST(WardPhoton, EnergyConservation) {
    struct Case {
        PrimType t;
        std::vector<double> r;
        bool metal;
    };
    std::vector<Case> cases = {
        {PrimType::Plastic, {.7, .5, .2, .05, .05}, false},
        {PrimType::Plastic, {.7, .5, .2, .05, 0}, false},  // Fresnel estimate active
        {PrimType::Metal, {.9, .6, .3, .9, .03}, true},
        {PrimType::Metal, {.9, .6, .3, .9, 0}, true},
        {PrimType::Trans,
         {
             .6,
             .7,
             .8,
             .04,
             .03,
             .6,
             .4,
         },
         false},
        {PrimType::Trans, {.6, .7, .8, .04, 0, .6, .4}, false},
    };
    for (auto& c : cases) {
        MaterialParams m = makeMaterial(prim(c.t, c.r));
        double T = c.r.size() > 5 ? c.r[5] : 0, Ts = c.r.size() > 6 ? c.r[6] : 0;
        for (double theta : {0.0, 30.0, 60.0}) {
            auto st =
                test::photonStats(m, 200000, 11, [&](Rng&) { return at(test::incident(theta)); });
            Color want = expectedAlbedo({c.r[0], c.r[1], c.r[2]}, c.r[3], c.r[4], T, Ts, c.metal,
                                        std::cos(theta * kPi / 180));
            test::expectMeanNear(st, want, "albedo");
        }
    }
}

TEST(WardPhoton, DiffuseIsCosineWeighted) {
    MaterialParams m = makeMaterial(prim(PrimType::Trans, {.8, .8, .8, 0, 0, .5, 0}));
    Rng rng(5, RngDomain::Test, 1);
    double sumR = 0, sumT = 0;
    long nR = 0, nT = 0;
    for (int i = 0; i < 200000; ++i) {
        PhotonScatter s = scatterPhoton(m, at(test::incident(40)), rng);
        EXPECT_TRUE(s.store);
        if (s.kind == ScatterKind::DiffuseReflection) sumR += s.dir.z, ++nR;
        if (s.kind == ScatterKind::DiffuseTransmission) sumT += -s.dir.z, ++nT;
        EXPECT_FALSE(isSpecular(s.kind));
    }
    // Cosine-weighted: E[cos] = 2/3, sd(cos) = sqrt(1/2 - 4/9).
    double sd = std::sqrt(0.5 - 4.0 / 9);
    EXPECT_NEAR(sumR / nR, 2.0 / 3, 4 * sd / std::sqrt(double(nR)));
    EXPECT_NEAR(sumT / nT, 2.0 / 3, 4 * sd / std::sqrt(double(nT)));
}

TEST(WardPhoton, SmoothSpecularIsExactMirror) {
    MaterialParams m = makeMaterial(prim(PrimType::Metal, {.9, .9, .9, 1, 0}));
    Rng rng(6, RngDomain::Test, 0);
    Vec3 d = test::incident(35, 70);
    for (int i = 0; i < 1000; ++i) {
        PhotonScatter s = scatterPhoton(m, at(d), rng);
        if (s.kind == ScatterKind::Absorbed) continue;
        ASSERT_EQ(s.kind, ScatterKind::SpecularReflection);
        EXPECT_FALSE(s.store);
        EXPECT_NEAR(s.dir.x, d.x, 1e-12);
        EXPECT_NEAR(s.dir.y, d.y, 1e-12);
        EXPECT_NEAR(s.dir.z, -d.z, 1e-12);
    }
}

TEST(WardBackward, Reciprocity) {
    // RADIANCE's reflection model is reciprocal: f(l, v) = evaluate / cos(l) symmetric.
    std::vector<Primitive> ps = {
        prim(PrimType::Plastic, {.5, .4, .3, .06, .15}),
        prim(PrimType::Metal, {.9, .7, .4, .8, .08}), prim(PrimType::Plastic, {.5, .4, .3, .06, 0}),
        prim(PrimType::Plastic2, {.5, .4, .3, .06, .05, .2}, {"1", "0", "0", "."})};
    Rng rng(7, RngDomain::Test, 0);
    for (auto& p : ps) {
        MaterialParams m = makeMaterial(p);
        for (int i = 0; i < 200; ++i) {
            Vec3 a = test::uniformSphere(rng), b = test::uniformSphere(rng);
            a.z = std::fabs(a.z) + 0.05, b.z = std::fabs(b.z) + 0.05;
            a = normalize(a), b = normalize(b);
            SurfacePoint sa = at(-a), sb = at(-b);  // viewer along a, resp. b
            sa.uDir = sb.uDir = {1, 0, 0};
            Color fab = evaluate(m, sa, b) / b.z, fba = evaluate(m, sb, a) / a.z;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(fab[c], fba[c], 1e-9 * std::max(1.0, fab[c])) << primTypeName(p.type);
        }
    }
}

TEST(WardBackward, SmoothSpecularRaysAndAmbient) {
    MaterialParams m = makeMaterial(prim(PrimType::Plastic, {.5, .5, .5, .05, 0}));
    Rng rng(1, RngDomain::Test, 0);
    Vec3 d = test::incident(20);
    BackwardResult r = shadeBackward(m, at(d), {}, rng);
    ASSERT_EQ(r.numRays, 1);
    EXPECT_NEAR(r.rays[0].dir.z, -d.z, 1e-12);
    double fest = std::exp(-5.85 * std::cos(20 * kPi / 180)) - 0.00202943064;
    double rspec = 0.05 + fest * 0.95;
    EXPECT_NEAR(r.rays[0].weight.r, rspec, 1e-12);
    EXPECT_NEAR(r.ambientReflect.g, 0.5 * (1 - rspec), 1e-12);
}

TEST(WardBackward, RoughSpecularSampledAboveSurface) {
    MaterialParams m = makeMaterial(prim(PrimType::Trans, {.5, .5, .5, .05, .2, .5, .5}));
    Rng rng(2, RngDomain::Test, 0);
    int refl = 0, trans = 0;
    for (int i = 0; i < 1000; ++i) {
        BackwardResult r = shadeBackward(m, at(test::incident(50)), {}, rng);
        for (int k = 0; k < r.numRays; ++k) {
            EXPECT_TRUE(r.rays[k].sampled);
            if (r.rays[k].kind == ScatterKind::SpecularReflection) {
                EXPECT_GT(r.rays[k].dir.z, 0);
                ++refl;
            } else {
                EXPECT_LT(r.rays[k].dir.z, 0);
                ++trans;
            }
        }
    }
    EXPECT_GT(refl, 900);
    EXPECT_GT(trans, 900);
    // Below the -st threshold the specular goes to the ambient coefficient instead.
    ShadeOptions opt;
    opt.specThreshold = 0.5;
    BackwardResult r = shadeBackward(m, at(test::incident(50)), opt, rng);
    EXPECT_EQ(r.numRays, 0);
    EXPECT_NEAR(r.ambientReflect.r, 0.5 * (1 - .475 - .05) + 0.05, 1e-12);
    EXPECT_NEAR(r.ambientTransmit.r, 0.5 * 0.475, 1e-12);
}

// The mean photon weight of the diffuse events over a sphere of incident directions
// equals the hemispherical integral of evaluate()'s diffuse part (forward == backward).
TEST(WardConsistency, DiffuseForwardMatchesBackward) {
    std::vector<Primitive> ps = {prim(PrimType::Plastic, {.7, .5, .3, 0, 0}),
                                 prim(PrimType::Trans, {.7, .5, .3, 0, .1, .4, 0})};
    for (auto& p : ps) {
        MaterialParams m = makeMaterial(p);
        const long n = 200000;
        Rng rng(9, RngDomain::Test, 0);
        Color fwd, fwd2;
        for (long i = 0; i < n; ++i) {
            Vec3 d = test::uniformSphere(rng);
            bool front = d.z < 0;
            SurfacePoint sp = makeSurfacePoint(d, front ? kUp : -kUp, front);
            PhotonScatter s = scatterPhoton(m, sp, rng);
            Color f = (s.kind == ScatterKind::DiffuseReflection ||
                       s.kind == ScatterKind::DiffuseTransmission)
                          ? s.fluxFactor
                          : Color{};
            fwd += f, fwd2 += f * f;
        }
        // Backward: integrate evaluate() over the full sphere of light directions with a
        // uniform-sphere Monte Carlo estimate (4 pi mean), viewer at normal incidence.
        Color bwd, bwd2;
        for (long i = 0; i < n; ++i) {
            Vec3 l = test::uniformSphere(rng);
            Color e = evaluate(m, at({0, 0, -1}), l) * (4 * kPi);
            bwd += e, bwd2 += e * e;
        }
        for (int c = 0; c < 3; ++c) {
            double mf = fwd[c] / n, mb = bwd[c] / n;
            double se = std::sqrt((fwd2[c] / n - mf * mf) / n + (bwd2[c] / n - mb * mb) / n);
            EXPECT_NEAR(mf, mb, 4 * se) << primTypeName(p.type) << " channel " << c;
        }
    }
}

TEST(WardAniso, PhotonEnergyAndHighlightShape) {
    std::vector<std::string> s{"1", "0", "0", "."};
    MaterialParams m = makeMaterial(prim(PrimType::Metal2, {.9, .7, .5, .8, .02, .05}, s));
    auto st = test::photonStats(m, 200000, 3, [&](Rng&) {
        SurfacePoint sp = at(test::incident(30));
        sp.uDir = {1, 0, 0};
        return sp;
    });
    Color c{.9, .7, .5};
    test::expectMeanNear(st, c * 0.2 + c * 0.8, "metal2 albedo");
    // A highlight narrower along u (rough .02) than along v (.05): offsetting the light
    // by the same angle along v keeps more of it.
    MaterialParams p = makeMaterial(prim(PrimType::Plastic2, {.5, .5, .5, .1, .02, .05}, s));
    SurfacePoint sp = at({0, 0, -1});
    sp.uDir = {1, 0, 0};
    double a = 0.05;  // exp(-(a/2)^2 / 0.02^2) vs exp(-(a/2)^2 / 0.05^2)
    Color alongU = evaluate(p, sp, normalize({std::sin(a), 0, std::cos(a)}));
    Color alongV = evaluate(p, sp, normalize({0, std::sin(a), std::cos(a)}));
    EXPECT_GT(alongV.r, 2 * alongU.r);
}

// scatterNormal's fast path (per-material coefficients, no pattern, no Fresnel term)
// must give the same bits as the per-hit setup, for every component it can choose.
TEST(WardPhoton, FastPathMatchesPerHitSetup) {
    const std::vector<Primitive> mats = {
        prim(PrimType::Plastic, {.75, .6, .4, 0, 0}),
        prim(PrimType::Plastic, {.5, .6, .7, .01, 0}),
        prim(PrimType::Plastic, {.5, .6, .7, .05, .1}),
        prim(PrimType::Metal, {.8, .6, .4, .9, .05}),
        prim(PrimType::Metal, {.8, .6, .4, .01, 0}),
        prim(PrimType::Trans, {.7, .7, .7, .03, .05, .5, .3}),
        prim(PrimType::Trans, {.6, .7, .8, .01, 0, .6, .5}),
    };
    Rng dirs(11, RngDomain::Test, 0);
    for (const Primitive& p : mats) {
        MaterialParams params = makeMaterial(p);
        const auto& m = std::get<NormalParams>(params);
        for (int i = 0; i < 4000; ++i) {
            Vec3 d = test::uniformSphere(dirs);
            const bool front = d.z < 0;
            SurfacePoint sp = makeSurfacePoint(d, front ? kUp : -kUp, front);
            Rng a(5, RngDomain::Test, uint64_t(i)), b(5, RngDomain::Test, uint64_t(i));
            PhotonScatter fast = scatterPhoton(params, sp, a);
            PhotonScatter ref = detail::scatterNormalPerHit(m, sp, b);
            ASSERT_EQ(fast.kind, ref.kind) << primTypeName(p.type) << " " << i;
            EXPECT_EQ(fast.store, ref.store);
            EXPECT_EQ(fast.dir, ref.dir);
            EXPECT_EQ(fast.fluxFactor, ref.fluxFactor);
            EXPECT_EQ(a.next(), b.next()) << "same number of draws";
        }
    }
}

}  // namespace
}  // namespace rp::material
