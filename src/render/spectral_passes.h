// Rendering a spectrum in passes (util/spectrum.h Pass): each pass's renderer traces the
// same ray with the same random streams for three bands, and the results are gathered
// into one, the samples of every colour (v, W, r, x) in band order.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "render/rpict.h"
#include "render/rtrace_run.h"
#include "util/spectrum.h"

namespace rp::render {

// One ray's results from every pass (`passes`: spectral::passesOf of the sampling): the
// first pass's result, with the samples of all filled in. Geometry (hits, distances,
// names) is the same in every pass; where sampling made it differ (a ray tree), the first
// pass's is kept.
RayResult mergePasses(std::span<const RayResult> perPass, std::span<const spectral::Pass> passes);

// One ray's ray trees from every pass, merged node by node (rtrace -o...t): each ray that
// any pass traced, in depth-first order, with its samples from the passes that traced it
// and black in the bands of a pass that did not (its weight there fell under -lw).
std::vector<TracedRay> mergeTrees(std::span<const std::vector<TracedRay>> perPass,
                                  std::span<const spectral::Pass> passes);

// One renderer per pass of `sampling` (passOptions), over one scene and its geometry: the
// tools' single way of setting up a rendering, RGB included (one pass).
using PassRenderers = std::vector<std::unique_ptr<Renderer>>;
PassRenderers passRenderers(const Scene& scene, const SceneGeometry& geometry,
                            const RenderOptions& options, const spectral::Sampling& sampling,
                            const std::vector<std::string>& searchPath);
// rpict's and rvu's pixel tracers for them: the one pass's, or every pass's gathered
// (pixelTracersOverPasses).
PixelTracerFactory passPixelTracers(const PassRenderers& renderers,
                                    const spectral::Sampling& sampling);

// rpict's pixel tracers over every pass: each sample is traced in every pass and turned
// into RADIANCE RGB (spectral::toRgb), so the picture and its adaptive sampling see the
// whole spectrum's colour. The distance (-z) is the first pass's.
PixelTracerFactory pixelTracersOverPasses(std::vector<PixelTracerFactory> passes,
                                          const spectral::Sampling& s);

}  // namespace rp::render
