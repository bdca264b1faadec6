// The direct calculation of the backward pass (RADIANCE source.c direct(), srcsamp.c,
// virtuals.c, m_mirror's and m_direct's virtual sources): the scene's light sources as
// the renderer sees them, their subdivision into samples at -ds resolution with -dj
// jitter, the sorted source test with the -dt threshold and -dc certainty, and virtual
// sources relayed by planar mirrors and prism1/prism2 surfaces (-dr, -dp). Shadow rays
// are traced by the caller's ShadowOracle, which knows materials (glass and trans pass
// light, mirrors reflect it, prisms redirect it, sources emit).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "geometry/scene_geometry.h"
#include "material/material.h"
#include "render/clip_set.h"
#include "render/render_options.h"
#include "render/renderer.h"
#include "render/source_list.h"
#include "scene/primitive.h"
#include "util/color.h"
#include "util/rng.h"
#include "util/vec.h"

namespace rp::render {

// What a shadow ray does where it meets a surface (material::shadowPass, answered by the
// renderer core through its modifier chain; never Alternate here).
using ShadowEvent = material::ShadowPass;

// What a shadow ray carries from surface to surface: each shadow ray starts with its lit
// point's DirectPoint::shadow.
struct ShadowPath {
    ClipSet clip;  // the antimatter volumes it is inside (clip_set.h)
    // PhotonMode::shadowsStopAtTransparent: the photons carry what transparent surfaces
    // would pass.
    bool transparentBlocks = false;
};

struct DirectPoint;

// One straight piece of a tested shadow ray, for the ray tree (rtrace -o...t/T): from
// `origin` along unit `dir` to the surface `hit` (none: it left the scene, through
// distant source `distant` if that is >= 0), with the radiance arriving along it and,
// for a surface it passed on from, the colour passed (the next piece's coefficient).
struct ShadowPiece {
    Vec3 origin, dir;
    std::optional<Hit> hit;
    int32_t distant = -1;  // index into SceneGeometry::sources()
    Color value;
    Color coefficient{1, 1, 1};  // the first piece: the sample's coefficient
};

// Which shadow rays the ray tree shows (RADIANCE rtrace: under -ot the shadow rays its
// materials pass on, glass and antimatter, which its direct() follows; under -oT every
// one, SFOLLOW). A shadow ray stopped by the first surface it meets is never shown
// (RADIANCE's shadow cache usually answers those without tracing), nor one toward a
// virtual source.
enum class ShadowTree { None, Followed, All };

// Per-thread access to materials for shadow rays. Implemented by the renderer core.
class ShadowOracle {
public:
    virtual ~ShadowOracle() = default;
    // The shadow rays the ray tree shows, and where they go: the pieces of one shadow
    // ray from `at`, first piece first (values known), after it was traced.
    virtual ShadowTree shadowTree() const { return ShadowTree::None; }
    virtual void reportShadowRay(const DirectPoint& at, std::span<const ShadowPiece> pieces) {}
    // The first surface along `ray` (t < ray.tmax).
    virtual std::optional<Hit> closestHit(const Ray& ray) = 0;
    // What a shadow ray travelling in `dir` along `path` does at `hit` (antimatter passes
    // it, Transmit, and changes path.clip). `passIllum`: the ray is aimed at another
    // source, so an illum it meets is its alternate material (RADIANCE source.c
    // passillum: a window's illum passes the sun through its glass).
    virtual ShadowEvent event(const Hit& hit, const Vec3& dir, ShadowPath& path,
                              bool passIllum = false) = 0;
    // Radiance of distant source `source` (index into SceneGeometry::sources()) seen in
    // unit direction `dir` (patterns applied); zero if it is not a light source.
    virtual Color distantRadiance(int32_t source, const Vec3& dir) = 0;
    // Redirection `projection` of the prism1/prism2 surface at `hit` for a shadow ray
    // travelling `dir` toward a virtual source, DxA DyA DzA aimed along `toSource`
    // (m_direct.c). The default knows no prisms.
    virtual material::Redirection redirect(const Hit& hit, const Vec3& dir, int projection,
                                           const Vec3& toSource) {
        return {};
    }
};

// The point being shaded.
struct DirectPoint {
    Vec3 point;                // hit point
    Vec3 normal;               // shading normal on the side the ray came from
    Vec3 geomNormal;           // geometric normal on that side (for spawn offsets)
    const Hit* hit = nullptr;  // the hit (spawnRay/spawnSegment offsets)
    bool transmits = false;    // the material transmits: sources behind count too
    // The ray's weight (RADIANCE r->rweight): -dt is relative to it (threshold dt/weight)
    // and sources are subdivided less for low-weight rays (-ds/weight), as in RADIANCE.
    double weight = 1;
    // The medium at the point: shadow rays are attenuated by its absorption (RADIANCE
    // rayparticipate: extinction times 1 - albedo, scattering is not a loss to them),
    // or with `scatterLoss` by the whole extinction: where photons carry the scattered
    // light to surfaces (a global map), counting it here as well would count it twice.
    const material::Medium* medium = nullptr;  // null: none
    bool scatterLoss = false;
    // rcontrib: each shadow ray that reaches a source is reported to `contrib` (if any)
    // with the path coefficient `contribCoef` times the sample's coefficient and what the
    // shadow path transmits (RADIANCE: the shadow ray's trace_contrib call).
    ContributionSink* contrib = nullptr;
    Color contribCoef{1, 1, 1};
    ShadowPath shadow;  // what each shadow ray from here starts with
    // For the ray tree: the generation of the ray that reached the point (its shadow
    // rays are one deeper).
    int generation = 0;
};

// RADIANCE's coefficient function for one source sample: the material's BRDF*cos for
// light from unit direction `toLight`, given the sample's solid angle `omega`
// (material::evaluate). Zero means "this sample cannot contribute".
// compute() multiplies it by omega: a sample contributes
// coefficient(toLight, omega) * omega * radiance (so a coefficient of cos gives irradiance).
using DirectCoefficient = std::function<Color(const Vec3& toLight, double omega)>;

// Working memory of DirectLighting::compute (candidate samples, relay crossings, the
// subdivision of sources), kept per thread by the caller so that shading a point does
// not allocate.
class DirectScratch {
public:
    DirectScratch();
    ~DirectScratch();
    DirectScratch(const DirectScratch&) = delete;
    DirectScratch& operator=(const DirectScratch&) = delete;

private:
    friend class DirectLighting;
    struct Buffers;
    std::unique_ptr<Buffers> b_;
};

// Where we differ from RADIANCE, and why (details beside the code):
//  - subdivision (source_sampling.h): polygon cells are clipped exactly against the
//    polygon, each weighted with its own covered area (area cos / d^2 at its sample, as
//    RADIANCE weighs a cell; RADIANCE aims at bounding-box cells and scales the whole
//    source's area); spheres and distant sources use equal-solid-angle cells of their
//    direction cone; at most 64 cells per source (MAXSPART) throughout;
//  - untested samples (-dt) are scaled by this call's found/estimated brightness ratio,
//    not by RADIANCE's per-source hit statistics gathered over the run (those depend on
//    the order rays are traced in, i.e. on threads);
//  - the -dp pretest is geometric (opaque surfaces only; see source_list.h);
//  - a local source seen through a prism: sampled through the prism's affine map, its
//    samples' solid angles scaled by the map's Jacobian (RADIANCE transforms the source's
//    axes but keeps its area); virtual sources are not given RADIANCE's spot cones;
//  - a shadow ray that reaches its target without the accelerator reporting the source
//    (grazing) is given the source's emission there, since the target is on it.
class DirectLighting {
public:
    // Builds the source list by RADIANCE's rules (source.c marksources): surfaces whose
    // material is light, spotlight, illum or glow with positive radius (local glows
    // only illuminate within their radius), and distant `source`s with light-type
    // materials (a glow on a `source`, such as a sky, is left to the ambient calculation:
    // RADIANCE's SSKIP). Zero-radiance sources are dropped. With -dr > 0 and mirrors (or,
    // given `redirect`, prisms) in the scene, virtual sources are added (virtuals.c)
    // unless `virtualSources` is false (photon-map mode switches them off).
    // `globalMedium` (-me -ma -mg) is what shadow rays leaving a dielectric or a mist
    // travel in.
    DirectLighting(const Scene& scene, const SceneGeometry& geometry, const DirectOptions& options,
                   bool virtualSources = true, const RedirectFunction& redirect = {},
                   const material::Medium& globalMedium = {});
    ~DirectLighting();

    // Direct contribution at `at`: sum over sources and their samples of
    // coefficient(toLight, omega) * radiance arriving along the shadow ray, honouring
    // -dt/-dc (untested sources estimated as RADIANCE does) and -dj.
    Color compute(const DirectPoint& at, const DirectCoefficient& coefficient, ShadowOracle& oracle,
                  Rng& rng, DirectScratch& scratch) const;

    // One sample of real source `source` as a whole (no subdivision) seen from `at.point`
    // in a medium (RADIANCE srcscatter: nopart, srcray with no parent surface): the
    // radiance arriving along its shadow ray times the sample's solid angle, with the
    // unit direction to it in `toLight`; zero if blocked or outside a spotlight's cone.
    Color sampleWhole(size_t source, const DirectPoint& at, ShadowOracle& oracle, Rng& rng,
                      Vec3& toLight) const;

    // A shadow ray aimed at source `source` as a whole (RADIANCE: a SHADOW ray with rsrc
    // set, as rpict's srcdraw.c traces from the view): the radiance reaching `at.point`
    // along unit `dir`, through what passes light, from wherever the ray meets the source
    // (a distant one within its disk); zero if it is blocked, misses the source, leaves a
    // spotlight outside its cone, or the source is virtual. `distance` (may be null):
    // how far away it met the source (HUGE_VAL for zero).
    Color traceToward(size_t source, const DirectPoint& at, const Vec3& dir, ShadowOracle& oracle,
                      double* distance = nullptr) const;

    // Whether `prim` is the surface of a (real) direct source: rays descended from
    // ambient or sampled specular rays must not count its emission again
    // (RADIANCE badcomponent). A local glow counts only within its radius of `from`.
    bool isSourceSurface(int32_t prim, const Vec3& from) const;
    // Whether distant source `source` is in the list (a `source` with a light material).
    bool isDistantSource(int32_t source) const;

    size_t sourceCount() const;         // real sources
    size_t virtualSourceCount() const;  // relayed by mirrors and prisms

    // The list itself (real sources first, then virtual ones), for diagnostics and tests.
    const SourceList& sourceList() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp::render
