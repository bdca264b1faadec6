// mkpmap -apE (issue 48): what photon ports see outside, from the classic calculation.
// RADIANCE's ports emit only the sources seen through them (manual 3.2.4: "external
// reflections are not accounted for"), so a sunlit ground, facades and overhangs outside
// a window bring no photons in; a side-lit room read 15-24 % low away from the sun patch.
// Here each port's exterior is sampled by backward rays, as mkillum samples an illum,
// and the port emits that light too (light/emitter.h PortExterior). The calculation
// lives here because the emission plan (light/) sits below the renderer.
#pragma once

#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/emitter.h"
#include "render/render_options.h"
#include "scene/primitive.h"

namespace rp::render {

// The settings of the rays behind a port's exterior table: two ambient bounces outside
// (sky on the ground, ground on a facade or overhang) with the irradiance cache, which
// makes a table of a few thousand rays cost well under a second.
RenderOptions portExteriorOptions();

// What a port sees outside, for the emission plan: the radiance of the surfaces its rays
// meet (renderers of `scene` with portExteriorOptions(), in the bands of `pass`: a
// spectral map set's pass sees its own bands, spectrum.h), and the ambient irradiance
// there for the photons left on them (light/emitter.h ExteriorView). The returned
// function keeps what it needs alive and must be called from one thread (its irradiance
// cache fills in call order, which keeps the plan the same for any -n).
light::PortExterior portExterior(const Scene& scene, const SceneGeometry& geometry,
                                 std::vector<std::string> searchPath,
                                 const spectral::Pass& pass = {});

}  // namespace rp::render
