// Photon map construction: header statistics and kd-tree build.
#include "pmap/photon_map.h"

#include <limits>

#include "pmap/incore_store.h"
#include "util/error.h"
#include "util/portable_io.h"

namespace rp::pmap {

using portable::getFlt;
using portable::putFlt;

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

StatsAccumulator::StatsAccumulator() {
    for (int a = 0; a < 3; ++a) {
        s_.bboxMin[a] = std::numeric_limits<float>::infinity();
        s_.bboxMax[a] = -std::numeric_limits<float>::infinity();
    }
}

void StatsAccumulator::addFirst(std::span<const Photon> photons) {
    RP_CHECK(!second_);
    s_.numPhotons += photons.size();
    // RADIANCE compat: buildPhotonMap sums flux and positions in double ("reduce summation
    // errors"). It averages the flux before the final RGBE rounding; we only have the
    // rounded flux, so this average can differ from RADIANCE's in the third digit.
    for (const Photon& p : photons) {
        const auto f = p.fluxRgb();
        for (int a = 0; a < 3; ++a) {
            flux_[a] += f[a];
            cog_[a] += p.pos[a];
            // (RADIANCE updates max only in an `else` branch after min, which can leave the
            // max short; we record the true bounding box.)
            s_.bboxMin[a] = std::min(s_.bboxMin[a], p.pos[a]);
            s_.bboxMax[a] = std::max(s_.bboxMax[a], p.pos[a]);
        }
    }
}

void StatsAccumulator::finishFirst() {
    second_ = true;
    if (s_.numPhotons == 0) return;
    const double n = static_cast<double>(s_.numPhotons);
    for (int a = 0; a < 3; ++a) {
        s_.avgFlux[a] = static_cast<float>(flux_[a] / n);
        cog_[a] /= n;
    }
}

void StatsAccumulator::addSecond(std::span<const Photon> photons) {
    if (!second_) finishFirst();
    for (const Photon& p : photons) {
        const double dx = p.pos[0] - cog_[0], dy = p.pos[1] - cog_[1], dz = p.pos[2] - cog_[2];
        dist2_ += dx * dx + dy * dy + dz * dz;
    }
}

PhotonMapStats StatsAccumulator::stats() const {
    if (s_.numPhotons == 0) return PhotonMapStats{};
    RP_CHECK(second_);
    PhotonMapStats s = s_;
    s.cogDist2 = static_cast<float>(dist2_ / static_cast<double>(s_.numPhotons));
    for (int a = 0; a < 3; ++a) s.cog[a] = portableRound(cog_[a]);
    return s;
}

PhotonMapStats computeStats(std::span<const Photon> photons) {
    StatsAccumulator acc;
    acc.addFirst(photons);
    acc.addSecond(photons);
    return acc.stats();
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
    map.store_ = std::make_shared<InCoreStore>(photons, InCoreStore::attributesFor(type), parallel,
                                               /*consume=*/true);
    return map;
}

void PhotonMap::makeSearchable(bool parallel) {
    store_ = std::make_shared<InCoreStore>(
        InCoreStore::copyOf(photons_, InCoreStore::attributesFor(type_), parallel));
}

}  // namespace rp::pmap
