// Photon maps in the backward pass (photon-map manual 3.2, 5; RADIANCE pmapray.c,
// pmapamb.c): the maps given with -ap, loaded and checked once (type from the file,
// default bandwidth with a warning, stale check against the scene's input files), and
// the density estimates the shading loop asks for: global irradiance (final gather's
// sample hits, or every hit with -ab -1), caustic irradiance at hits of non-ambient
// rays, direct photons in place of the direct calculation (a debugging aid), and
// light scattered in participating media from volume photons.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "pmap/bias_comp.h"
#include "pmap/contrib_coeffs.h"
#include "pmap/density.h"
#include "pmap/photon_map.h"
#include "pmap/photon_store.h"
#include "render/photon_mode.h"
#include "render/render_options.h"
#include "render/renderer.h"
#include "scene/primitive.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::render {

// RADIANCE compat: -ap without a bandwidth uses 40 photons and warns (pmapparm.c).
constexpr int kDefaultBandwidth = 40;

class PhotonLighting {
public:
    // Loads each -ap map. Throws InputError for a missing, foreign or truncated file,
    // two maps of one type, a bandwidth range with bw2 <= bw1 or any range for a volume
    // map (RADIANCE has no bias compensation for them), and a map older than any of the
    // scene's input files ("stale": rerun mkpmap). Contribution maps are rcontrib's
    // (`trackedSources` non-null): there every other type is refused, elsewhere they
    // are; a contribution map's photons from sources not marked in `trackedSources`
    // (light::findLightSources order) are left out, as RADIANCE's lookups skip them. An
    // empty `uses` gives an inactive set. `store` sizes the maps' stores (-ac, -aC, -n;
    // its bandwidth is set per map).
    // A precomputed contribution map (mkpmap -apC with -m) is rcontrib's too: each of
    // `trackedModifiers` needs its coefficient file beside the map (pmap/contrib_coeffs.h).
    PhotonLighting(const std::vector<PhotonMapUse>& uses, double maxSearchRadius,
                   const Scene& scene, const std::vector<bool>* trackedSources = nullptr,
                   const pmap::StoreOptions& store = {},
                   const std::vector<std::string>& trackedModifiers = {});
    ~PhotonLighting();

    bool active() const { return !maps_.empty(); }
    bool hasGlobal() const { return global_ >= 0; }  // global or precomputed global
    bool hasCaustic() const { return caustic_ >= 0; }
    bool hasDirect() const { return direct_ >= 0; }
    bool hasVolume() const { return volume_ >= 0; }
    bool hasContrib() const { return contrib_ >= 0; }
    // Caustic photons at the hits of non-ambient rays: a caustic map's, or those of a
    // contribution map that arrived through specular surfaces (RADIANCE ambPmapCaustic).
    bool hasCausticLight() const { return caustic_ >= 0 || contribCaustic_; }
    // Which kinds are loaded (PhotonMode's input).
    PhotonMapKinds kinds() const {
        return {hasGlobal(), hasCaustic(), hasDirect(), hasVolume(), hasContrib(), contribCaustic_};
    }

    // Per-thread lookup state (adaptive radius, result buffers); adds its lookup counts
    // to the owner's when destroyed.
    class Lookups {
    public:
        explicit Lookups(const PhotonLighting& owner);
        ~Lookups();
        std::vector<pmap::PhotonLookup> lookups;  // one per map, in maps_ order
        // The contribution map's caustic photons, with their own adaptive radius.
        std::optional<pmap::PhotonLookup> contribCaustic;
        std::vector<pmap::BiasCompStats> biasStats;  // one per map
        // A precomputed contribution map's decoded bins.
        std::vector<pmap::Rgb> bins;
        std::vector<Color> binValues;
        pmap::CoeffCodec::Scratch scratch;
        // Called at the start of every primary ray (PhotonLookup::restartAdaptiveRadius).
        void startRay() {
            for (pmap::PhotonLookup& l : lookups) l.restartAdaptiveRadius();
            if (contribCaustic) contribCaustic->restartAdaptiveRadius();
        }

    private:
        const PhotonLighting& owner_;
    };
    std::unique_ptr<Lookups> makeLookups() const;

    // Irradiance / pi at a surface point with unit normal `normal` (on the side the
    // light comes from), from the global (or precomputed) map, the caustic map and the
    // direct map; zero without such a map.
    // `coverage` (render/surface_probes.h) serves maps used with -ape.
    Color globalDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                        const pmap::DiscCoverage* coverage = nullptr) const;
    Color causticDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                         const pmap::DiscCoverage* coverage = nullptr) const;
    Color directDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                        const pmap::DiscCoverage* coverage = nullptr) const;
    // The contribution map's irradiance / pi at a final-gather hit, as the global map's
    // (or with `caustic`, of its caustic photons only, at other hits, as a caustic map's);
    // each photon's share of it, times the path coefficient `coef`, goes to `sink` with
    // the source that emitted it (RADIANCE photonContrib). A precomputed contribution map
    // gives the bins of its nearest precomputed photon (caustic-flagged with `caustic`,
    // unflagged otherwise) to `sink` instead. Zero without a contribution map.
    Color contribDensity(Lookups& l, const Vec3& pos, const Vec3& normal, const Color& coef,
                         ContributionSink* sink, bool caustic = false,
                         const pmap::DiscCoverage* coverage = nullptr) const;
    // The coefficient files of a precomputed contribution map, one per tracked modifier
    // (empty otherwise).
    std::vector<pmap::CoeffInfo> precomputedModifiers() const;
    // The contribution map (for the source list its primaries index); null without one.
    const pmap::PhotonMap* contribMap() const {
        return contrib_ >= 0 ? &maps_[size_t(contrib_)].map : nullptr;
    }
    // From the volume map at `pos`: light scattered toward unit `out` per unit length of
    // a ray, over the medium's albedo, with eccentricity `g` (pmap::PhotonLookup::
    // volumeDensity); zero without a volume map.
    Color volumeDensity(Lookups& l, const Vec3& pos, const Vec3& out, double g) const;

    // Lookups that found too few photons, summed over threads (reported once by tools).
    uint64_t shortLookups() const { return shortLookups_.load(); }
    uint64_t lookups() const { return lookups_.load(); }
    // Bias compensation statistics of the finished threads' lookups, as manual 5.3's
    // progress line ("50/500/321.4 caustic, (0.045/0.141/0.067 error)"); "" if none.
    std::string biasReport() const;

private:
    struct Map {
        pmap::PhotonMap map;
        PhotonMapUse use;
        std::string file;
    };
    Color density(Lookups& l, int index, const Vec3& pos, const Vec3& normal,
                  const pmap::DiscCoverage* coverage) const;
    Color precomputedContrib(Lookups& l, const Vec3& pos, const Vec3& normal, const Color& coef,
                             ContributionSink* sink, bool caustic) const;
    void openCoefficients(const Scene& scene, const std::vector<std::string>& modifiers);
    pmap::LookupParams lookupParams(const Map& m) const;

    std::vector<Map> maps_;
    double maxSearchRadius_ = 0;
    int global_ = -1, caustic_ = -1, direct_ = -1, volume_ = -1, contrib_ = -1;
    struct Coefficients {
        pmap::CoeffFile file;
        int32_t modifier = -1;  // a scene record of the modifier's name
    };
    std::vector<Coefficients> coefficients_;  // a precomputed contribution map's
    // Whether the contribution map holds caustic photons (searched with the caustic
    // filter, as RADIANCE's ambPmapCaustic does).
    bool contribCaustic_ = false;
    mutable std::atomic<uint64_t> shortLookups_{0}, lookups_{0};
    mutable std::mutex statsMutex_;
    mutable std::vector<pmap::BiasCompStats> biasStats_;  // per map, merged from threads
};

}  // namespace rp::render
