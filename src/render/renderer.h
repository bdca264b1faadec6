// The backward ray tracer shared by rtrace and rpict (RADIANCE raytrace.c/rayfunc
// dispatch): a ray meets a surface, its material (after patterns, textures and mixtures)
// is shaded with direct light (direct.h), ideal and sampled specular rays, and indirect
// light from the ambient calculation (ambient.h). One Renderer per scene and options,
// shared by all threads; one Renderer::Context per thread.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "render/render_options.h"
#include "scene/primitive.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::pmap {
struct FoundPhoton;  // pmap/photon_store.h
}

namespace rp::render {

// What rtrace's -o specifiers report about one traced ray (RADIANCE rtrace.c oputs).
struct RayResult {
    Vec3 origin, direction;      // o d: as traced (direction unit)
    Color value;                 // v: radiance along the ray (irradiance with -i / -I)
    Color coefficient{1, 1, 1};  // W: the ray's colour coefficient (1 for input rays)
    double weight = 1;           // w: the ray's weight (1 for input rays)
    bool hit = false;            // false: the ray left the scene
    // It left the scene through a distant source (RADIANCE sourcehit sets ro to it): s m M
    // name the source, n and N are -d, p is the origin (hit stays false).
    bool distantSource = false;
    double distance = 1e10;  // L: distance to the first intersection (RADIANCE FHUGE if none)
    double effectiveLength = 1e10;   // l: effective distance (through mirrors: apparent)
    Vec3 point;                      // p: first intersection
    Vec3 normal;                     // n: perturbed surface normal (RADIANCE's ron + pert)
    Vec3 unperturbedNormal;          // N
    double u = 0, v = 0;             // c: local surface coordinates (geometry/ray.h Hit::u, v)
    int32_t prim = -1;               // s: surface hit (index into Scene::prims; -1 none)
    int32_t modifier = -1;           // m: its modifier
    int32_t material = -1;           // M: its material after patterns/textures/aliases
    Color mirrored;                  // r: value contribution of pure specular reflection
    Color unmirrored;                // x: value minus the mirrored part
    double mirroredLength = 1e10;    // R: effective length of the mirrored ray
    double unmirroredLength = 1e10;  // X: effective length of the unmirrored part
    // Rendering a spectrum in passes (-cs above 3): the samples of v, W, r and x
    // (sampling.n each), gathered from the passes; null when rendering RGB.
    struct Samples {
        std::vector<double> value, coefficient, mirrored, unmirrored;
    };
    std::shared_ptr<const Samples> samples;
};

// One ray of the ray tree, for rtrace's trace output (-o...t...): every ray traced,
// each after the rays it spawned (RADIANCE reports a ray when its value is known).
struct TracedRay {
    int depth = 0;  // 0: the input ray
    RayResult result;
};

class DirectLighting;
struct SourceList;
class Ambient;
class PhotonLighting;

// rcontrib's view of the ray tree (RADIANCE rcontrib.c trace_contrib, pmcontrib2.c
// photonContrib). Every ray that ends on a surface whose modifier is tracked, every
// shadow ray that reaches a source and every ray that leaves the scene through a distant
// source is reported with its path coefficient: the product of the coefficients of the
// rays from the input ray down to it (RADIANCE raycontrib). Photon contributions come
// per photon from a contribution map. One sink per input ray (not shared by threads).
class ContributionSink {
public:
    virtual ~ContributionSink() = default;
    // Whether rays ending on surfaces modified by `modifier` are reported (cheap; asked
    // before anything is computed for them).
    virtual bool tracks(int32_t modifier) const = 0;
    // A ray travelling unit `dir` ended at `point` on a surface modified by `modifier`
    // (tracked), or left the scene through distant source `modifier` (point far along
    // dir). `coef`: its path coefficient; `value`: the radiance it brings back (after
    // shading). A light that the direct calculation counts already is not reported
    // (RADIANCE zeroes that ray's coefficient).
    virtual void add(int32_t modifier, const Vec3& point, const Vec3& dir, const Color& coef,
                     const Color& value) = 0;
    // Photon contributions (rcontrib -ap): photons of the contribution map (their
    // primaries say what source emitted each and, with primary rays, where), each bringing
    // its flux times `scale` times `coef` (the path coefficient), as irradiance / pi.
    virtual void addPhotons(std::span<const pmap::FoundPhoton> photons, double scale,
                            const Color& coef) = 0;
    // Binned contributions of a precomputed contribution map (already times the path
    // coefficient, as irradiance / pi): values[b] for bin b of the tracked modifier
    // `modifier` (a scene record of that name).
    virtual void addBins(int32_t modifier, std::span<const Color> values) = 0;
};

class Renderer {
public:
    // Resolves materials and patterns, builds the source list and the ambient cache
    // (loading -af). Throws InputError for bad material arguments, missing function
    // files and materials that are not supported yet.
    Renderer(const Scene& scene, const SceneGeometry& geometry, const RenderOptions& options,
             std::vector<std::string> searchPath);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Per-thread state: random streams, pattern evaluators, scratch space. Opaque
    // outside src/render; ContextPtr destroys it where its type is complete.
    class Context;
    struct ContextDeleter {
        void operator()(Context* c) const;
    };
    using ContextPtr = std::unique_ptr<Context, ContextDeleter>;
    ContextPtr makeContext() const;

    // Traces one input ray from `origin` in unit direction `dir`. `rayIndex` keys the
    // random streams so that a ray's result does not depend on the thread tracing it
    // (the shared ambient cache can still make results order dependent, as in RADIANCE).
    // With options.irradiance (-i) the value at the first surface hit is irradiance.
    // `tree` (may be null) receives every ray traced for this one, for rtrace -o~.
    // `maxDistance` (rtrace -ld): surfaces beyond it are not seen and a ray reaching it
    // ends there with nothing (RADIANCE's clipped ray), no source or sky behind.
    // `contrib` (may be null): rcontrib's sink, told about every contribution.
    RayResult trace(Context& ctx, const Vec3& origin, const Vec3& dir, uint64_t rayIndex,
                    std::vector<TracedRay>* tree = nullptr, double maxDistance = HUGE_VAL,
                    ContributionSink* contrib = nullptr) const;

    // rtrace -I: irradiance at `point` on a surface facing unit `normal` (light arriving
    // from the side the normal points to), direct plus ambient, as RADIANCE computes it
    // with a ray starting just off the point: the surface is taken kIrradianceOffset
    // in front of `point`, as RADIANCE's rtrace does.
    static constexpr double kIrradianceOffset = 1e-4;
    RayResult irradiance(Context& ctx, const Vec3& point, const Vec3& normal, uint64_t rayIndex,
                         ContributionSink* contrib = nullptr) const;

    // rpict's bitty sources (source_draw.h): the radiance reaching `origin` along unit
    // `dir` from direct source `source` (index into directSources().sources), traced as
    // a shadow ray aimed at it (DirectLighting::traceToward) in the medium around
    // `origin`; zero if blocked or missed. `distance` receives how far away it met the
    // source. `rayIndex` keys the random streams, as trace's.
    Color traceToSource(Context& ctx, size_t source, const Vec3& origin, const Vec3& dir,
                        uint64_t rayIndex, double* distance) const;
    // The direct calculation's light sources (source_list.h).
    const SourceList& directSources() const;

    const Scene& scene() const { return scene_; }
    const SceneGeometry& geometry() const { return geometry_; }
    const RenderOptions& options() const { return options_; }

    // Statistics since construction (all threads): rays traced, for -t reports.
    long raysTraced() const;
    // Ambient records in the irradiance cache (loaded and computed).
    long ambientRecords() const;

    // The -ap photon maps (inactive without), e.g. for the short-lookup count.
    const PhotonLighting& photons() const;

    // Writes new ambient records to the -af file (if any). Called by the tools at exit.
    void flushAmbientFile() const;

private:
    struct Impl;
    const Scene& scene_;
    const SceneGeometry& geometry_;
    RenderOptions options_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp::render
