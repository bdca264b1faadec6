// One test per photon-map mode rule (photon_mode.h), each against the RADIANCE source
// it follows.
#include "render/photon_mode.h"

#include <gtest/gtest.h>

namespace rp::render {
namespace {

PhotonMapKinds global() { return {.global = true}; }
PhotonMapKinds globalAndCaustic() { return {.global = true, .caustic = true}; }
PhotonMapKinds causticOnly() { return {.caustic = true}; }
PhotonMapKinds contribWithCaustics() { return {.contrib = true, .contribCaustic = true}; }

constexpr PathDepth kPrimary{0, 0};      // the eye ray's hit
constexpr PathDepth kGatherHit{1, 1};    // a final-gather sample's hit
constexpr PathDepth kBelowGather{1, 2};  // a specular child of a gather sample

TEST(PhotonMode, NoMapsChangesNothing) {
    const PhotonMode m({}, 3);
    EXPECT_FALSE(m.active());
    EXPECT_EQ(m.ambientBounces(), 3);
    EXPECT_TRUE(m.virtualSources());
    EXPECT_FALSE(m.specularRaysInPhotons(kBelowGather));
    EXPECT_FALSE(m.specularDirectInPhotons(kBelowGather));
    EXPECT_FALSE(m.shadowsStopAtTransparent(kGatherHit));
    const PhotonMode::AmbientReads r = m.ambientReads(kGatherHit);
    EXPECT_FALSE(r.global || r.caustic || r.contribGather || r.contribCaustic);
}

TEST(PhotonMode, AmbientBouncesBecomeOneGatherOrNone) {
    // Manual 5.1 and rtrace/rpict 5.4: any -ab >= 0 is one final gather, -ab < 0 none.
    EXPECT_EQ(PhotonMode(global(), 0).ambientBounces(), 1);
    EXPECT_EQ(PhotonMode(global(), 7).ambientBounces(), 1);
    EXPECT_EQ(PhotonMode(global(), -3).ambientBounces(), -1);
}

TEST(PhotonMode, NoVirtualSourcesWithPhotons) {
    // source.c: mirror and prism light comes through caustic photons instead.
    EXPECT_FALSE(PhotonMode(causticOnly(), 1).virtualSources());
}

TEST(PhotonMode, SpecularRaysOfGatherSamples) {
    // pmapmat.h ambRayInPmap: a global map alone lets a gather sample see through glass
    // at its first hit, but not below; a caustic map carries that light already.
    const PhotonMode g(global(), 1);
    EXPECT_FALSE(g.specularRaysInPhotons(kPrimary));
    EXPECT_FALSE(g.specularRaysInPhotons(kGatherHit));
    EXPECT_TRUE(g.specularRaysInPhotons(kBelowGather));
    EXPECT_TRUE(PhotonMode(globalAndCaustic(), 1).specularRaysInPhotons(kGatherHit));
    EXPECT_FALSE(PhotonMode(globalAndCaustic(), 1).specularRaysInPhotons(kPrimary));
    EXPECT_TRUE(PhotonMode(contribWithCaustics(), 1).specularRaysInPhotons(kGatherHit));
    // -ab < 0: no gather at all, every ambient-level ray's specular light is in photons.
    EXPECT_TRUE(PhotonMode(global(), -1).specularRaysInPhotons(kGatherHit));
}

TEST(PhotonMode, BsdfSpecularDirectOnlyBelowTheGather) {
    // ambRayInPmap for a BSDF's specular direct light: at a gather hit it is not in the
    // photons (issue 43), even with a caustic map.
    const PhotonMode m(globalAndCaustic(), 1);
    EXPECT_FALSE(m.specularDirectInPhotons(kPrimary));
    EXPECT_FALSE(m.specularDirectInPhotons(kGatherHit));
    EXPECT_TRUE(m.specularDirectInPhotons(kBelowGather));
    EXPECT_TRUE(PhotonMode(global(), -1).specularDirectInPhotons(kGatherHit));
}

TEST(PhotonMode, ShadowRaysStopAtTransparentSurfaces) {
    // pmapmat.h shadowRayInPmap: below an ambient ray always; on the primary path only
    // when caustic light is in the photons; everywhere with -ab < 0.
    const PhotonMode g(global(), 1);
    EXPECT_FALSE(g.shadowsStopAtTransparent(kPrimary));
    EXPECT_TRUE(g.shadowsStopAtTransparent(kGatherHit));
    EXPECT_TRUE(PhotonMode(causticOnly(), 1).shadowsStopAtTransparent(kPrimary));
    EXPECT_TRUE(PhotonMode(contribWithCaustics(), 1).shadowsStopAtTransparent(kPrimary));
    EXPECT_TRUE(PhotonMode(global(), -1).shadowsStopAtTransparent(kPrimary));
}

TEST(PhotonMode, DirectVolumeAndMediumRules) {
    EXPECT_TRUE(PhotonMode({.direct = true}, 1).directFromPhotons());
    EXPECT_FALSE(PhotonMode(global(), 1).directFromPhotons());
    EXPECT_TRUE(PhotonMode({.volume = true}, 1).volumeFromPhotons());
    // Scattered shadow-ray light reaches surfaces as global photons.
    EXPECT_TRUE(PhotonMode(global(), 1).mediumScatterInPhotons());
    EXPECT_FALSE(PhotonMode(causticOnly(), 1).mediumScatterInPhotons());
}

TEST(PhotonMode, AmbientReadsFollowPmapamb) {
    // pmapamb.c: the gather hit reads the global map alone; the primary hit adds the
    // caustic map and gathers.
    const PhotonMode gc(globalAndCaustic(), 1);
    PhotonMode::AmbientReads r = gc.ambientReads(kGatherHit);
    EXPECT_TRUE(r.global);
    EXPECT_FALSE(r.caustic);
    r = gc.ambientReads(kPrimary);
    EXPECT_FALSE(r.global);
    EXPECT_TRUE(r.caustic);
    // -ab -1: the primary hit reads the global map.
    EXPECT_TRUE(PhotonMode(globalAndCaustic(), -1).ambientReads(kPrimary).global);
    // ambPmapCaustic: without a global map the caustic map fills in at gather hits too.
    EXPECT_TRUE(PhotonMode(causticOnly(), 1).ambientReads(kGatherHit).caustic);
    // A contribution map: the whole term at gather hits, its caustic photons elsewhere.
    const PhotonMode c(contribWithCaustics(), 1);
    EXPECT_TRUE(c.ambientReads(kGatherHit).contribGather);
    EXPECT_FALSE(c.ambientReads(kGatherHit).contribCaustic);
    EXPECT_TRUE(c.ambientReads(kPrimary).contribCaustic);
    EXPECT_FALSE(c.ambientReads(kPrimary).contribGather);
}

}  // namespace
}  // namespace rp::render
