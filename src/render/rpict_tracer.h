// The PixelTracerFactory rpict uses with the real renderer: one Renderer::Context per
// worker thread, tracing primary rays with Renderer::trace. Kept apart from rpict.h so that
// the picture loop and its tests do not depend on the renderer's internals.
#pragma once

#include "render/renderer.h"
#include "render/rpict.h"

namespace rp::render {

// Each tracer made owns a fresh Context; `renderer` must outlive every tracer. The tracer
// returns RayResult::value and stores RayResult::distance.
PixelTracerFactory rendererPixelTracers(const Renderer& renderer);

}  // namespace rp::render
