#include "material/mist_probe.h"

#include <algorithm>
#include <optional>

namespace rp::material {

bool sceneHasMist(const Scene& scene) {
    return std::any_of(scene.prims.begin(), scene.prims.end(),
                       [](const Primitive& p) { return p.type == PrimType::Mist; });
}

std::vector<EnclosingMist> enclosingMists(const SceneGeometry& geometry,
                                          const SurfaceChains& chains, const Vec3& p, Rng& rng) {
    std::vector<EnclosingMist> out;
    // An oblique direction, so that the probe does not run along the axis-aligned edges
    // and faces of boxes (genbox) where hits are ambiguous.
    const Vec3 dir = normalize(Vec3(0.2718, 0.5772, 0.7701));
    std::vector<int32_t> entered;  // mists the probe went into on its way
    std::optional<SurfaceChainEvaluator> eval;
    Ray ray{p, dir, HUGE_VAL};
    for (int pass = 0; pass < 10000; ++pass) {  // bounded: pathological stacks of surfaces
        std::optional<Hit> hit = geometry.closestHit(ray);
        if (!hit) break;
        ray = spawnRay(*hit, dir);
        if (hit->modifier == kVoid) continue;
        ChainResult c;
        if (chains.isPlain(hit->modifier)) {
            c = ChainResult::plain(chains.plainMaterial(hit->modifier));
        } else {
            if (!eval) eval.emplace(chains);
            c = eval->resolve(hit->modifier, PatternPoint::atHit(dir, *hit), rng);
        }
        for (int i = 0; i < c.count; ++i) {
            const ShadingLayer& layer = c.layers[size_t(i)];
            if (layer.material == kVoid) continue;
            if (!std::holds_alternative<MistParams>(*chains.materials().at(layer.material).params))
                continue;
            if (hit->front) {
                entered.push_back(layer.material);
                continue;
            }
            auto it = std::find(entered.rbegin(), entered.rend(), layer.material);
            if (it != entered.rend())
                entered.erase(std::next(it).base());
            else
                out.push_back({layer.material, layer.pattern});
        }
    }
    return out;
}

Medium mediumWithin(const std::vector<EnclosingMist>& around, const Medium& global,
                    const MaterialTable& materials, MistSet& mists) {
    Medium m = global;
    for (auto e = around.rbegin(); e != around.rend(); ++e) {
        const auto& mist = std::get<MistParams>(*materials.at(e->material).params);
        m = changeMedium(m, mistCrossing(mist, true, e->pattern), global, &mist);
        mists.enter(e->material);
    }
    return m;
}

}  // namespace rp::material
