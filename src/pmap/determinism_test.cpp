// Photon maps do not depend on the thread count (STYLE.md: random streams seeded from
// (seed, domain, chunk)), over a scene with every material family photons interact with;
// and a photon meeting plastic2 after a BSDF uses plastic2's own orientation, the one the
// backward pass prepares (nothing of the BSDF's hit leaks through the reused SurfacePoint).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "material/material_calc.h"
#include "pmap/trace_test_util.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

using testing::distribute;
using testing::makeRun;
using testing::mapsFor;
using testing::sceneFromText;

const std::string kBsdfXml = std::string(RP_SOURCE_DIR) + "/tests/data/bsdf/ttree3.xml";

// The up vectors of plastic2 and ashik2 come from a function file.
void writeCal(const std::string& path) {
    std::ofstream(path) << "ux = 1; uy = 0; uz = 0;\nvx = 0; vy = 1; vz = 0;\n";
}

// A 4 m room (plastic walls, light panel) holding one object of each family: plastic2 and
// ashik2 with their own up vectors (.cal), metal, trans, mirror, glass, dielectric,
// BRTDfunc, two BSDFs with different up vectors, WGMDfunc, a mist volume and an
// antimatter clip. prism1 is left out: the photon tracer refuses it (RADIANCE's has none).
std::string scene(const std::string& cal) {
    return testing::boxRoom() + R"(
void plastic2 aniso_a 4 ux uy uz )" +
           cal + R"( 0 6 .6 .5 .4 .3 .05 .25
void ashik2 ashik_a 4 vx vy vz )" +
           cal + R"( 0 8 .3 .3 .3 .2 .2 .2 20 80
void metal metal_a 0 0 5 .8 .7 .5 .9 .1
void trans trans_a 0 0 7 .6 .6 .6 .04 .05 .5 .3
void mirror mirror_a 0 0 3 .9 .9 .9
void glass glass_a 0 0 3 .86 .86 .86
void dielectric diel_a 0 0 5 .95 .95 .95 1.5 0
void BRTDfunc brtd_a 10 .2 .2 .2 .1 .1 .1 0 0 0 . 0 9 .3 .3 .3 .05 .05 .05 .1 .1 .1
void BSDF bsdf_a 6 0 )" +
           kBsdfXml + R"( 0 0 1 . 0 0
void BSDF bsdf_b 6 0 )" +
           kBsdfXml + R"( 1 0 0 . 0 0
void WGMDfunc wgmd_a 13 void .08 .15 .3 void .1 .15 .3 void 0 1 0 . 0 9 .3 .3 .3 .2 .2 .2 .1 .1 .1
void mist fog 0 0 7 .2 .2 .2 .8 .8 .8 .3
void antimatter anti 1 metal_a 0 0
aniso_a polygon p2floor 0 0 12  .2 .2 .01  1.8 .2 .01  1.8 1.8 .01  .2 1.8 .01
ashik_a polygon ashfloor 0 0 12  2.2 .2 .01  3.8 .2 .01  3.8 1.8 .01  2.2 1.8 .01
metal_a sphere ball 0 0 4 1 3 .5 .4
anti sphere bite 0 0 4 1.2 3 .7 .25
trans_a polygon tpane 0 0 12  3 2.5 .1  3.8 2.5 .1  3.8 2.5 1.5  3 2.5 1.5
mirror_a polygon mir 0 0 12  3.98 .5 .5  3.98 .5 2  3.98 1.5 2  3.98 1.5 .5
glass_a polygon gpane 0 0 12  .5 3.5 .2  1.5 3.5 .2  1.5 3.5 1.2  .5 3.5 1.2
diel_a sphere dball 0 0 4 2 2 .5 .3
brtd_a polygon bpane 0 0 12  2.5 3.5 .1  3.5 3.5 .1  3.5 3.5 1  2.5 3.5 1
bsdf_a polygon bsdfx 0 0 12  .02 2.2 .2  .02 2.2 1.2  .02 3 1.2  .02 3 .2
bsdf_b polygon bsdfy 0 0 12  .5 .02 .2  1.5 .02 .2  1.5 .02 1.2  .5 .02 1.2
wgmd_a polygon wpane 0 0 12  2.2 2.2 .02  2.8 2.2 .02  2.8 2.8 .02  2.2 2.8 .02
fog sphere cloud 0 0 4 3 1 2.5 .5
)";
}

std::vector<Photon> mapOf(const DistributionResult& r, PhotonMapType t) {
    return r.photons[size_t(t)].toVector();
}

// Global and caustic maps traced with 1, 2 and 3 threads hold the same photons, byte for
// byte and in the same order (seed 3; 20000 global, 5000 caustic photons).
TEST(PhotonMapDeterminism, SameMapsForOneTwoThreeThreads) {
    TempDir dir;
    const std::string cal = dir.file("up.cal");
    writeCal(cal);
    auto run = makeRun(sceneFromText(scene(cal)), mapsFor(true, true, false), {}, true);
    const DistributionResult one = distribute(*run, 20000, 5000, 0, 1, 3);
    for (auto t : {PhotonMapType::Global, PhotonMapType::Caustic})
        ASSERT_GT(mapOf(one, t).size(), 1000u) << int(t);
    for (int threads : {2, 3}) {
        const DistributionResult r = distribute(*run, 20000, 5000, 0, threads, 3);
        EXPECT_EQ(r.emitted, one.emitted) << threads;
        for (auto t : {PhotonMapType::Global, PhotonMapType::Caustic}) {
            const auto got = mapOf(r, t), want = mapOf(one, t);
            ASSERT_EQ(got.size(), want.size()) << threads << " threads, map " << int(t);
            EXPECT_EQ(std::memcmp(got.data(), want.data(), got.size() * sizeof(Photon)), 0)
                << threads << " threads, map " << int(t);
        }
    }
}

int32_t primNamed(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.prims.size(); ++i)
        if (s.prims[i].name == name) return int32_t(i);
    return -1;
}

// The photon tracer's sequence at a BSDF hit and then a plastic2 hit on one reused
// SurfacePoint (trace.cpp: setSurfaceHit, prepareHit, scatterPhoton,
// resetPreparedInputs) against a fresh SurfacePoint prepared as the backward pass
// prepares one: the same u orientation, the same evaluate() value, the same photon.
TEST(PhotonMapDeterminism, Plastic2AfterBsdfUsesItsOwnUpVector) {
    TempDir dir;
    const std::string cal = dir.file("up.cal");
    writeCal(cal);
    const Scene s = sceneFromText(scene(cal));
    const std::vector<std::string> path{std::string(RP_SOURCE_DIR) + "/lib"};
    const material::MaterialCalc calc(s, path);
    const material::SurfaceChains chains(s, path);
    material::HitEvaluators evals(&calc, chains);
    const int32_t bsdf = primNamed(s, "bsdf_b"), aniso = primNamed(s, "aniso_a");
    ASSERT_GE(bsdf, 0);
    ASSERT_GE(aniso, 0);
    const material::MaterialParams bsdfParams = material::makeMaterial(s.prims[size_t(bsdf)]);
    const material::MaterialParams anisoParams = material::makeMaterial(s.prims[size_t(aniso)]);

    const Vec3 up{0, 0, 1}, dir45 = normalize(Vec3{.3, .5, -1});
    const Vec3 bsdfNormal{0, 1, 0}, bsdfDir = normalize(Vec3{.2, -1, -.3});
    Rng rng(9, RngDomain::Test, 0);
    material::HitScratch scratch;
    material::SurfacePoint sp;  // the tracer's, reused along the path
    material::setSurfaceHit(sp, bsdfDir, bsdfNormal, false);
    material::prepareHit(evals, bsdf, bsdfParams,
                         material::PatternPoint::atHit(bsdfDir, {1, 0, .5}, -bsdfNormal, 1), sp,
                         scratch, rng);
    ASSERT_NE(sp.bsdf, nullptr);
    EXPECT_NEAR(sp.uDir.x, 1, 1e-12);  // bsdf_b's up vector
    (void)material::scatterPhoton(bsdfParams, sp, rng);
    material::resetPreparedInputs(sp);
    const material::PatternPoint at = material::PatternPoint::atHit(dir45, {1, 1, .01}, up, 2);
    material::setSurfaceHit(sp, dir45, up, true);
    material::prepareHit(evals, aniso, anisoParams, at, sp, scratch, rng);

    material::HitScratch freshScratch;
    material::SurfacePoint fresh = material::makeSurfacePoint(dir45, up, true);
    material::prepareHit(evals, aniso, anisoParams, at, fresh, freshScratch, rng);
    EXPECT_EQ(sp.uDir, fresh.uDir);
    EXPECT_NEAR(fresh.uDir.x, 1, 1e-12);  // ux = 1 of up.cal, not the BSDF's
    const Vec3 l = normalize(Vec3{.4, .6, 1});
    EXPECT_EQ(material::evaluate(anisoParams, sp, l), material::evaluate(anisoParams, fresh, l));
    for (uint64_t k = 0; k < 200; ++k) {
        Rng a(k, RngDomain::Test, 1), b(k, RngDomain::Test, 1);
        const material::PhotonScatter pa = material::scatterPhoton(anisoParams, sp, a);
        const material::PhotonScatter pb = material::scatterPhoton(anisoParams, fresh, b);
        ASSERT_EQ(pa.kind, pb.kind) << k;
        ASSERT_EQ(pa.dir, pb.dir) << k;
    }
}

}  // namespace
}  // namespace rp::pmap
