// rendererPixelTracers (see rpict_tracer.h).
#include "render/rpict_tracer.h"

#include <memory>

#include "render/renderer_impl.h"  // Renderer::Context must be complete to be destroyed

namespace rp::render {

PixelTracerFactory rendererPixelTracers(const Renderer& renderer) {
    return [&renderer]() -> PixelTracer {
        std::shared_ptr<Renderer::Context> ctx(renderer.makeContext());
        return [&renderer, ctx](const Vec3& org, const Vec3& dir, uint64_t index,
                                double maxDistance, double* distance) {
            RayResult r = renderer.trace(*ctx, org, dir, index, nullptr, maxDistance);
            *distance = r.distance;
            return r.value;
        };
    };
}

}  // namespace rp::render
