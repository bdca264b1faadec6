// RendererTracer (see rtrace_tracer.h).
#include "render/rtrace_tracer.h"

#include <tbb/enumerable_thread_specific.h>

#include "render/renderer_impl.h"

namespace rp::render {

struct RendererTracer::Contexts {
    tbb::enumerable_thread_specific<Renderer::ContextPtr> perThread;
    tbb::enumerable_thread_specific<std::unique_ptr<ContribTally>> tallies;
};

RendererTracer::RendererTracer(const Renderer& renderer, bool immediateIrradiance)
    : renderer_(renderer),
      irradiance_(immediateIrradiance),
      contexts_(std::make_unique<Contexts>()) {}

RendererTracer::~RendererTracer() = default;

RayTraceFn RendererTracer::trace() const {
    return [this](const Vec3& origin, const Vec3& dir, uint64_t index, std::vector<TracedRay>* tree,
                  double maxDistance) {
        Renderer::ContextPtr& ctx = contexts_->perThread.local();
        if (!ctx) ctx = renderer_.makeContext();
        if (irradiance_) return renderer_.irradiance(*ctx, origin, dir, index);
        return renderer_.trace(*ctx, origin, dir, index, tree, maxDistance);
    };
}

ContribTraceFn RendererTracer::contributions(const ContribTargets& targets) const {
    return [this, &targets](const Vec3& origin, const Vec3& dir, uint64_t index, double maxDistance,
                            std::vector<Color>& values) {
        Renderer::ContextPtr& ctx = contexts_->perThread.local();
        if (!ctx) ctx = renderer_.makeContext();
        std::unique_ptr<ContribTally>& tally = contexts_->tallies.local();
        if (!tally) tally = std::make_unique<ContribTally>(targets);
        tally->reset();
        if (irradiance_)
            renderer_.irradiance(*ctx, origin, dir, index, tally.get());
        else
            renderer_.trace(*ctx, origin, dir, index, nullptr, maxDistance, tally.get());
        const std::vector<Color>& v = tally->values();
        for (size_t k = 0; k < v.size() && k < values.size(); ++k) values[k] += v[k];
    };
}

}  // namespace rp::render
