// Photon distribution (photon-map manual 4.1-4.2, RADIANCE pmap.c distribPhotons): the
// prepass, the prediction of how many photons to emit so that every map reaches its
// target, the main pass, and flux normalisation. Runs in parallel over fixed chunks of
// photon indices, so the result is the same for any thread count. Tracing one photon
// is trace.h; building and saving maps is mkpmap.h.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "pmap/pass_settings.h"
#include "pmap/photon.h"
#include "pmap/record_store.h"
#include "pmap/trace.h"
#include "util/cluster.h"

namespace rp::pmap {

struct DistributionSettings {
    std::array<uint64_t, kNumPhotonMapTypes> targets{};  // 0 = map not requested
    PassSettings pass;                                   // -apD -apM -apr -n -t
    std::ostream* progress = nullptr;                    // where -t reports go
    // With a budget (mkpmap -aC), the photons held in memory (prepass deposits and final
    // records, all maps together) stay within it; map t's photons beyond it are spilled to
    // a temporary file beside files[t], which errors name. Without, all stay in memory.
    MemoryBudget* budget = nullptr;
    std::array<std::string, kNumPhotonMapTypes> files;
    // The ranks tracing this distribution together (null: this process alone). Every
    // rank calls distributePhotons with the same settings; the photons are the root's.
    Cluster* cluster = nullptr;
};

struct DistributionResult {
    // Normalised flux, in photon index order (as the kd-tree build wants them: any order);
    // empty on ranks other than the root. The counts are the same on every rank.
    std::array<RecordStore<Photon>, kNumPhotonMapTypes> photons;
    uint64_t emitted = 0;  // photons emitted over all passes
    uint64_t prepassEmitted = 0;
    int prepasses = 0;
    std::array<double, kNumPhotonMapTypes> storeProbability{};  // per map, all passes
    long runaways = 0;
    // The root's seconds storing what was traced, serially (decoding other ranks' chunks,
    // thinning, normalising, appending): the part that does not scale with ranks.
    double storingSeconds = 0;
};

// Photons traced per work item: fixed, so that chunk boundaries (and thus the order
// photons are concatenated in) never depend on the number of threads.
constexpr uint64_t kPhotonsPerChunk = 2048;

// Traces photons until every requested map holds about its target. Throws InputError
// when a map is still empty after maxPrepass prepasses (manual 4.2).
//
// Algorithm. Photon i's emission and path are functions of (seed, i) only (trace.h),
// and every deposit carries its own storage draw u. The prepass traces indices
// [0, N0) storing everything (N0 = -apD x smallest target, doubled while a map is empty,
// up to -apM passes) and measures each map's stored photons per emitted photon r_t.
// The total to emit is N = max_t target_t / r_t; map t then keeps a deposit iff
// u < p_t = target_t / (r_t N), in the prepass (thinned after the fact) and in the main
// pass over [N0, N) alike. Every kept photon of map t thus carries flux
// weight x path factors / (N p_t): one probability and one normaliser per map, unlike
// RADIANCE, which stores all prepass photons and rescales by an approximate ratio.
DistributionResult distributePhotons(const PhotonTracer& tracer,
                                     const DistributionSettings& settings);

}  // namespace rp::pmap
