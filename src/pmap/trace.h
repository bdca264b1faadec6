// The photon tracer of mkpmap's forward pass: follows one emitted photon through the
// scene (iterative loop, RADIANCE pmap.c tracePhoton + pmapmat.c) and deposits it by
// the storage rules of each map type (manual 3, 3.2.4-3.2.5). Emission is light/
// emitter.h; how many photons to trace and flux normalisation are distribute.h.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/emitter.h"
#include "material/material.h"
#include "material/material_calc.h"
#include "material/mist_probe.h"
#include "material/surface_chain.h"
#include "pmap/mkpmap_options.h"
#include "pmap/photon.h"
#include "scene/primitive.h"

namespace rp::pmap {

// A deposited photon before flux normalisation (32 bytes): `flux` is the emitted
// weight times the path's scatter factors, i.e. still to be divided by the number of
// photons emitted and the map's storage probability. `u` is the photon's storage draw,
// kept so that prepass photons can be thinned after the fact (distribute.h).
struct RawPhoton {
    float pos[3];
    int8_t norm[3];
    uint8_t caustic;
    float flux[3];
    float u;
};
static_assert(sizeof(RawPhoton) == 32);

struct TraceSettings {
    // Which map types collect photons. PreComp collects global photons (precomp.h);
    // contribution maps are distributed by contrib.h through the Global slot.
    std::array<bool, kNumPhotonMapTypes> maps{};
    bool backVisible = true;             // -bv
    long maxBounce = 5000;               // -lr / -apm
    double maxDistance = 0;              // -ld, 0 = unlimited
    std::vector<RegionOfInterest> rois;  // -api
    std::vector<std::string> sensors;    // -aps / -apS modifier names
    std::vector<std::string> include;    // -ai: store only on these modifiers
    std::vector<std::string> exclude;    // -ae: never store on these modifiers
    material::Medium medium;             // -me -ma -mg: the global medium photons start in
};

// Photons deposited by a range of traced photons, one list per map type.
struct PhotonBins {
    std::array<std::vector<RawPhoton>, kNumPhotonMapTypes> maps;
    long runaways = 0;  // paths cut at the bounce limit
};

class PhotonTracer {
public:
    // Resolves materials, sensors and include/exclude sets once. Throws InputError for
    // a sensor modifier that is not antimatter, sensors that match nothing, and argument
    // errors of the materials plain chains reach (those reached only through a mixture
    // are reported when a photon reaches them).
    // `chains`: the surfaces' compiled modifier chains and their materials, the same
    // ones backward shading and emission use, evaluated at photon hits. `materialCalc`
    // (may be null when the scene has no function-driven materials) evaluates BRTDfunc's
    // specular colour expressions, as pmapmat.c brdfPhotonScatter does. Both must
    // outlive the tracer.
    PhotonTracer(const Scene& scene, const SceneGeometry& geometry, const light::EmissionPlan& plan,
                 TraceSettings settings, const material::SurfaceChains& chains,
                 const material::MaterialCalc* materialCalc = nullptr);

    // What trace() reuses from photon to photon on one thread: the evaluators of the
    // scene's functions (patterns, textures, function-driven materials), whose calc
    // machines cost more to set up than most photons' whole paths, and the record of the
    // hit at hand, which a path sets afresh at each hit (setSurfaceHit, then
    // resetPreparedInputs) and which cost as much to construct per photon as an open
    // scene's photons take to trace. One per thread; the results do not depend on which
    // photons a workspace traced before.
    class Workspace {
    public:
        explicit Workspace(const PhotonTracer& tracer)
            : evals_(tracer.materialCalc_, tracer.chains_) {}

    private:
        friend class PhotonTracer;
        material::HitEvaluators evals_;
        material::SurfacePoint sp_;
        material::HitScratch scratch_;  // what prepareHit gives, for the hit at hand
    };

    // Emits photon `index` of the run keyed by `seed` and traces it. A deposit for map
    // type t is kept when its storage draw u < storeProbability[t]. Thread-safe with one
    // workspace per thread.
    using StoreProbabilities = std::array<double, kNumPhotonMapTypes>;
    void trace(Workspace& workspace, uint64_t seed, uint64_t index,
               const StoreProbabilities& storeProbability, PhotonBins& out) const;

    const TraceSettings& settings() const { return settings_; }
    const light::EmissionPlan& plan() const { return plan_; }

private:
    // What the tracer needs to know about a surface's modifier, computed once; the
    // materials themselves are the chains' (chains_.materials()).
    struct SurfaceModifier {
        bool resolved = false;
        bool plain = true;         // no pattern, texture or mixture on the chain
        int32_t material = kVoid;  // the material reached (RADIANCE findmaterial; for a
                                   // chain with a mixture: the mixture, for port tests)
        bool storeAllowed = true;  // include/exclude sets
    };
    // What this run's settings make of a material: a photon sensor (-aps), one whose hits
    // are prepared (material::needsPreparation: functions, WGMDfunc components).
    enum MaterialRole : uint8_t { kSensor = 1, kPrepare = 2 };

    // trace()'s phases over one photon's path (defined in trace.cpp): the next segment
    // and what ends it (false: the path ended); the port rejection of its first hit;
    // what the surface's chain makes of it; the material's scattering.
    struct PhotonPath;
    // The material a chain gives at a hit, with the pattern and normal perturbation.
    struct ChainHit {
        int32_t material = kVoid;
        Color pattern{1, 1, 1};
        Vec3 perturbation;
    };
    bool advance(PhotonPath& p) const;
    bool rejectedAtPort(PhotonPath& p, const Hit& hit) const;
    bool atSurface(PhotonPath& p, const Hit& hit) const;
    bool scatterAt(PhotonPath& p, const Hit& hit, const ChainHit& at,
                   const material::MaterialRecord& mi, bool storeAllowed) const;

    // The material a photon meets at `hit` and what the chain did to it: for a plain
    // chain the material alone; otherwise the chain is evaluated at the hit, and of a
    // mixture's materials one is chosen with its weight's probability (pmapmat.c
    // mx_funcPhotonScatter draws one). Returns kVoid for an invisible surface.
    int32_t resolveChain(int32_t modifier, const Hit& hit, const Vec3& dir,
                         material::HitEvaluators& evals, Rng& rng, Color& pattern,
                         Vec3& perturbation) const;
    // The record of material `m` if photons can scatter there; throws its argument
    // error, or "not supported yet" for prisms.
    const material::MaterialRecord& scatterer(int32_t m) const;

    void deposit(const Hit& hit, bool front, const Color& flux, bool indirect, bool caustic,
                 const std::array<double, kNumPhotonMapTypes>& prob, Rng& storeRng,
                 PhotonBins& out) const;
    bool inRegions(const Vec3& p) const;

    // The photon's way through the medium `m` it travels in, up to `hit` (null: it
    // leaves the scene) or to a collision drawn from the medium's mean extinction
    // (pmap.c photonParticipate): a collision stores a volume photon (where the medium
    // scatters), is survived by albedo roulette and turns the ray by the phase function.
    enum class MediumStep { Reached, Scattered, Lost };
    MediumStep travelMedium(PhotonPath& path, const Hit* hit, const material::Medium& m) const;
    // A photon at a mist boundary `hit` (material `matIndex`): the medium it goes on in,
    // and, leaving a mist it never entered, the collision it may have had in it since it
    // started there (travelMedium's steps; Reached: it goes on, its ray spawned past).
    MediumStep crossMist(PhotonPath& path, const material::MistParams& mist, int32_t matIndex,
                         const Hit& hit, const Color& pattern) const;

    const Scene& scene_;
    const SceneGeometry& geometry_;
    SceneCube cube_;  // photons scattered in a medium outside it have leaked
    const material::SurfaceChains& chains_;
    const material::MaterialTable& materials_;  // chains_.materials()
    const material::MaterialCalc* materialCalc_;
    const light::EmissionPlan& plan_;
    TraceSettings settings_;
    std::vector<SurfaceModifier> surfaces_;  // indexed by modifier (prim) index
    std::vector<uint8_t> roles_;             // MaterialRole bits, indexed by prim
    std::vector<double> sourceMaxDistance_;  // per emission source: glow radius or 0
    // Per emission source: the medium and mists its photons start in (the mists that
    // enclose its centre, material/mist_probe.h; the global medium for distant sources).
    std::vector<material::Medium> sourceMedium_;
    std::vector<material::MistSet> sourceMists_;
    void findSourceMedia();
};

}  // namespace rp::pmap
