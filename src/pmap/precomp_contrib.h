// Precomputed contribution photon maps (the photon-map development branch, manual rev
// 1.51 and tech report rev 1.13: mkpmap -apC file nphotons bwidth comp with -m/-M, -bn,
// -apP): a fraction of a contribution map's photons (precomp.h's stratified choice) each
// gather the binned contributions of their `bwidth` nearest photons, per tracked modifier:
// each neighbour's share of the density estimate (RADIANCE photonContrib) goes to the bin
// rcontrib's own bin expression gives its primary ray (contrib_bins.h), divided by its
// source's radiance for coefficients (-V-). rcontrib then looks up the single nearest
// precomputed photon instead of a density estimate over all sources. The bins are
// compressed (wavelet.h) into one file per modifier (contrib_coeffs.h).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "pmap/contrib_bins.h"
#include "pmap/pass_settings.h"
#include "pmap/photon.h"
#include "pmap/wavelet.h"

namespace rp::pmap {

struct PrecompContribSettings {
    double fraction = 0.25;      // -apP
    int bandwidth = 0;           // photons per estimate
    double compression = 0;      // [0, 1]
    bool contributions = false;  // -V
    PassSettings pass;           // -n, -t, -apr
    std::ostream* progress = nullptr;
    std::string mapFile;  // coefficient files go beside it
    std::string commandLine;
    bool overwrite = false;  // -fo
};

struct PrecompContribResult {
    // Position and normal of each precomputed photon, `primary` the index of its records,
    // flux the sum of its bins over every modifier (what pmapdump shows). First those
    // estimated from every photon, then, with the caustic flag, a selection of the caustic
    // photons estimated from caustic photons alone (what rcontrib reads at its sensor
    // points, as it reads a contribution map's caustic photons there).
    std::vector<Photon> photons;
    std::vector<double> emptyBins;  // per modifier: fraction of zero bins over all records
};

// The contribution photons with their primaries and primary rays (one per primary); the
// coefficient files are written (committed) before returning. Throws InputError when no
// photon is selected, or for a modifier that no source's material names. The files are
// the same for any number of threads.
PrecompContribResult precomputeContrib(std::vector<Photon> photons,
                                       const std::vector<PhotonPrimary>& primaries,
                                       const std::vector<PrimaryRay>& rays,
                                       const std::vector<ContribSource>& sources,
                                       const ContribBins& bins, const PrecompContribSettings& s);

}  // namespace rp::pmap
