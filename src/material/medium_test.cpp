// How a ray's or photon's medium follows its path (m_mist.c, dielectric.c): one rule for
// backward rays, shadow rays and photons.
#include <gtest/gtest.h>

#include "material/material.h"

namespace rp::material {
namespace {

const Medium kGlobal{Color{0.01, 0.01, 0.01}, Color{0.5, 0.5, 0.5}, 0.2};

TEST(Medium, MistAddsItsExtinctionAndSetsAlbedoAndEccentricity) {
    MistParams fog;
    fog.extinction = Color{0.1, 0.1, 0.4};
    fog.albedo = Color{0.9, 0.8, 0.7};
    fog.eccentricity = 0.3;
    // The pattern at the hit scales the extinction (m_mist.c: r->pcol).
    MediumChange in = mistCrossing(fog, true, Color{1, 1, 0.5});
    Medium m = changeMedium(kGlobal, in, kGlobal, &fog);
    EXPECT_NEAR(m.extinction.r, 0.11, 1e-15);
    EXPECT_NEAR(m.extinction.b, 0.21, 1e-15);
    EXPECT_EQ(m.albedo, *fog.albedo);
    EXPECT_EQ(m.eccentricity, 0.3);
    // Leaving subtracts it again, but never below the global medium, and restores the
    // global albedo and eccentricity the mist had set.
    Medium out = changeMedium(m, mistCrossing(fog, false, Color{1, 1, 0.5}), kGlobal, &fog);
    EXPECT_NEAR(out.extinction.r, 0.01, 1e-15);
    EXPECT_NEAR(out.extinction.b, 0.01, 1e-15);
    EXPECT_EQ(out.albedo, kGlobal.albedo);
    EXPECT_EQ(out.eccentricity, kGlobal.eccentricity);
    Medium under = changeMedium(kGlobal, mistCrossing(fog, false, Color{1, 1, 1}), kGlobal, &fog);
    EXPECT_EQ(under.extinction, kGlobal.extinction);
}

TEST(Medium, MistWithoutAlbedoKeepsTheRays) {
    MistParams cone;  // no real arguments: a source list only (RADIANCE's spotcones.rad)
    Medium inside{Color{0.1, 0.1, 0.1}, Color{0.9, 0.9, 0.9}, 0.3};
    Medium m = changeMedium(inside, mistCrossing(cone, true, Color{1, 1, 1}), kGlobal, &cone);
    EXPECT_EQ(m.extinction, inside.extinction);
    EXPECT_EQ(m.albedo, inside.albedo);
    EXPECT_EQ(m.eccentricity, 0.3);
    m = changeMedium(m, mistCrossing(cone, false, Color{1, 1, 1}), kGlobal, &cone);
    EXPECT_EQ(m.albedo, inside.albedo);  // left unchanged: it set none
}

TEST(Medium, DielectricInsideAndOut) {
    // Inside: its own absorption, no scattering (dielectric.c); leaving: the global
    // extinction and albedo, the eccentricity kept.
    Medium glass =
        changeMedium(kGlobal, MediumChange{MediumChange::Kind::Given, Color{2, 2, 2}}, kGlobal);
    EXPECT_EQ(glass.extinction, (Color{2, 2, 2}));
    EXPECT_FALSE(glass.scatters());
    Medium out = changeMedium(Medium{Color{}, Color{}, 0.7},
                              MediumChange{MediumChange::Kind::Global, Color{}}, kGlobal);
    EXPECT_EQ(out.extinction, kGlobal.extinction);
    EXPECT_EQ(out.albedo, kGlobal.albedo);
    EXPECT_EQ(out.eccentricity, 0.7);
    EXPECT_FALSE(Medium{}.active());
}

}  // namespace
}  // namespace rp::material
