// Photon density estimates as RADIANCE computes them (pmutil.c photonDensity,
// photonPreCompDensity) and the automatic maximum search radius of findPhotons
// (pmapdata.c; manual section 3.2.3), and the bias-compensated estimate (-ap file min max;
// the bandwidth choice itself is in bias_comp.h). Photons come from the map's store
// (photon_store.h), whichever it is. The edge correction of -ape (radphoton's own) is
// modelled in edge_estimate.h.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "pmap/bias_comp.h"
#include "pmap/photon_map.h"
#include "pmap/photon_store.h"
#include "util/vec.h"

namespace rp::pmap {

struct LookupParams {
    int bandwidth = 40;  // photons per density estimate (-ap file bwidth; RADIANCE default 40)
    double maxSearchRadius = 0;    // -am: fixed maximum search radius (not squared); 0 = automatic
    double gatherTolerance = 0.5;  // short lookup: found < tolerance x queue length (contrib: 1)
    bool causticOnly = false;  // only caustic photons (a contribution map's, at non-ambient hits)
    // -ape: surfaceDensity and contribDensity corrected for a straight light/shadow edge
    // through the search disc (edge_estimate.h); off: RADIANCE's estimates.
    bool edgeAware = false;
};

// The part of a surface density estimate's search disc where photons can be (-ape): the
// caller measures it from the scene's geometry (render/surface_coverage.h); pmap only asks.
class DiscCoverage {
public:
    struct Part {
        // Fraction in [0, 1] of the disc under which a surface that holds photons lies
        // within the slab of the plane.
        double fraction = 1;
        // Whether that part is the disc cut by one straight edge (the model of
        // edgeGradientFactor); not for a strip narrower than the disc or a corner.
        bool straightEdge = true;
    };
    // The part of the disc of squared radius `radius2` around the query, in its tangent
    // plane, where photons can be within `slab` of the plane.
    virtual Part part(double radius2, double slab) const = 0;
    // The tangent plane's unit normal, on the side the light comes from (the surface's
    // geometric normal: a shading normal's tilt would move the plane off the photons).
    virtual const Vec3& planeNormal() const = 0;

protected:
    ~DiscCoverage() = default;
};

// -ape's estimate over the query's own surface: photons within this fraction of the first
// search's radius of the tangent plane (neighbouring slats or shelves are further).
constexpr double kCoverageSlab = 0.1;

// Per-thread lookup state for one photon map: the result buffer (k+1 entries, allocated once)
// and the adaptive search radius, which RADIANCE keeps in the shared PhotonMap. Keeping it
// per thread makes every thread's results independent of the others. Not thread-safe: give
// each thread its own PhotonLookup (e.g. tbb::enumerable_thread_specific).
class PhotonLookup {
public:
    // The map must be searchable (PhotonMap::store) and outlive this object. Bandwidths
    // above the photon count are clamped to it (RADIANCE compat: loadPmaps "adjusting
    // density estimate bandwidth").
    PhotonLookup(const PhotonMap& map, const LookupParams& params);

    // RADIANCE's findPhotons: up to bandwidth+1 nearest photons to `pos` (normal filter if
    // `normal` is non-null; null for volume photons) within the current maximum radius,
    // then the adaptive update:
    //  - initial and limiting squared radius = 100 x (bandwidth+1) x CoGdist / numPhotons,
    //    or maxSearchRadius^2 when fixed (then never adapted);
    //  - short lookup (1 < found < gatherTolerance x (bandwidth+1)): squared radius x4 if
    //    below the limit (RADIANCE compat: it may then overshoot the limit by up to x4, as in
    //    pmapdata.c; the redo of PMAP_LOOKUP_REDO is not done) and the run of good lookups
    //    restarts; every 1000 consecutive good lookups: squared radius x0.9.
    // Returns the hits, the furthest first (the others in no particular order); valid
    // until the next call.
    std::span<const FoundPhoton> findPhotons(const Vec3& pos, const Vec3* normal);

    // RADIANCE's photonDensity (surface maps without bias compensation). Returns
    //   sum(flux of the k nearest) / (pi * pi r^2)
    // per RGB channel, i.e. irradiance E / pi, the value RADIANCE's ambient calculation
    // uses (multiply by pi for irradiance in W/m^2). k+1 photons are gathered; the furthest
    // is left out of the sum and r^2 = ((r_furthest + r_second)/2)^2 evaluated as
    // 0.25 (d1 + d2 + 2 sqrt(d1 d2)) with d1 = squared distance of the furthest (or the
    // search limit when fewer than k+1 were found, as RADIANCE's maxDist2) and d2 the
    // largest of the others. Fewer than 2 photons give 0.
    // With LookupParams::edgeAware and a `coverage`, the estimate first asks whether the
    // disc reaches past one straight edge of the surface (a window's or a slat's edge),
    // where RADIANCE's divides by area with no photons and reads low. Then the search is
    // repeated among photons within kCoverageSlab of the first radius of the tangent
    // plane only (not those of parallel surfaces nearby), and the sum divided by the part
    // of that disc the surface covers instead of all of it, corrected for light varying
    // across the edge (edgeGradientFactor). Elsewhere the result is multiplied by the
    // light/shadow edge factor of the photons (fitEdge with u = d / d1, d each photon's
    // squared distance; all of them for a short lookup, else all but the furthest); where
    // neither applies it is RADIANCE's, bit for bit.
    std::array<double, 3> surfaceDensity(const Vec3& pos, const Vec3& normal,
                                         const DiscCoverage* coverage = nullptr);

    // RADIANCE's photonContrib (pmcontrib2.c) for contribution maps: surfaceDensity, with
    // the photons it sums handed to `each` once, with `scale`: each photon's share of the
    // estimate is its flux times scale (1 / (pi * pi r^2); with edgeAware, corrected as
    // surfaceDensity corrects the sum). Their primaries say which source emitted them.
    // All at once, so that the caller can fetch what it looks up per photon together.
    using PhotonShares = std::function<void(std::span<const FoundPhoton> photons, double scale)>;
    std::array<double, 3> contribDensity(const Vec3& pos, const Vec3& normal,
                                         const PhotonShares& each,
                                         const DiscCoverage* coverage = nullptr);

    // RADIANCE's volumePhotonDensity: for the bandwidth nearest volume photons to `pos`
    // (no normal filter; radius as surfaceDensity's),
    //   sum(flux x 4 pi HG(g, dot(incident direction, out))) / (4 pi x 4/3 pi r^3)
    // per RGB channel: the flux scattered toward unit `out` per unit volume and solid
    // angle, over the extinction (photons are stored at collisions, whose density is
    // extinction times fluence). Times the albedo it is the radiance scattered into a ray
    // per unit length (render/medium.cpp). `phase4Pi(g, cosTheta)` is the phase function
    // times 4 pi (util/henyey_greenstein.h).
    std::array<double, 3> volumeDensity(const Vec3& pos, const Vec3& out, double g,
                                        double (*phase4Pi)(double, double));

    // RADIANCE's photonPreCompDensity: the flux of the single nearest photon with a similar
    // normal within squared radius CoGdist (precomputed maps store irradiance / pi there);
    // 0 if none.
    std::array<double, 3> precompDensity(const Vec3& pos, const Vec3& normal);
    // That photon (precomputed maps), or null; valid until the next call. `caustic`: of
    // the photons with the caustic flag, or (false) of those without (precomputed
    // contribution maps, whose flag marks caustic estimates); unset: any.
    const FoundPhoton* nearestPhoton(const Vec3& pos, const Vec3& normal,
                                     std::optional<bool> caustic = std::nullopt);

    // Bias-compensated surfaceDensity (-ap file bwMin bwMax): gathers up to bwMax+1 photons
    // (findPhotons' search and adaptive radius, with a queue of bwMax+1) and returns E/pi at
    // the bandwidth in [bwMin, bwMax] chosen as documented in bias_comp.h (bwMax is clamped
    // to the photon count, bwMin to bwMax). RADIANCE compat: RADIANCE sizes the automatic
    // radius for the upper bandwidth, so construct this lookup with bandwidth = bwMax.
    // The result depends only on the photons found; with a fixed maximum radius (-am), or
    // while the adaptive radius does not cut the search short, it is independent of query
    // order and threads. Adds the lookup to `stats` when non-null.
    std::array<double, 3> biasCompensatedDensity(const Vec3& pos, const Vec3& normal, int bwMin,
                                                 int bwMax, BiasCompStats* stats = nullptr);

    // Starts the adaptive radius afresh (the limit, no run of good lookups), as for a new
    // lookup object. RADIANCE keeps this state for a whole run, so its results depend on
    // the order of all lookups before; the renderer restarts it with every primary ray
    // (render/renderer.cpp), so that each ray's result depends only on that ray, whatever
    // the number of threads and whichever thread traced it.
    void restartAdaptiveRadius() {
        maxDist2_ = maxDist2Limit_;
        goodRun_ = 0;
    }

    // Current squared maximum search radius (RADIANCE's maxDist0) and its limit.
    double maxDist2() const { return maxDist2_; }
    double maxDist2Limit() const { return maxDist2Limit_; }
    int bandwidth() const { return bandwidth_; }
    // Counters for the end-of-run warning: tools add shortLookups() of every thread to a
    // WarningCounter ("short photon lookups") and report it once.
    uint64_t lookups() const { return lookups_; }
    uint64_t shortLookups() const { return shortLookups_; }

private:
    // The photons of a surface estimate (the furthest first, left out of the sum) and
    // what their flux sum is multiplied by: 1 / (pi^2 r^2), times -ape's corrections.
    struct Estimate {
        std::span<const FoundPhoton> hits;
        double scale = 0;  // 0: fewer than 2 photons
    };
    Estimate estimate(const Vec3& pos, const Vec3& normal, const DiscCoverage* coverage);
    // RADIANCE's squared estimate radius for `hits` (>= 2, the furthest first): the mean
    // of the radii of the furthest (the search limit if the queue did not fill) and the
    // second furthest, squared.
    double estimateRadius2(std::span<const FoundPhoton> hits) const;
    double estimateRadius2(std::span<const FoundPhoton> hits, double d1) const;
    // The edge factor for `hits` from search() with a queue of queueLen (edge_estimate.h),
    // 1 without edgeAware: the k photons in the disc of squared radius d1 (the furthest
    // photon's or, for a short lookup, the search limit's).
    double edgeFactor(std::span<const FoundPhoton> hits, size_t queueLen);
    // For the own-surface estimate over the `covered` part of its disc (squared radius
    // d1): the density at the query over the part's mean (edgeGradientFactor).
    double gradientFactor(std::span<const FoundPhoton> hits, size_t queueLen, double d1,
                          double covered);
    // findPhotons with a queue of queueLen.
    std::span<FoundPhoton> search(const Vec3& pos, const Vec3* normal, size_t queueLen);
    // The photons within `slab` of the tangent plane (PhotonQuery::slab), in a buffer of
    // their own, so that search()'s stay valid; the adaptive radius is left alone. `d1`:
    // the furthest's squared distance, or the limit's if fewer than queueLen were found.
    std::span<const FoundPhoton> searchOwnSurface(const Vec3& pos, const Vec3& normal,
                                                  size_t queueLen, float slab, double& d1);

    const PhotonMap* map_;
    std::unique_ptr<PhotonStore::Cursor> cursor_;
    bool causticOnly_;
    int bandwidth_;
    bool fixedRadius_;
    double gatherTolerance_;
    double maxDist2_ = 0;
    double maxDist2Limit_ = 0;
    float lastSearchDist2_ = 0;  // RADIANCE's pmap->maxDist2 after the search
    int goodRun_ = 0;
    uint64_t lookups_ = 0;
    uint64_t shortLookups_ = 0;
    std::vector<FoundPhoton> hits_;
    size_t found_ = 0;
    std::vector<FoundPhoton> ownHits_;               // searchOwnSurface's
    std::vector<std::array<double, 3>> biasPrefix_;  // scratch for compensateBias
    bool edgeAware_;
    std::vector<double> edgeU_, edgeScratch_;  // scratch for edgeFactor
};

}  // namespace rp::pmap
