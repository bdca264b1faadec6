#include "light/pattern_emission.h"

#include <tbb/enumerable_thread_specific.h>

#include <memory>

namespace rp::light {

namespace {

// One evaluator per thread. The Rng only decides between the sides of mixtures nested
// beyond ChainResult::kMaxLayers, which a light's pattern chain does not hold in practice.
struct ChainThread {
    explicit ChainThread(const material::SurfaceChains& chains) : eval(chains) {}
    material::SurfaceChainEvaluator eval;
    Rng rng{0, RngDomain::Emission, 0};
};

}  // namespace

std::function<EmissionModifier(const LightSource&)> patternModifiers(
    const material::SurfaceChains& chains) {
    return [&chains](const LightSource& source) {
        // The chain is walked from the light material itself, as RADIANCE's m_light
        // calls raytexture with the material's modifier: its one layer carries r->pcol.
        const int32_t material = source.material;
        chains.checkChain(material);
        using Threads = tbb::enumerable_thread_specific<ChainThread>;
        auto threads = std::make_shared<Threads>([&chains] { return ChainThread(chains); });
        EmissionModifier m;
        m.directionalOnly = chains.directionalOnly(source.patternModifier);
        m.eval = [threads, material](const EmissionQuery& q) {
            // The same ray variables as a shadow ray meeting the source (pmapsrc.c): D
            // points at the source (minus the photon direction), Rdot = N . photon
            // direction is positive in front, N is the unflipped surface normal.
            material::PatternPoint at;
            at.dir = q.rayDir;
            at.point = q.point;
            at.normal = q.normal;
            at.rdot = q.rdot;
            ChainThread& t = threads->local();
            return t.eval.resolve(material, at, t.rng).layers[0].pattern;
        };
        return m;
    };
}

}  // namespace rp::light
