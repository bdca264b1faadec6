// The rays RADIANCE's mkillum traces (mkillum2.c raysamp and srcsamps), traced by a
// Renderer: sample rays of RADIANCE's type PRIMARY|SPECULAR, and shadow rays to every
// light source. Lives in src/render because both need the renderer's per-thread Context
// (renderer_impl.h); where the rays go and what becomes of their values is src/illum.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "render/renderer.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::render {

class IllumRayTracer {
public:
    explicit IllumRayTracer(const Renderer& renderer);
    ~IllumRayTracer();
    IllumRayTracer(const IllumRayTracer&) = delete;
    IllumRayTracer& operator=(const IllumRayTracer&) = delete;

    // Radiance arriving at `origin` from the unit direction `dir` travels (the ray goes
    // along dir). RADIANCE compat (mkillum2.c raysamp: rayorigin(PRIMARY|SPECULAR)): the
    // light sources such a ray meets, directly or through glass, count nothing
    // (source.c badcomponent), since the direct component is sampled apart (l+) or left
    // to the renderer (illum); glows that are not sources still count. `rayIndex` keys
    // the random streams, so the value does not depend on the thread. Thread-safe.
    Color radiance(const Vec3& origin, const Vec3& dir, uint64_t rayIndex) const;

    // One shadow ray through `point` to each real light source (mkillum2.c srcsamps:
    // srcray over the source list, each source taken whole), starting `offset` before the
    // point: `visit` gets the unit direction toward the source and the radiance the ray
    // brings times the source's solid angle, for the rays that reach their source.
    // Virtual sources (mirrors) are not sampled. Thread-safe.
    using SourceVisit = std::function<void(const Vec3& toSource, const Color& radianceOmega)>;
    void sourceSamples(const Vec3& point, double offset, uint64_t rayIndex,
                       const SourceVisit& visit) const;

    // The renderer's random base (-u+: new for each run, -u-: fixed), for streams of the
    // caller's own that should follow the same rule.
    uint64_t seed() const;

private:
    struct Contexts;
    Renderer::Context& context() const;
    const Renderer& renderer_;
    std::unique_ptr<Contexts> contexts_;
};

}  // namespace rp::render
