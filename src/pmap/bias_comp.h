// Bias compensation for photon density estimates (-ap file bwidth1 bwidth2; photon-map
// manual 3.2.2, Schregle 2003 "Bias compensation for photon maps"): the choice of bandwidth
// per lookup and the statistics of the -t progress report (manual 5.3). The photon search
// itself is PhotonLookup::biasCompensatedDensity (density.h).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"

namespace rp::pmap {

// Formulation (ours; RADIANCE's differs, see below). A lookup gathers the m <= bw2+1
// nearest photons, sorted by squared distance d_1 <= ... <= d_m. The estimate at
// bandwidth j (j photons summed) is RADIANCE's photonDensity for k = j:
//     E(j) = (sum of the flux of photons 1..j) / (pi * pi * R2(j)),
//     R2(j) = ((sqrt(d_j) + sqrt(d_{j+1})) / 2)^2,
// with d_{j+1} replaced by the search radius^2 when j+1 = m and the search ended short of
// bw2+1 photons (as photonDensity uses its search limit then). E(bw2) with a full queue is
// exactly surfaceDensity with bandwidth bw2. Bandwidths run over [b1, b2] = [min(bw1, m-1),
// min(bw2, m-1)].
//
// Bias is the systematic change of E(j) as j grows; noise of a j-photon estimate is
// ~ E/sqrt(j) (Poisson count of photons of similar flux). Two nested estimates E(r), E(j),
// r < j, share the r nearest photons, so under a constant density their difference has
// variance E^2 (1/r - 1/j) (the photons r+1..j are independent of the first r). We call j
// consistent with r when, in every RGB channel c,
//     |E_c(j) - E_c(r)| <= kBiasCompZ * E_c(j) * sqrt(1/r - 1/j).
// Binary search, as Schregle's, for the largest consistent bandwidth: lo = b1 (always
// accepted), hi = b2; while lo < hi: mid = lo + ceil((hi - lo) / 2); if mid is consistent
// with both b1 (the least biased estimate: bounds the total drift) and lo (the last
// accepted: sensitive to a local jump, its difference has little noise when lo is large)
// then lo = mid, else hi = mid - 1. The result is E(lo) with bandwidth lo.
//
// Why not RADIANCE's test: it compares each estimate with a weighted running mean of the
// previous lookups' estimates, so the result depends on the order of queries (and on
// threads). Ours uses only the photons around the query point: the same point always gets
// the same bandwidth and estimate (given the same photons found, i.e. the same search
// radius; see PhotonLookup on the adaptive radius). The price is a noisier reference: a
// bias smaller than about kBiasCompZ / sqrt(b1) of the estimate goes undetected.
constexpr double kBiasCompZ = 2.0;

// Per-lookup relative error estimate of the report: 1/sqrt(bandwidth used), the noise of
// the chosen estimate (its remaining bias is, by construction, within the noise; manual 5.3
// calls these figures approximate too).

// Statistics for the -t report (manual 5.3). Accumulate per thread, then merge().
struct BiasCompStats {
    uint64_t lookups = 0;  // lookups with at least 2 photons (the others estimate 0)
    int minBandwidth = std::numeric_limits<int>::max();
    int maxBandwidth = 0;
    double sumBandwidth = 0;
    double minError = std::numeric_limits<double>::infinity();
    double maxError = 0;
    double sumError2 = 0;

    void add(int bandwidth, double relError);
    void merge(const BiasCompStats& o);
    double meanBandwidth() const { return lookups ? sumBandwidth / double(lookups) : 0; }
    double rmsError() const;
    // Manual 5.3's line "Nmin/Nmax/Navg ptype, (emin/emax/erms error)", e.g.
    // "50/500/321.4 caustic, (0.045/0.141/0.067 error)"; "" if there were no lookups.
    std::string report(const char* photonType) const;
};

struct BiasCompResult {
    std::array<double, 3> density = {0, 0, 0};  // irradiance / pi, as surfaceDensity
    int bandwidth = 0;                          // photons summed (0 when fewer than 2 found)
    double relError = 0;
};

// The bandwidth choice above over the photons `hits` found around the query (any order;
// sorted in place by dist2), `photons` the map they index, `searchDist2` the search
// radius^2 of the lookup, `full` whether the search filled its queue (then the furthest
// photon only sets the radius of E(m-1)). `prefix` is scratch (reused, no allocation once
// large enough). Deterministic: depends on nothing else.
BiasCompResult compensateBias(std::span<PhotonHit> hits, std::span<const Photon> photons,
                              double searchDist2, bool full, int bwMin, int bwMax,
                              std::vector<std::array<double, 3>>& prefix);

}  // namespace rp::pmap
