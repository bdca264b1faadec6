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
#include "pmap/photon_store.h"

namespace rp::pmap {

// Formulation: RADIANCE's (pmapbias.c, after Schregle 2003), made deterministic. A lookup
// gathers the m <= bw2+1 nearest photons, sorted by squared distance d_1 <= ... <= d_m.
// The estimate at bandwidth j (j photons summed) is RADIANCE's photonDensity for k = j:
//     E(j) = (sum of the flux of photons 1..j) / (pi * pi * R2(j)),
//     R2(j) = ((sqrt(d_j) + sqrt(d_{j+1})) / 2)^2,
// with d_{j+1} replaced by the search radius^2 when j+1 = m and the search ended short of
// bw2+1 photons (as photonDensity uses its search limit then). Bandwidths run over
// [b1, b2] = [min(bw1, m-1), min(bw2, m-1)].
//
// A per-lookup history holds E(1), ..., E(b1) with weights j^2 (RADIANCE's BIASCOMP_WGT);
// its weighted mean and variance per RGB channel describe what noise looks like here.
// Binary search: lo = b1, hi = b2; while hi - lo > 1: mid = (lo + hi) / 2; the deviation
// d_c = mean_c - E_c(mid) is plausible noise with likelihood p_c = exp(-d_c^2 / (2 var_c));
// if the mean of p over the channels is at least kBiasCompAccept, E(mid) joins the history
// (mean and variance updated) and lo = mid, else hi = mid. The result is the last estimate
// that joined the history, E(lo). So bw1 = bw2 gives the fixed-bandwidth estimate.
//
// RADIANCE accepts E(mid) with probability p (a random number per step), which makes its
// result depend on the random stream, i.e. on the order of queries and on processes (the
// caustic README: 138.6 vs 119.2 W/m2 at one sensor). We accept exactly when acceptance is
// the more likely outcome (p >= 1/2, |d| <= 1.18 sigma): the same point always gets the
// same bandwidth and estimate (given the same photons found, i.e. the same search radius;
// see PhotonLookup on the adaptive radius).
constexpr double kBiasCompAccept = 0.5;

// Per-lookup relative error of the report, as RADIANCE's: the result relative to the
// final history mean, minus 1, averaged over the channels.

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
// sorted in place by dist2), `searchDist2` the search
// radius^2 of the lookup, `full` whether the search filled its queue (then the furthest
// photon only sets the radius of E(m-1)). `prefix` is scratch (reused, no allocation once
// large enough). Deterministic: depends on nothing else.
BiasCompResult compensateBias(std::span<FoundPhoton> hits, double searchDist2, bool full, int bwMin,
                              int bwMax, std::vector<std::array<double, 3>>& prefix);

}  // namespace rp::pmap
