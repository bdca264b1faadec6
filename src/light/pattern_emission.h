// Connects modified light sources (a glow or light whose material has a pattern chain,
// e.g. gensky's `skyfunc`) to photon emission: an EmissionOptions::modifierFor that
// evaluates the chain with the photon-origin ray variables of manual 3.1.2.
#pragma once

#include <functional>

#include "light/emitter.h"
#include "material/pattern.h"

namespace rp::light {

// For EmissionOptions::modifierFor. `patterns` must outlive the plan. The returned
// modifiers are thread-safe (one PatternEvaluator per thread). Throws notSupportedYet
// at the pattern's line for chains holding patterns that cannot be evaluated yet.
std::function<EmissionModifier(const LightSource&)> patternModifiers(
    const material::PatternSet& patterns);

}  // namespace rp::light
