// RADIANCE's photon-map mode rules (see photon_mode.h).
#include "render/photon_mode.h"

namespace rp::render {

PhotonMode::PhotonMode(const PhotonMapKinds& maps, int requestedBounces)
    : maps_(maps),
      active_(maps.any()),
      bounces_(maps.any() ? (requestedBounces < 0 ? -1 : 1) : requestedBounces) {}

PhotonMode::AmbientReads PhotonMode::activeReads(const PathDepth& p) const {
    AmbientReads r;
    const bool gather = gatherHit(p);
    if (maps_.contrib) {
        r.contribGather = gather;
        r.contribCaustic = !gather && maps_.contribCaustic;
        if (gather) return r;
    }
    if (maps_.global && gather) {
        r.global = true;
        return r;
    }
    r.caustic = maps_.caustic && (p.ambientLevel == 0 || !maps_.global);
    return r;
}

}  // namespace rp::render
