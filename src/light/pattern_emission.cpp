#include "light/pattern_emission.h"

#include <tbb/enumerable_thread_specific.h>

#include <memory>

namespace rp::light {

std::function<EmissionModifier(const LightSource&)> patternModifiers(
    const material::PatternSet& patterns) {
    return [&patterns](const LightSource& source) {
        int32_t chain = source.patternModifier;
        patterns.checkChain(chain);
        using Evaluators = tbb::enumerable_thread_specific<material::PatternEvaluator>;
        auto evaluators = std::make_shared<Evaluators>(
            [&patterns] { return material::PatternEvaluator(patterns); });
        EmissionModifier m;
        m.directionalOnly = patterns.directionalOnly(chain);
        m.eval = [evaluators, chain](const EmissionQuery& q) {
            material::PatternPoint at;
            at.dir = q.rayDir;  // towards the photon origin (manual 3.1.2)
            at.point = q.point;
            at.normal = q.normal;
            at.rdot = q.rdot;
            return evaluators->local().chainColor(chain, at);
        };
        return m;
    };
}

}  // namespace rp::light
