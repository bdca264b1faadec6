// Contribution photon maps (mkpmap -apC file n; photon-map manual 4.5 and 8, RADIANCE
// pmapcontrib.c distribPhotonContrib): every light source emits until it has stored
// about n / nsources photons, whatever its flux, and its photons carry that source's
// flux divided by the number it emitted, so energy balance holds per source. Every
// emitted photon whose path stores at least one photon gets a primary (PhotonPrimary:
// the emitting source's index, as RADIANCE's default build, file version 3.1k; with
// -apCPD also its PrimaryRay, as its PMAP_CBDM build, 3.1kPD), and all photons stored
// along that path index it.
// Photons are stored where global photons are (indirect hits; pmapmat.c addPhotons).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/emitter.h"
#include "pmap/pass_settings.h"
#include "pmap/photon.h"
#include "pmap/trace.h"
#include "scene/primitive.h"
#include "util/cluster.h"

namespace rp::pmap {

struct ContribSettings {
    uint64_t target = 0;  // -apC nphotons, over all sources
    PassSettings pass;    // -apD -apM -apr -n -t (manual 4.4 line, photons as "global")
    std::ostream* progress = nullptr;
    bool primaryRays = false;  // -apCPD: keep where each primary left its source
    // The ranks tracing together (null: this process alone); photons, primaries and
    // per-source counts are the root's, the others return them empty.
    Cluster* cluster = nullptr;
};

struct ContribResult {
    std::vector<Photon> photons;  // normalised flux, primary = index into primaries
    std::vector<PhotonPrimary> primaries;
    std::vector<PrimaryRay> primaryRays;  // one per primary with primaryRays, else empty
    std::vector<uint64_t> emitted;        // per source (index into plan.sources())
    std::vector<uint64_t> stored;         // per source
    uint64_t totalEmitted = 0;
    long runaways = 0;
};

// Distributes photons source by source. `plan` supplies the sources (srcIdx is the index
// into plan.sources()) and `emission` the options a single-source plan is built with;
// `trace` is used as is except that only the global map is collected. Sources with zero
// flux, and sources that store nothing after -apM prepasses, are skipped with a warning
// (as RADIANCE). Throws InputError if nothing is stored at all or there are more sources
// than a 16-bit source index holds. The result does not depend on `threads`.
// `chains` and `materialCalc` as for PhotonTracer.
ContribResult distributeContrib(const Scene& scene, const SceneGeometry& geometry,
                                const light::EmissionPlan& plan,
                                const light::EmissionOptions& emission, TraceSettings trace,
                                const ContribSettings& settings,
                                const material::SurfaceChains& chains,
                                const material::MaterialCalc* materialCalc = nullptr);

}  // namespace rp::pmap
