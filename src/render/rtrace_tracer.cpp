// RendererTracer (see rtrace_tracer.h).
#include "render/rtrace_tracer.h"

#include <tbb/enumerable_thread_specific.h>

#include "render/renderer_impl.h"

namespace rp::render {

struct RendererTracer::Contexts {
    tbb::enumerable_thread_specific<Renderer::ContextPtr> perThread;
};

RendererTracer::RendererTracer(const Renderer& renderer, bool immediateIrradiance)
    : renderer_(renderer), irradiance_(immediateIrradiance), contexts_(std::make_unique<Contexts>()) {}

RendererTracer::~RendererTracer() = default;

RayTraceFn RendererTracer::trace() const {
    return [this](const Vec3& origin, const Vec3& dir, uint64_t index,
                  std::vector<TracedRay>* tree, double maxDistance) {
        Renderer::ContextPtr& ctx = contexts_->perThread.local();
        if (!ctx) ctx = renderer_.makeContext();
        if (irradiance_) return renderer_.irradiance(*ctx, origin, dir, index);
        return renderer_.trace(*ctx, origin, dir, index, tree, maxDistance);
    };
}

}  // namespace rp::render
