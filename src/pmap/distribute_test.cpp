// Distribution: targets met within 5 %, results independent of the thread count,
// flux normalised by the photons emitted over all passes.
#include <gtest/gtest.h>

#include "pmap/trace_test_util.h"

namespace rp::pmap {
namespace {

using testing::distribute;
using testing::makeRun;
using testing::mapsFor;
using testing::sceneFromFile;

std::string cornell() { return std::string(RP_SOURCE_DIR) + "/examples/cornell/scene.rad"; }

// The brief's 5 %: global 50k + caustic 100k on the Cornell box (RADIANCE's mkpmap.1
// promises "up to 10 %").
TEST(Distribute, CornellTargetsWithinFivePercent) {
    auto run = makeRun(sceneFromFile(cornell()), mapsFor(true, true, false));
    DistributionResult r = distribute(*run, 50000, 100000, 0, 2);
    EXPECT_NEAR(double(r.photons[size_t(PhotonMapType::Global)].size()), 50000, 2500);
    EXPECT_NEAR(double(r.photons[size_t(PhotonMapType::Caustic)].size()), 100000, 5000);
    EXPECT_GE(r.emitted, r.prepassEmitted);
    // The map that sets the photon count stores everything; the other is thinned.
    EXPECT_DOUBLE_EQ(r.storeProbability[size_t(PhotonMapType::Caustic)], 1.0);
    EXPECT_LT(r.storeProbability[size_t(PhotonMapType::Global)], 1.0);
}

// Photon i's path depends on (seed, i) only and chunks are concatenated in index order,
// so every thread count gives the same photons in the same order.
TEST(Distribute, IdenticalForAnyThreadCount) {
    auto run = makeRun(sceneFromFile(cornell()), mapsFor(true, true, true));
    DistributionResult a = distribute(*run, 5000, 8000, 3000, 1, 7);
    DistributionResult b = distribute(*run, 5000, 8000, 3000, 2, 7);
    DistributionResult c = distribute(*run, 5000, 8000, 3000, 3, 7);
    EXPECT_EQ(a.emitted, b.emitted);
    for (size_t t = 0; t < a.photons.size(); ++t) {
        EXPECT_TRUE(a.photons[t].toVector() == b.photons[t].toVector()) << t;
        EXPECT_TRUE(a.photons[t].toVector() == c.photons[t].toVector()) << t;
    }
    // A different seed gives a different map.
    DistributionResult d = distribute(*run, 5000, 8000, 3000, 2, 8);
    EXPECT_FALSE(a.photons[size_t(PhotonMapType::Global)].toVector() ==
                 d.photons[size_t(PhotonMapType::Global)].toVector());
}

// Flux per photon is independent of the target: the total stored flux of the direct map
// is the emitted flux whatever the number of photons (within 4 sigma of the smaller map).
TEST(Distribute, FluxNormalisedOverAllPasses) {
    auto run = makeRun(sceneFromFile(cornell()), mapsFor(false, false, true));
    for (uint64_t n : {2000u, 20000u}) {
        DistributionResult r = distribute(*run, 0, 0, n);
        Color sum;
        for (const Photon& p : r.photons[size_t(PhotonMapType::Direct)].toVector()) {
            auto f = p.fluxRgb();
            sum += Color{f[0], f[1], f[2]};
        }
        // Every emitted photon hits the room once: direct flux = total emitted flux
        // minus what lands on the lamp's back/glass sphere/mirror (non-diffuse).
        EXPECT_LT(sum.average(), run->plan->totalFluxW() * 1.001) << n;
        EXPECT_GT(sum.average(), run->plan->totalFluxW() * 0.6) << n;
    }
}

}  // namespace
}  // namespace rp::pmap
