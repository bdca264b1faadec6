// Internals of Renderer shared by its source files (renderer.cpp: construction and the
// public entry points; shade.cpp: the shading loop; shadow.cpp: shadow rays and
// hemisphere samples). Not for use outside src/render.
#pragma once

#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "material/material.h"
#include "material/material_calc.h"
#include "material/surface_chain.h"
#include "render/ambient.h"
#include "render/clip_set.h"
#include "render/direct.h"
#include "render/photon_lighting.h"
#include "render/photon_mode.h"
#include "render/renderer.h"
#include "util/rng.h"

namespace rp::render {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

// The sources whose light scatters into a ray's medium (RADIANCE's slights), as indices
// into the direct source list.
struct ScatterSources {
    static constexpr int kMax = 32;  // RADIANCE MAXSLIST
    int count = 0;
    std::array<int32_t, kMax> index;
    bool contains(int32_t s) const {
        for (int i = 0; i < count; ++i)
            if (index[size_t(i)] == s) return true;
        return false;
    }
};

// What a ray in a participating medium carries (m_mist.c): its medium, the sources whose
// light scatters into it and the mists it is inside.
struct MediaState {
    material::Medium medium;
    ScatterSources scatter;
    material::MistSet mists;
};

// Why a bound on transmissions at all: they keep the ray's level, so with -lw 0 nothing
// else would stop a ray between two facing prisms. 256 panes is past any building.
constexpr int kMaxTransits = 256;

// RADIANCE's ray type bits that matter for over-counting (badcomponent): a ray that
// descends from an ambient sample or a sampled (rough) specular ray must not see the
// emission of surfaces the direct calculation already counts.
struct RayState {
    int depth = 0;               // reflections so far (RADIANCE rlvl)
    int generation = 0;          // rays it descends from (RADIANCE's ray-tree indentation)
    double weight = 1;           // estimated contribution to the result (rweight)
    int ambientLevel = 0;        // ambient bounces so far
    bool indirect = false;       // descended from an ambient or sampled specular ray
    bool primary = true;         // the input ray itself
    bool irradianceHit = false;  // -i: shade the first surface as white Lambertian
    ClipSet clip;                // what antimatter hides from the ray (RADIANCE clipset)
    // What it travels in; null: the global medium (-me -ma -mg), in no mist. Points to
    // the storage of whoever changed it, which outlives the ray (rays are traced depth
    // first), so that rays outside media copy no more than a pointer.
    const MediaState* media = nullptr;
    // rcontrib (ContributionSink): where contributions go, null when nobody asks, and
    // the ray's path coefficient (RADIANCE raycontrib: the product of its ancestors'
    // rcoef). Participating media are not part of it, as in RADIANCE.
    ContributionSink* contrib = nullptr;
    Color contribCoef{1, 1, 1};
    // Surfaces passed straight through since the last reflection: they do not count
    // towards -lr, so this bounds a chain of them instead (kMaxTransits).
    int transits = 0;
    PathDepth pathDepth() const { return {ambientLevel, depth}; }
};

// One material record, checked once. `error` holds the message for a record that cannot
// be used (not supported yet, bad values): thrown when a ray first meets it, as RADIANCE
// reports problems with materials when they are used.
struct Renderer::Impl {
    Impl(const Scene& scene, const SceneGeometry& geometry, const RenderOptions& options,
         std::vector<std::string> searchPath);

    const Scene& scene;
    const SceneGeometry& geometry;
    const RenderOptions& options;
    material::SurfaceChains chains;
    material::MaterialCalc materialCalc;  // .cal functions of function-driven materials
    // rcontrib: per light source (light::findLightSources), whether -m tracks its
    // material; empty otherwise.
    std::vector<bool> trackedSources;
    PhotonLighting photons;         // -ap maps (inactive without)
    PhotonMode photonMode;          // RADIANCE's photon-map mode rules for these maps
    AmbientOptions ambientOptions;  // -a options as used (photon mode adjusts -ab)
    DirectLighting direct;
    Ambient ambient;
    material::ShadeOptions shadeOptions;
    uint64_t seed = 0;  // base of every ray's random stream
    mutable std::atomic<long> rays{0};

    // The material record (chains.materials()); throws for unusable records.
    const material::MaterialRecord& material(int32_t index) const {
        return chains.materials().at(index);
    }

    AntimatterTable antimatter;     // what each antimatter clips (clip_set.h)
    material::Medium globalMedium;  // -me -ma -mg
    // Per mist material: its string arguments as direct source indices (m_mist.c).
    std::unordered_map<int32_t, std::vector<int32_t>> mistSources;
    bool hasMists = false;  // primary rays then probe for the mists around their origin
    // By material index: whether its hits need material::prepareHit (needsPreparation,
    // decided once: most materials need nothing and are shaded on every hit).
    std::vector<bool> prepares;
};

class Renderer::Context : public ShadowOracle {
public:
    Context(const Renderer& renderer, const Impl& impl);

    // ShadowOracle
    std::optional<Hit> closestHit(const Ray& ray) override;
    ShadowEvent event(const Hit& hit, const Vec3& dir, ShadowPath& path,
                      bool passIllum = false) override;
    Color distantRadiance(int32_t source, const Vec3& dir) override;
    material::Redirection redirect(const Hit& hit, const Vec3& dir, int projection,
                                   const Vec3& toSource) override;
    ShadowTree shadowTree() const override;
    void reportShadowRay(const DirectPoint& at, std::span<const ShadowPiece> pieces) override;

    // An ambient hemisphere sample of the ray in `parent` (HemisphereTracer::trace): it
    // starts with the parent's depth, clip set and medium.
    HemisphereTracer::Sample traceSample(const RayState& parent, const Vec3& origin,
                                         const Vec3& dir, int ambientLevel, double weight,
                                         double share);

    // Radiance arriving at ray.origin from ray.dir. `first` (may be null) receives what
    // the first surface hit was; `distance` the distance to it (1e10 if none).
    // `hitNormal` (optional) receives the geometric normal where the ray ended.
    Color radiance(const Ray& ray, const RayState& state, RayResult* first, double& distance,
                   Vec3* hitNormal = nullptr);

    // Irradiance at a point on a white Lambertian surface facing `normal`, for a ray in
    // `state` (its ambient level, weight, clip set, medium and contribution path).
    Color irradianceAt(const Hit& hit, const Vec3& normal, const RayState& state);

    // The media of a ray starting at `p`: the mists enclosing it (material/mist_probe.h),
    // entered outermost first; nullopt in a scene without mists or outside every mist.
    std::optional<MediaState> mediaAt(const Vec3& p);

    // What each shadow ray from a point reached by a ray in `state` starts with.
    ShadowPath shadowStart(const RayState& state) const;

    const Renderer& renderer;
    const Impl& impl;
    // Pattern chains and material functions, for every hit this thread shades, lights or
    // passes a shadow ray through (material::prepareHit).
    material::HitEvaluators evaluators;
    DirectScratch directScratch;  // the direct calculation's working memory
    Rng rng{0, RngDomain::Sampling, 0};
    std::vector<TracedRay>* tree = nullptr;
    int treeDepth = 0;
    std::unique_ptr<PhotonLighting::Lookups> photonLookups;  // null without photon maps

private:
    // A layer that passes the ray on may change its medium (a mist boundary): `crossing`,
    // with the mist's material index in `crossingMist`.
    struct Passage {
        material::MediumChange crossing;
        int32_t mist = -1;
        const material::MistParams* mistParams = nullptr;
        // A light seen where the direct calculation counts it (RADIANCE zeroes the ray's
        // coefficient): not a contribution.
        bool uncounted = false;
    };
    Color shadeHit(const Ray& ray, const Hit& hit, const RayState& state, RayResult* first,
                   Color& passWeight, Passage& passage);
    Color shadeLayer(const Ray& ray, const Hit& hit, const RayState& state,
                     const material::ShadingLayer& layer, RayResult* first, bool& passThrough,
                     Passage& passage);
    // shadeLayer's phases: a light material; the ideal and sampled specular rays of `b`;
    // direct light for a material that takes it.
    Color shadeLight(const Ray& ray, const Hit& hit, const RayState& state,
                     const material::ShadingLayer& layer, const material::MaterialRecord& e,
                     const material::SurfacePoint& sp, RayResult* first, bool& passThrough,
                     Passage& passage);
    void addSpecularRays(const Hit& hit, const RayState& state, const material::BackwardResult& b,
                         RayResult* first, Color& value);
    void addDirect(const Hit& hit, const material::MaterialParams& params,
                   const material::SurfacePoint& sp, const material::BackwardResult& b,
                   const RayState& state, Color& value);
    // Shades with a mirror's or illum's alternate material (its whole modifier chain).
    Color shadeAlternate(const Ray& ray, const Hit& hit, const RayState& state, int32_t alternate,
                         RayResult* first, bool& passThrough, Passage& passage);
    // The medium along a ray segment of length `t` (HUGE_VAL: the ray left the scene):
    // returns the light scattered into the ray and sets `transmit` to the segment's
    // transmittance (RADIANCE rayparticipate, srcscatter).
    Color participate(const Ray& ray, double t, const RayState& state, Color& transmit);
    Color sourceScatter(const Ray& ray, double t, const RayState& state);
    Color volumeScatter(const Ray& ray, double t, const RayState& state);
    // The media after `passage` (m_mist.c); `segment` receives those of the segment
    // before it (a ray leaving a mist it did not know it was in was in it).
    void cross(MediaState& media, const Passage& passage, MediaState& segment) const;
    // Adds the sources mist material `mist` names (m_mist.c add2slist).
    void addSources(ScatterSources& to, int32_t mist) const;
    const material::Medium& mediumOf(const RayState& s) const {
        return s.media ? s.media->medium : impl.globalMedium;
    }
    MediaState mediaOf(const RayState& s) const {
        return s.media ? *s.media : MediaState{impl.globalMedium, {}, {}};
    }
    // `record` (may be null): filled with the source the ray leaves through, unless it
    // already holds a surface.
    Color escaped(const Ray& ray, const RayState& state, RayResult* record);
    // Direct light at `hit`; `behindOnly`: only sources behind the surface (the far point
    // of a thick BSDF, whose reflected light is taken at the hit itself).
    Color directAt(const Hit& hit, const material::MaterialParams& params,
                   const material::SurfacePoint& sp, bool transmits, const RayState& state,
                   bool behindOnly = false);
    // The ambient term at `hit`, which the caller multiplies by `coef` (the material's
    // ambient coefficient; for contributions).
    Color ambientAt(const Hit& hit, const Vec3& normal, int32_t modifier, const RayState& state,
                    const Color& coef);
    material::ChainResult resolve(int32_t modifier, const Hit& hit, const Vec3& dir);
    // Radiance of a light material reached through `modifier` (patterns applied) seen
    // along `dir`; `isGlow`/`isLight` say what it was (both false: not a light).
    Color sourceRadiance(int32_t modifier, const Hit& at, const Vec3& dir, bool& isGlow,
                         bool& isLight);
    ShadowEvent chainEvent(const material::ChainResult& chain, const Hit& hit, const Vec3& dir,
                           bool passIllum);
    ShadowEvent layerEvent(const Hit& hit, const Vec3& dir, const material::ShadingLayer& l,
                           bool passIllum);

    // The shading point of `layer` at `hit` for a ray travelling `dir` (RADIANCE
    // raynormal: the perturbed normal turned to the ray), not yet prepared.
    material::SurfacePoint surfaceAt(const Hit& hit, const Vec3& dir,
                                     const material::ShadingLayer& layer) const {
        const Vec3 ng = hit.front ? hit.normal : -hit.normal;
        material::SurfacePoint sp = material::makeSurfacePoint(dir, ng, hit.front, layer.pattern);
        if (lengthSquared(layer.perturbation) > 0)
            material::perturbSurface(sp, hit.normal, layer.perturbation);
        sp.distance = hit.t;
        return sp;
    }
    // material::prepareHit for `material` at the hit: what its functions, component
    // modifiers or redirections give, into sp (pointing into `scratch`, made only where
    // needed: most hits have nothing to prepare, and the scratch is large).
    void prepare(int32_t material, const material::MaterialParams& params, const Hit& hit,
                 const Vec3& dir, material::SurfacePoint& sp,
                 std::optional<material::HitScratch>& scratch) {
        if (impl.prepares[size_t(material)]) prepareHit(material, params, hit, dir, sp, scratch);
    }
    void prepareHit(int32_t material, const material::MaterialParams& params, const Hit& hit,
                    const Vec3& dir, material::SurfacePoint& sp,
                    std::optional<material::HitScratch>& scratch);
};

// m_direct.c: redirection `projection` of the prism1/prism2 material of the surface at
// `hit` for a ray travelling `dir`, DxA DyA DzA along `toSource` (zero: none), evaluated
// with `ev` (an evaluator of `calc`). Not ok if the surface's material is no prism.
material::Redirection evalRedirect(const material::MaterialTable& materials,
                                   const material::MaterialCalc& calc,
                                   material::MaterialCalcEvaluator& ev, const Hit& hit,
                                   const Vec3& dir, int projection, const Vec3& toSource);

}  // namespace rp::render
