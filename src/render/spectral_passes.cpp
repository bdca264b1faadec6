// Gathering the passes of a spectral rendering (see spectral_passes.h).
#include "render/spectral_passes.h"

#include <map>
#include <memory>

#include "render/rpict_tracer.h"
#include "util/error.h"

namespace rp::render {

RayResult mergePasses(std::span<const RayResult> perPass, std::span<const spectral::Pass> passes) {
    RP_CHECK(perPass.size() == passes.size() && !perPass.empty());
    const spectral::Sampling& s = passes[0].sampling;
    auto samples = std::make_shared<RayResult::Samples>();
    for (auto* v :
         {&samples->value, &samples->coefficient, &samples->mirrored, &samples->unmirrored})
        v->assign(size_t(s.n), 0.0);
    for (size_t p = 0; p < passes.size(); ++p) {
        const RayResult& r = perPass[p];
        passes[p].placeBands(r.value, samples->value);
        passes[p].placeBands(r.coefficient, samples->coefficient);
        passes[p].placeBands(r.mirrored, samples->mirrored);
        passes[p].placeBands(r.unmirrored, samples->unmirrored);
    }
    RayResult merged = perPass[0];
    // The RGB fields hold the samples' RGB, for whoever reads them.
    merged.value = spectral::toRgb(samples->value, s);
    merged.coefficient = spectral::toRgb(samples->coefficient, s);
    merged.mirrored = spectral::toRgb(samples->mirrored, s);
    merged.unmirrored = spectral::toRgb(samples->unmirrored, s);
    merged.samples = std::move(samples);
    return merged;
}

namespace {

// A ray tree node's place: the child numbers from the input ray down to it. Trees are
// written depth first, so the places of one tree sort in its order.
using TreePlace = std::vector<int>;

std::vector<TreePlace> treePlaces(const std::vector<TracedRay>& tree) {
    std::vector<TreePlace> places;
    places.reserve(tree.size());
    std::vector<int> count;
    for (const TracedRay& node : tree) {
        count.resize(size_t(node.depth) + 1, 0);
        ++count[size_t(node.depth)];
        places.push_back(count);
    }
    return places;
}

RayResult unlit(RayResult r) {
    r.value = r.coefficient = r.mirrored = r.unmirrored = Color{};
    r.samples.reset();
    return r;
}

}  // namespace

std::vector<TracedRay> mergeTrees(std::span<const std::vector<TracedRay>> perPass,
                                  std::span<const spectral::Pass> passes) {
    RP_CHECK(perPass.size() == passes.size());
    std::map<TreePlace, std::vector<const TracedRay*>> nodes;
    for (size_t p = 0; p < perPass.size(); ++p) {
        const std::vector<TreePlace> places = treePlaces(perPass[p]);
        for (size_t k = 0; k < places.size(); ++k) {
            auto& slot = nodes[places[k]];
            slot.resize(perPass.size(), nullptr);
            slot[p] = &perPass[p][k];
        }
    }
    std::vector<TracedRay> merged;
    merged.reserve(nodes.size());
    for (const auto& [place, inPasses] : nodes) {
        const TracedRay* traced = nullptr;
        for (const TracedRay* t : inPasses)
            if (t && !traced) traced = t;
        std::vector<RayResult> results;
        for (const TracedRay* t : inPasses)
            results.push_back(t ? t->result : unlit(traced->result));
        merged.push_back({int(place.size()) - 1, mergePasses(results, passes)});
    }
    return merged;
}

PixelTracerFactory pixelTracersOverPasses(std::vector<PixelTracerFactory> passes,
                                          const spectral::Sampling& s) {
    return [passes = std::move(passes), s] {
        std::vector<PixelTracer> tracers;
        for (const PixelTracerFactory& f : passes) tracers.push_back(f());
        const std::vector<spectral::Pass> bands = spectral::passesOf(s);
        return PixelTracer([tracers = std::move(tracers), bands, s](
                               const Vec3& org, const Vec3& dir, uint64_t index, double maxDistance,
                               double* distance) mutable {
            double samples[spectral::kMaxSamples];
            double ignored = 0;
            for (size_t p = 0; p < tracers.size(); ++p) {
                const Color c =
                    tracers[p](org, dir, index, maxDistance, p == 0 ? distance : &ignored);
                bands[p].placeBands(c, std::span<double>(samples, size_t(s.n)));
            }
            return spectral::toRgb(std::span<const double>(samples, size_t(s.n)), s);
        });
    };
}

PassRenderers passRenderers(const Scene& scene, const SceneGeometry& geometry,
                            const RenderOptions& options, const spectral::Sampling& sampling,
                            const std::vector<std::string>& searchPath) {
    PassRenderers out;
    for (const RenderOptions& pass : passOptions(options, sampling))
        out.push_back(std::make_unique<Renderer>(scene, geometry, pass, searchPath));
    return out;
}

PixelTracerFactory passPixelTracers(const PassRenderers& renderers,
                                    const spectral::Sampling& sampling) {
    std::vector<PixelTracerFactory> each;
    for (const auto& r : renderers) each.push_back(rendererPixelTracers(*r));
    return each.size() == 1 ? each[0] : pixelTracersOverPasses(std::move(each), sampling);
}

}  // namespace rp::render
