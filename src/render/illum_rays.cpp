// IllumRayTracer (see illum_rays.h).
#include "render/illum_rays.h"

#include <tbb/enumerable_thread_specific.h>

#include <optional>

#include "render/renderer_impl.h"

namespace rp::render {

struct IllumRayTracer::Contexts {
    tbb::enumerable_thread_specific<Renderer::ContextPtr> perThread;
};

IllumRayTracer::IllumRayTracer(const Renderer& renderer)
    : renderer_(renderer), contexts_(std::make_unique<Contexts>()) {}

IllumRayTracer::~IllumRayTracer() = default;

Renderer::Context& IllumRayTracer::context() const {
    Renderer::ContextPtr& ctx = contexts_->perThread.local();
    if (!ctx) ctx = renderer_.makeContext();
    return *ctx;
}

uint64_t IllumRayTracer::seed() const { return context().impl.seed; }

Color IllumRayTracer::radiance(const Vec3& origin, const Vec3& dir, uint64_t rayIndex) const {
    Renderer::Context& ctx = context();
    // The same stream rule as Renderer::trace, so that a ray's value depends on its index
    // alone.
    ctx.rng = Rng(ctx.impl.seed, RngDomain::Sampling, rayIndex);
    if (ctx.photonLookups) ctx.photonLookups->startRay();
    ctx.tree = nullptr;
    ctx.treeDepth = 0;
    RayState state;
    // RADIANCE's SPECULAR bit: sources met are left to the direct calculation.
    state.indirect = true;
    const std::optional<MediaState> start = ctx.mediaAt(origin);
    if (start) state.media = &*start;
    double distance = 1e10;
    return ctx.radiance(Ray{origin, dir, HUGE_VAL}, state, nullptr, distance);
}

void IllumRayTracer::sourceSamples(const Vec3& point, double offset, uint64_t rayIndex,
                                   const SourceVisit& visit) const {
    Renderer::Context& ctx = context();
    ctx.rng = Rng(ctx.impl.seed, RngDomain::Sampling, rayIndex);
    DirectPoint at;
    // Shadow rays in the global medium lose what it absorbs (RADIANCE rayparticipate).
    if (ctx.impl.globalMedium.active()) at.medium = &ctx.impl.globalMedium;
    const DirectLighting& direct = ctx.impl.direct;
    const SourceList& list = direct.sourceList();
    for (size_t s = 0; s < direct.sourceCount(); ++s) {
        // RADIANCE compat (srcsamps): the ray starts `offset` back along its way, so that
        // it crosses the surface at `point` itself, through whatever material the surface
        // has in the scene, even near its edges. The way is taken toward the source's
        // centre, which the sample lies close to.
        const DirectSource& src = list.sources[s];
        const Vec3 toward = src.distant() ? src.centre : normalize(src.centre - point);
        at.point = point - toward * offset;
        Vec3 toSource;
        const Color c = direct.sampleWhole(s, at, ctx, ctx.rng, toSource);
        if (c.max() > 0) visit(toSource, c);
    }
}

}  // namespace rp::render
