// Density estimates and the adaptive maximum search radius (see density.h).
#include "pmap/density.h"

#include <algorithm>
#include <cmath>

#include "pmap/edge_estimate.h"
#include "util/error.h"

namespace rp::pmap {

namespace {
// RADIANCE compat: pmapdata.c PMAP_MAXDIST_COEFF, _INC, _DEC, _CNT, PMAP_SHORT_LOOKUP_THRESH.
constexpr double kMaxDistCoeff = 100;
constexpr double kMaxDistInc = 4;
constexpr double kMaxDistDec = 0.9;
constexpr int kMaxDistCount = 1000;
constexpr size_t kShortLookupThreshold = 1;
}  // namespace

PhotonLookup::PhotonLookup(const PhotonMap& map, const LookupParams& params)
    : map_(&map),
      cursor_(map.searchable() ? map.store().makeCursor() : nullptr),
      causticOnly_(params.causticOnly),
      bandwidth_(static_cast<int>(
          std::min<uint64_t>(std::max(params.bandwidth, 1), std::max<uint64_t>(map.size(), 1)))),
      fixedRadius_(params.maxSearchRadius > 0),
      gatherTolerance_(params.gatherTolerance),
      edgeAware_(params.edgeAware) {
    const size_t queueLen = static_cast<size_t>(bandwidth_) + 1;
    hits_.resize(queueLen);
    if (fixedRadius_) {
        maxDist2Limit_ = params.maxSearchRadius * params.maxSearchRadius;
    } else if (!map.empty()) {
        // RADIANCE computes this in float (PhotonMap.maxDist2Limit); so do we.
        maxDist2Limit_ = static_cast<float>(kMaxDistCoeff * static_cast<double>(queueLen) *
                                            map.stats().cogDist2 / static_cast<double>(map.size()));
    }
    // A degenerate map (one point, CoGdist 0) would otherwise never find anything.
    if (!(maxDist2Limit_ > 0)) maxDist2Limit_ = HUGE_VAL;
    maxDist2_ = maxDist2Limit_;
}

std::span<const FoundPhoton> PhotonLookup::findPhotons(const Vec3& pos, const Vec3* normal) {
    return search(pos, normal, static_cast<size_t>(bandwidth_) + 1);
}

// hits_[0] is the furthest, the others in no particular order (PhotonStore::findNearest).
std::span<FoundPhoton> PhotonLookup::search(const Vec3& pos, const Vec3* normal, size_t queueLen) {
    lastSearchDist2_ = static_cast<float>(maxDist2_);
    const PhotonQuery query{pos, normal, causticOnly_, lastSearchDist2_, queueLen};
    found_ = map_->store().findNearest(*cursor_, query, hits_);
    ++lookups_;
    if (found_ == queueLen) lastSearchDist2_ = hits_[0].dist2;

    if (static_cast<double>(found_) < static_cast<double>(queueLen) * gatherTolerance_) {
        // Short lookup. One photon or none is taken to mean there really are no photons
        // nearby, so growing the radius would not help (RADIANCE's threshold).
        if (found_ > kShortLookupThreshold) {
            ++shortLookups_;
            if (!fixedRadius_ && maxDist2_ < maxDist2Limit_) maxDist2_ *= kMaxDistInc;
        }
        goodRun_ = 0;
    } else if (!fixedRadius_) {
        goodRun_ = (goodRun_ + 1) % kMaxDistCount;
        if (goodRun_ == 0) maxDist2_ *= kMaxDistDec;
    }
    return {hits_.data(), found_};
}

std::span<const FoundPhoton> PhotonLookup::searchOwnSurface(const Vec3& pos, const Vec3& normal,
                                                            size_t queueLen, float slab,
                                                            double& d1) {
    PhotonQuery query{pos, &normal, causticOnly_, static_cast<float>(maxDist2_), queueLen};
    query.slab = slab;
    const size_t n = map_->store().findNearest(*cursor_, query, ownHits_);
    d1 = n == queueLen ? ownHits_[0].dist2 : query.maxDist2;
    return {ownHits_.data(), n};
}

double PhotonLookup::estimateRadius2(std::span<const FoundPhoton> hits) const {
    return estimateRadius2(hits, lastSearchDist2_);
}

double PhotonLookup::estimateRadius2(std::span<const FoundPhoton> hits, double d1) const {
    // hits[0] is the furthest (search()); d2 is the second furthest. RADIANCE compat: d1 is
    // pmap->maxDist2 after the search, i.e. the furthest photon when the queue filled up
    // and the search limit otherwise; RADIANCE takes d2 from the heap's children of the
    // furthest, which hold the second furthest. (RADIANCE reads node[2] even when only 2
    // photons were found; we look only at photons that exist.)
    float second = hits[1].dist2;
    for (size_t i = 2; i < hits.size(); ++i) second = std::max(second, hits[i].dist2);
    const double d2 = second;
    return 0.25 * (d1 + d2 + 2 * std::sqrt(d1 * d2));
}

double PhotonLookup::edgeFactor(std::span<const FoundPhoton> hits, size_t queueLen) {
    if (!edgeAware_ || !(lastSearchDist2_ > 0)) return 1;
    // The disc the photons were drawn from: with a full queue the furthest photon's (it
    // only sets the radius; given it, the others are spread over the disc as the density
    // says, which is what the edge model describes), else the search limit's, which then
    // holds every photon found (far outside a caustic, lookups are short).
    const size_t first = hits.size() == queueLen ? 1 : 0;
    edgeU_.clear();
    const double inv = 1.0 / lastSearchDist2_;
    for (size_t i = first; i < hits.size(); ++i)
        edgeU_.push_back(std::min(1.0, hits[i].dist2 * inv));
    return fitEdge(edgeU_, edgeScratch_).factor;
}

// Below this part of the disc covered (one probe in 64, render/surface_coverage.cpp) the
// own-surface estimate is not used.
constexpr double kMinCoverage = 1.0 / 64;
// The query lies on its surface, so a straight edge leaves at least half its first disc
// (less by the probes' resolution); less means a strip narrower than the disc, where the
// own-surface estimate would average across the whole width, and light often varies
// most (one side of a slat lit, the other not): RADIANCE's estimate is kept.
constexpr double kMinDiscCoverage = 0.4;
// Likewise when the search among the surface's own photons had to reach much further than
// the first (half a disc needs twice the squared radius).
constexpr double kMaxOwnReach = 3;

PhotonLookup::Estimate PhotonLookup::estimate(const Vec3& pos, const Vec3& normal,
                                              const DiscCoverage* coverage) {
    const size_t queueLen = static_cast<size_t>(bandwidth_) + 1;
    const std::span<const FoundPhoton> hits = search(pos, &normal, queueLen);
    if (hits.size() < 2) return {hits, 0};
    const double r2 = estimateRadius2(hits);
    if (edgeAware_ && coverage) {
        const float slab = static_cast<float>(kCoverageSlab * std::sqrt(r2));
        const DiscCoverage::Part whole = coverage->part(r2, slab);
        if (whole.fraction < 1 && whole.fraction >= kMinDiscCoverage && whole.straightEdge) {
            // The photons of the query's own surface, over the part of their disc it covers.
            double d1 = 0;
            const auto own = searchOwnSurface(pos, coverage->planeNormal(), queueLen, slab, d1);
            const double ownR2 = own.size() >= 2 ? estimateRadius2(own, d1) : 0;
            if (own.size() >= 2 && ownR2 <= kMaxOwnReach * r2) {
                const DiscCoverage::Part p = coverage->part(ownR2, slab);
                if (p.fraction >= kMinCoverage && p.straightEdge)
                    return {own, gradientFactor(own, queueLen, d1, p.fraction) /
                                     (kPi * kPi * ownR2 * p.fraction)};
            }
        }
    }
    return {hits, edgeFactor(hits, queueLen) / (kPi * kPi * r2)};
}

double PhotonLookup::gradientFactor(std::span<const FoundPhoton> hits, size_t queueLen, double d1,
                                    double covered) {
    // The photons and their disc as edgeFactor takes them.
    const size_t first = hits.size() == queueLen ? 1 : 0;
    edgeU_.clear();
    for (size_t i = first; i < hits.size(); ++i)
        edgeU_.push_back(std::min(1.0, hits[i].dist2 / d1));
    return edgeGradientFactor(edgeU_, edgeOffsetOfFraction(covered), edgeScratch_);
}

std::array<double, 3> PhotonLookup::surfaceDensity(const Vec3& pos, const Vec3& normal,
                                                   const DiscCoverage* coverage) {
    std::array<double, 3> irrad = {0, 0, 0};
    if (map_->empty()) return irrad;
    const Estimate e = estimate(pos, normal, coverage);
    if (!(e.scale > 0)) return irrad;
    // Skip the extra (furthest) photon; uniform kernel. The fluxes are RGBE values (8-bit
    // mantissas), so their sum in double is exact and does not depend on the order of the
    // hits. Divided by the search area pi r^2 and by pi, RADIANCE's ambient normalisation.
    for (size_t i = 1; i < e.hits.size(); ++i) {
        const auto f = e.hits[i].fluxRgb();
        for (int c = 0; c < 3; ++c) irrad[c] += f[c];
    }
    for (double& v : irrad) v *= e.scale;
    return irrad;
}

std::array<double, 3> PhotonLookup::contribDensity(const Vec3& pos, const Vec3& normal,
                                                   const PhotonShares& each,
                                                   const DiscCoverage* coverage) {
    std::array<double, 3> irrad = {0, 0, 0};
    if (map_->empty()) return irrad;
    const Estimate e = estimate(pos, normal, coverage);
    if (!(e.scale > 0)) return irrad;
    const std::span<const FoundPhoton> summed = e.hits.subspan(1);  // the furthest is left out
    for (const FoundPhoton& p : summed) {
        const auto f = p.fluxRgb();
        for (int c = 0; c < 3; ++c) irrad[c] += f[c] * e.scale;
    }
    each(summed, e.scale);
    return irrad;
}

std::array<double, 3> PhotonLookup::volumeDensity(const Vec3& pos, const Vec3& out, double g,
                                                  double (*phase4Pi)(double, double)) {
    std::array<double, 3> sum = {0, 0, 0};
    if (map_->empty()) return sum;
    auto hits = search(pos, nullptr, static_cast<size_t>(bandwidth_) + 1);
    if (hits.size() < 2) return sum;
    const double r2 = estimateRadius2(hits);
    for (size_t i = 1; i < hits.size(); ++i) {
        const FoundPhoton& p = hits[i];
        const Vec3 in = Vec3(p.norm[0], p.norm[1], p.norm[2]) / 127.0;
        const double w = phase4Pi(g, dot(in, out) / std::max(length(in), 1e-9));
        const auto f = p.fluxRgb();
        for (int c = 0; c < 3; ++c) sum[c] += w * f[c];
    }
    const double scale = 3.0 / (16 * kPi * kPi * r2 * std::sqrt(r2));
    for (double& v : sum) v *= scale;
    return sum;
}

std::array<double, 3> PhotonLookup::biasCompensatedDensity(const Vec3& pos, const Vec3& normal,
                                                           int bwMin, int bwMax,
                                                           BiasCompStats* stats) {
    if (map_->empty()) return {0, 0, 0};
    const int upper = static_cast<int>(
        std::min<uint64_t>(std::max(bwMax, 1), static_cast<uint64_t>(map_->size())));
    const size_t queueLen = static_cast<size_t>(upper) + 1;
    if (hits_.size() < queueLen) hits_.resize(queueLen);
    auto hits = search(pos, &normal, queueLen);
    const BiasCompResult r = compensateBias(hits, lastSearchDist2_, hits.size() == queueLen,
                                            std::min(bwMin, upper), upper, biasPrefix_);
    // compensateBias sorted the hits: no longer a heap, so forget them.
    found_ = 0;
    if (stats && r.bandwidth > 0) stats->add(r.bandwidth, r.relError);
    return r.density;
}

const FoundPhoton* PhotonLookup::nearestPhoton(const Vec3& pos, const Vec3& normal,
                                               std::optional<bool> caustic) {
    if (map_->empty()) return nullptr;
    // RADIANCE compat: find1Photon searches within the squared radius CoGdist.
    PhotonQuery query{pos, &normal, caustic.value_or(false), map_->stats().cogDist2, 1};
    query.causticExcluded = caustic.has_value() && !*caustic;
    if (map_->store().findNearest(*cursor_, query, hits_) == 0) return nullptr;
    return &hits_[0];
}

std::array<double, 3> PhotonLookup::precompDensity(const Vec3& pos, const Vec3& normal) {
    const FoundPhoton* p = nearestPhoton(pos, normal);
    if (!p) return {0, 0, 0};
    const auto f = p->fluxRgb();
    return {f[0], f[1], f[2]};
}

}  // namespace rp::pmap
