// Photon map construction: header statistics and kd-tree build.
#include "pmap/photon_map.h"

#include <limits>

#include "pmap/incore_store.h"
#include "util/portable_io.h"
#include "util/error.h"

namespace rp::pmap {

using portable::putFlt;
using portable::getFlt;

namespace {
// The value a double becomes after putflt/getflt, so that in-memory == on-disk.
double portableRound(double v) {
    std::string b;
    putFlt(b, v);
    return getFlt(reinterpret_cast<const unsigned char*>(b.data()));
}
}  // namespace

std::string photonMapFormat(PhotonMapType type) {
    return std::string("Radiance_") + photonMapTypeName(type) + "_kdT_Photon_Map";
}

PhotonMapStats computeStats(std::span<const Photon> photons) {
    PhotonMapStats s;
    s.numPhotons = photons.size();
    if (photons.empty()) return s;
    // RADIANCE compat: buildPhotonMap sums flux and positions in double ("reduce summation
    // errors"). It averages the flux before the final RGBE rounding; we only have the
    // rounded flux, so this average can differ from RADIANCE's in the third digit.
    double flux[3] = {0, 0, 0}, cog[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a) {
        s.bboxMin[a] = std::numeric_limits<float>::infinity();
        s.bboxMax[a] = -std::numeric_limits<float>::infinity();
    }
    for (const Photon& p : photons) {
        const auto f = p.fluxRgb();
        for (int a = 0; a < 3; ++a) {
            flux[a] += f[a];
            cog[a] += p.pos[a];
            // (RADIANCE updates max only in an `else` branch after min, which can leave the
            // max short; we record the true bounding box.)
            s.bboxMin[a] = std::min(s.bboxMin[a], p.pos[a]);
            s.bboxMax[a] = std::max(s.bboxMax[a], p.pos[a]);
        }
    }
    const double n = static_cast<double>(photons.size());
    for (int a = 0; a < 3; ++a) {
        s.avgFlux[a] = static_cast<float>(flux[a] / n);
        cog[a] /= n;
    }
    double dist2 = 0;
    for (const Photon& p : photons) {
        const double dx = p.pos[0] - cog[0], dy = p.pos[1] - cog[1], dz = p.pos[2] - cog[2];
        dist2 += dx * dx + dy * dy + dz * dz;
    }
    s.cogDist2 = static_cast<float>(dist2 / n);
    for (int a = 0; a < 3; ++a) s.cog[a] = portableRound(cog[a]);
    return s;
}

PhotonMap::PhotonMap(PhotonMapType type, std::vector<Photon> photons,
                     std::vector<PhotonPrimary> primaries, bool parallel)
    : type_(type), primaries_(std::move(primaries)) {
    RP_CHECK(primaries_.empty() || type == PhotonMapType::Contrib);
    stats_ = computeStats(photons);
    photons_ = buildKdTree(std::move(photons), parallel);
}

void PhotonMap::setPrimaryRays(std::vector<PrimaryRay> rays) {
    RP_CHECK(rays.empty() || rays.size() == primaries_.size());
    primaryRays_ = std::move(rays);
}

const PhotonStore& PhotonMap::store() const {
    RP_CHECK(store_ != nullptr);
    return *store_;
}

PhotonMap PhotonMap::searchableFrom(PhotonMapType type, std::vector<Photon> photons,
                                    bool parallel) {
    PhotonMap map;
    map.type_ = type;
    map.stats_ = computeStats(photons);
    map.store_ = std::make_shared<InCoreStore>(photons, InCoreStore::attributesFor(type),
                                               parallel, /*consume=*/true);
    return map;
}

void PhotonMap::makeSearchable(bool parallel) {
    store_ = std::make_shared<InCoreStore>(
        InCoreStore::copyOf(photons_, InCoreStore::attributesFor(type_), parallel));
}

}  // namespace rp::pmap
