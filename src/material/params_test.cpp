// Parameter checking and derived constants of makeMaterial (params.cpp).
#include <gtest/gtest.h>

#include "material/material.h"
#include "material/test_util.h"

namespace rp::material {
namespace {

using test::prim;

template <class T>
const T& as(const MaterialParams& m) {
    EXPECT_TRUE(std::holds_alternative<T>(m));
    return std::get<T>(m);
}

// Expects an InputError whose message starts with file:line and contains `text`.
void expectError(const Primitive& p, const std::string& text) {
    try {
        makeMaterial(p);
        ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind("test.rad:" + std::to_string(p.loc.line) + ": ", 0), 0u) << what;
        EXPECT_NE(what.find(text), std::string::npos) << what;
    }
}

TEST(MaterialParams, PlasticDerivedConstants) {
    auto m = as<NormalParams>(makeMaterial(prim(PrimType::Plastic, {.5, .4, .3, .05, .1})));
    EXPECT_EQ(m.kind, NormalParams::Kind::Plastic);
    EXPECT_DOUBLE_EQ(m.alpha2, 0.01);
    EXPECT_FALSE(m.pureSpecular);
    EXPECT_DOUBLE_EQ(m.diffuseReflectance.r, 0.95 * 0.5);  // (1 - spec) colour
    EXPECT_DOUBLE_EQ(m.diffuseReflectance.b, 0.95 * 0.3);
    EXPECT_EQ(m.specularColor, Color::grey(0.05));  // uncoloured highlight
    EXPECT_EQ(m.diffuseTransmittance, Color{});
}

TEST(MaterialParams, MetalSpecularIsColoured) {
    auto m = as<NormalParams>(makeMaterial(prim(PrimType::Metal, {.8, .6, .2, .9, 0})));
    EXPECT_TRUE(m.pureSpecular);
    EXPECT_DOUBLE_EQ(m.specularColor.g, 0.6 * 0.9);
    EXPECT_NEAR(m.diffuseReflectance.r, 0.8 * 0.1, 1e-15);
}

TEST(MaterialParams, TransSplits) {
    // normal.c: trans = T (1 - rspec), tspec = trans Ts, tdiff = trans - tspec.
    auto m = as<NormalParams>(makeMaterial(prim(PrimType::Trans, {.6, .6, .6, .04, .02, .5, .3})));
    EXPECT_DOUBLE_EQ(m.trans, 0.5 * 0.96);
    EXPECT_DOUBLE_EQ(m.tspec, 0.5 * 0.96 * 0.3);
    EXPECT_DOUBLE_EQ(m.tdiff, 0.5 * 0.96 * 0.7);
    EXPECT_DOUBLE_EQ(m.rdiff, 1 - 0.48 - 0.04);
}

TEST(MaterialParams, NegativeRoughnessAcceptedLikeRadiance) {
    auto m = as<NormalParams>(makeMaterial(prim(PrimType::Plastic, {.5, .5, .5, .05, -.1})));
    EXPECT_NEAR(m.alpha2, 0.01, 1e-15);
}

TEST(MaterialParams, AnisoRoughnessTooSmall) {
    std::vector<std::string> s{"1", "0", "0", "."};
    expectError(prim(PrimType::Plastic2, {.5, .5, .5, .05, 0, .1}, s, 12), "roughness too small");
    expectError(prim(PrimType::Trans2, {.5, .5, .5, .05, .1, 1e-7, .5, .5}, s, 13),
                "roughness too small");
    auto m = as<AnisoParams>(makeMaterial(prim(PrimType::Metal2, {.5, .4, .3, .9, .1, .2}, s)));
    EXPECT_EQ(m.uExpr[0], "1");
    EXPECT_EQ(m.funcFile, ".");
    EXPECT_DOUBLE_EQ(m.specularColor.g, 0.4 * 0.9);
}

TEST(MaterialParams, Spotlight) {
    auto m = as<LightParams>(makeMaterial(prim(PrimType::Spotlight, {10, 10, 10, 90, 0, 0, -2})));
    EXPECT_NEAR(m.spotSolidAngle, 2 * kPi * (1 - std::cos(kPi / 4)), 1e-12);
    EXPECT_EQ(m.spotAim, (Vec3{0, 0, -1}));
    EXPECT_DOUBLE_EQ(m.spotFocalLength, 2);
    expectError(prim(PrimType::Spotlight, {1, 1, 1, 0, 0, 0, -1}, {}, 20), "zero angle");
    expectError(prim(PrimType::Spotlight, {1, 1, 1, 30, 0, 0, 0}, {}, 21), "zero focus vector");
}

TEST(MaterialParams, GlowIllumLight) {
    auto g = as<LightParams>(makeMaterial(prim(PrimType::Glow, {1, 2, 3, -1})));
    EXPECT_EQ(g.kind, LightParams::Kind::Glow);
    EXPECT_DOUBLE_EQ(g.glowMaxRadius, -1);
    auto i = as<LightParams>(makeMaterial(prim(PrimType::Illum, {1, 1, 1}, {"glassmat"})));
    ASSERT_TRUE(i.alternate.has_value());
    EXPECT_EQ(*i.alternate, "glassmat");
    auto l = as<LightParams>(makeMaterial(prim(PrimType::Light, {100, 90, 80})));
    EXPECT_EQ(l.radiance, (Color{100, 90, 80}));
}

TEST(MaterialParams, GlassIndexAndChecks) {
    auto g = as<GlassParams>(makeMaterial(prim(PrimType::Glass, {.96, .96, .96})));
    EXPECT_DOUBLE_EQ(g.index, 1.52);
    auto g2 = as<GlassParams>(makeMaterial(prim(PrimType::Glass, {.9, 0, .9, 1.7})));
    EXPECT_DOUBLE_EQ(g2.index, 1.7);
    EXPECT_DOUBLE_EQ(g2.transmission.g, 1e-15);  // glass.c floor for pow()
    expectError(prim(PrimType::Glass, {.9, .9, .9, 0}, {}, 30), "index of refraction");
}

TEST(MaterialParams, DielectricAndInterface) {
    auto d = as<DielectricParams>(makeMaterial(prim(PrimType::Dielectric, {.9, .9, .9, 1.5, 5})));
    EXPECT_DOUBLE_EQ(d.insideIndex, 1.5 + 5.0 / 500);
    EXPECT_DOUBLE_EQ(d.outsideIndex, 1);
    auto i = as<DielectricParams>(
        makeMaterial(prim(PrimType::Interface, {.9, .8, .7, 1.33, 1, 1, 1, 1.5})));
    EXPECT_TRUE(i.isInterface);
    EXPECT_DOUBLE_EQ(i.outsideIndex, 1.5);
    expectError(prim(PrimType::Dielectric, {1, 1, 1, 0, 0}, {}, 31), "index of refraction");
    expectError(prim(PrimType::Interface, {1, 1, 1, 1.3, 1, 1, 1, -1}, {}, 32),
                "index of refraction");
}

TEST(MaterialParams, FuncMaterialsKeepArgs) {
    auto f = as<FuncParams>(
        makeMaterial(prim(PrimType::Transfunc, {.5, .5, .5, .1, .4, .25, 7}, {"brtd", "my.cal"})));
    EXPECT_EQ(f.sargs[1], "my.cal");
    EXPECT_EQ(f.rargs.size(), 7u);
    EXPECT_DOUBLE_EQ(f.trans, 0.4 * 0.9);
    EXPECT_DOUBLE_EQ(f.tdiff, 0.36 * 0.75);
    EXPECT_DOUBLE_EQ(f.rdiff, 1 - 0.36 - 0.1);
}

TEST(MaterialParams, BrtdConstantsParsed) {
    std::vector<std::string> s{"0.1", ".1", "0.1", "0", "0", "0", "0", "0", "0", "."};
    auto b = as<BrtdParams>(
        makeMaterial(prim(PrimType::BRTDfunc, {.2, .2, .2, .3, .3, .3, .1, .1, .1}, s)));
    ASSERT_TRUE(b.specularReflection.has_value());
    EXPECT_DOUBLE_EQ(b.specularReflection->g, 0.1);
    EXPECT_FALSE(b.directionalDiffuse);
    s[0] = "rr";
    auto b2 = as<BrtdParams>(
        makeMaterial(prim(PrimType::BRTDfunc, {.2, .2, .2, .3, .3, .3, .1, .1, .1}, s)));
    EXPECT_FALSE(b2.specularReflection.has_value());
}

TEST(MaterialParams, Mist) {
    // m_mist.c: 0, 3, 6 or 7 real arguments; absent albedo and eccentricity stay unset
    // (the ray keeps its own), the string arguments name sources.
    auto none = as<MistParams>(makeMaterial(prim(PrimType::Mist, {}, {"spot", "sun"})));
    EXPECT_EQ(none.sources, (std::vector<std::string>{"spot", "sun"}));
    EXPECT_TRUE(none.extinction.isBlack());
    EXPECT_FALSE(none.albedo);
    EXPECT_FALSE(none.eccentricity);
    auto ext = as<MistParams>(makeMaterial(prim(PrimType::Mist, {0.1, 0.2, 0.4}, {})));
    EXPECT_EQ(ext.extinction, (Color{0.1, 0.2, 0.4}));
    EXPECT_FALSE(ext.albedo);
    auto all = as<MistParams>(
        makeMaterial(prim(PrimType::Mist, {0.1, 0.1, 0.4, 0.9, 0.8, 0.7, -0.3}, {})));
    EXPECT_EQ(*all.albedo, (Color{0.9, 0.8, 0.7}));
    EXPECT_DOUBLE_EQ(*all.eccentricity, -0.3);
    EXPECT_FALSE(storesPhotons(makeMaterial(prim(PrimType::Mist, {}, {}))));
    expectError(prim(PrimType::Mist, {-0.1, 0, 0}, {}, 40), "negative extinction");
    expectError(prim(PrimType::Mist, {0.1, 0.1, 0.1, 1.5, 0.5, 0.5}, {}, 41),
                "albedo outside [0,1]");
    expectError(prim(PrimType::Mist, {0.1, 0.1, 0.1, 0.5, 0.5, 0.5, 1}, {}, 42),
                "eccentricity outside (-1,1)");
}

TEST(MaterialParams, PrismsCountTheirRedirections) {
    // The expressions and the function file are MaterialCalc's (checked at load there).
    EXPECT_EQ(as<PrismParams>(
                  makeMaterial(prim(PrimType::Prism1, {}, {"coef1", "dx1", "dy1", "dz1", "p.cal"})))
                  .redirections,
              1);
    EXPECT_EQ(as<PrismParams>(makeMaterial(prim(PrimType::Prism2, {1.52},
                                                {"c1", "x1", "y1", "z1", "c2", "x2", "y2", "z2",
                                                 "p.cal", "-rz", "90"})))
                  .redirections,
              2);
    EXPECT_FALSE(
        storesPhotons(makeMaterial(prim(PrimType::Prism1, {}, {"1", "0", "0", "1", "."}))));
}

TEST(MaterialParams, NotAMaterial) {
    expectError(prim(PrimType::Polygon, {0, 0, 0, 1, 0, 0, 0, 1, 0}, {}, 50), "not a material");
}

TEST(MaterialParams, StoresPhotons) {
    EXPECT_TRUE(storesPhotons(makeMaterial(prim(PrimType::Plastic, {.5, .5, .5, 0, 0}))));
    EXPECT_FALSE(storesPhotons(makeMaterial(prim(PrimType::Metal, {.5, .5, .5, 1, 0}))));
    EXPECT_FALSE(storesPhotons(makeMaterial(prim(PrimType::Mirror, {.9, .9, .9}))));
    EXPECT_FALSE(storesPhotons(makeMaterial(prim(PrimType::Glass, {.9, .9, .9}))));
    EXPECT_FALSE(storesPhotons(makeMaterial(prim(PrimType::Light, {9, 9, 9}))));
    EXPECT_FALSE(storesPhotons(makeMaterial(prim(PrimType::Antimatter, {}, {"void"}))));
    EXPECT_TRUE(storesPhotons(makeMaterial(prim(PrimType::Trans, {.5, .5, .5, 0, 0, 1, 0}))));
    EXPECT_TRUE(storesPhotons(
        makeMaterial(prim(PrimType::Plasdata, {.5, .5, .5, .1}, {"f", "d.dat", "f.cal", "x"}))));
}

}  // namespace
}  // namespace rp::material

namespace rp::material {
namespace {

// RADIANCE raytrace.c raynormal. A smoothed triangle of RADIANCE's porsche.octf met from
// behind at grazing incidence: the texture's normal (0.6, 0, 0.8) faces away from the
// ray, and RADIANCE reflects it about the plane across the ray; rtrace -on prints
// (0.721340, 0.119369, -0.682216) for it.
TEST(PerturbedNormal, TurnedToTheRayAndFixedWhenItFacesAway) {
    const Vec3 n = normalize(Vec3{-5.281701e-03, 3.735920e-01, -9.275781e-01});
    const Vec3 dir = normalize(Vec3{-0.99204, -0.08962, -0.08843});
    const Vec3 wanted{0.6, 0, 0.8};
    const Vec3 p = perturbedNormal(n, wanted - n, dot(dir, n) < 0, dir);
    EXPECT_NEAR(p.x, 0.721340, 2e-5);
    EXPECT_NEAR(p.y, 0.119369, 2e-5);
    EXPECT_NEAR(p.z, -0.682216, 2e-5);
    EXPECT_GT(-dot(p, dir), 0);  // faces the ray
    // A perturbation on the ray's side is only normalised and turned.
    const Vec3 up{0, 0, 1};
    const Vec3 q = perturbedNormal(up, Vec3{0.1, 0, 0}, false, Vec3{0, 0, 1});
    EXPECT_NEAR(q.x, -0.1 / std::sqrt(1.01), 1e-12);
    EXPECT_NEAR(q.z, -1 / std::sqrt(1.01), 1e-12);
    // One that cancels the normal leaves it as it was.
    EXPECT_EQ(perturbedNormal(up, Vec3{0, 0, -1}, true, Vec3{0, 0, -1}), up);
}

}  // namespace
}  // namespace rp::material
