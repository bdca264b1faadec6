// Connects modified light sources (a glow or light whose material has a pattern chain:
// gensky's `skyfunc`, a luminaire's `brightdata` distribution) to photon emission: an
// EmissionOptions::modifierFor that walks the chain with the renderer's own evaluator
// (material/surface_chain.h), so photons leave a source as shadow rays see it.
#pragma once

#include <functional>

#include "light/emitter.h"
#include "material/surface_chain.h"

namespace rp::light {

// For EmissionOptions::modifierFor. `chains` must outlive the plan. The returned
// modifiers are thread-safe (one evaluator per thread). Throws InputError or
// notSupportedYet at the record's line for chains that cannot be evaluated.
std::function<EmissionModifier(const LightSource&)> patternModifiers(
    const material::SurfaceChains& chains);

}  // namespace rp::light
