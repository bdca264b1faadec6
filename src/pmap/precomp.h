// Precomputed global photon maps (mkpmap -app file n bwidth, -apP fraction; photon-map
// manual 3.2.1 and 4.5, RADIANCE pmapdata.c preComputeGlobal, after Christensen 2000):
// a stratified random subset of the global photons keeps, as its flux, the irradiance
// density estimate over the full global map at its position. Renderers then look up the
// single nearest precomputed photon (density.h precompDensity).
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <vector>

#include "pmap/pass_settings.h"
#include "pmap/photon.h"

namespace rp::pmap {

struct PrecompSettings {
    double fraction = 0.25;  // -apP, in ]0, 1]
    int bandwidth = 40;      // -app's bwidth: photons per density estimate
    // -apr (the subset is a function of seed and photon count only), -n, -t ("N_p
    // precomputed, P% after T hours", manual 4.4); -apD and -apM are not used here.
    PassSettings pass;
    std::ostream* progress = nullptr;
};

// Indices of the photons to precompute among n global photons: floor(fraction * n) of
// them, photon i of the subset drawn uniformly from the stratum [i, i+1) / fraction
// (RADIANCE's stratified choice, which avoids duplicates and clustering). Ascending.
std::vector<uint64_t> precompSelection(uint64_t n, double fraction, uint64_t seed);

// Precomputes the selected photons. Each kept photon has its position and normal; its
// flux becomes PhotonLookup::surfaceDensity over a global map of all `global` photons at
// that position and normal with the given bandwidth, i.e. irradiance / pi, which is what
// RADIANCE stores (photonDensity's value, written with newPhoton and no flux rescaling
// in buildPhotonMap) and what its photonPreCompDensity returns unchanged. The caustic
// flag and primary are cleared (RADIANCE's dummy ray). Parallel over fixed chunks of
// photons, each with a fresh lookup state, so the result does not depend on `threads`.
// Returns photons in selection order (the caller builds the PreComp map from them).
std::vector<Photon> precomputeGlobal(std::vector<Photon> global, const PrecompSettings& settings);

// Photons per precomputation work item (fixed: deterministic adaptive search radius).
constexpr uint64_t kPrecompChunk = 512;

// Sorts the photon indices [first, last) into a space-filling curve's order over their
// photons' positions (ties by index): consecutive estimates then search neighbouring
// parts of the map, which stay in the cache between them.
void sortAlongCurve(const std::vector<Photon>& photons, std::vector<uint64_t>::iterator first,
                    std::vector<uint64_t>::iterator last);

// Runs work(i0, i1) over [0, count) in chunks of kPrecompChunk on pass.threads threads,
// each chunk once (any order), with -t progress lines "N precomputed, P% after T hours"
// on `progress` and a closing 100% line.
void forEachPrecompChunk(uint64_t count, const PassSettings& pass, std::ostream* progress,
                         const std::function<void(uint64_t i0, uint64_t i1)>& work);

}  // namespace rp::pmap
