// The RayTraceFn (rtrace_run.h) and ContribTraceFn (rcontrib_run.h) that trace with a Renderer: one
// Renderer::Context per worker thread, -I (immediate irradiance) or ordinary rays. Lives in
// src/render because a Context is only complete here (renderer_impl.h).
#pragma once

#include <memory>

#include "render/rcontrib.h"
#include "render/rcontrib_run.h"
#include "render/renderer.h"
#include "render/rtrace_run.h"

namespace rp::render {

// Owns the per-thread contexts; `trace()` stays valid while this object and `renderer` live.
class RendererTracer {
public:
    // immediateIrradiance: rtrace -I, origin = surface point, direction = its normal.
    RendererTracer(const Renderer& renderer, bool immediateIrradiance);
    ~RendererTracer();
    RendererTracer(const RendererTracer&) = delete;
    RendererTracer& operator=(const RendererTracer&) = delete;

    RayTraceFn trace() const;
    // rcontrib: each ray's contributions tallied by `targets` (outliving this object).
    ContribTraceFn contributions(const ContribTargets& targets) const;

private:
    struct Contexts;
    const Renderer& renderer_;
    bool irradiance_;
    std::unique_ptr<Contexts> contexts_;
};

}  // namespace rp::render
