// mkillum's command line and run (see mkillum.h).
#include "illum/mkillum.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <memory>

#include "calc/search_path.h"
#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "illum/illum_filter.h"
#include "render/illum_rays.h"
#include "render/renderer.h"
#include "render/spectral_passes.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/file_read.h"
#include "util/options.h"
#include "util/paths.h"
#include "util/spectrum.h"

namespace rp::illum {

namespace {

// The renderer as the sampling sees it: one pass (RGB), or every pass of a spectral
// sampling with its bands gathered into RADIANCE RGB, as RADIANCE 6's mkillum computes
// spectra and writes RGB data.
class RendererIllumTracer : public IllumTracer {
public:
    RendererIllumTracer(const std::vector<std::unique_ptr<render::IllumRayTracer>>& rays,
                        const spectral::Sampling& sampling)
        : rays_(rays), passes_(spectral::passesOf(sampling)), sampling_(sampling) {}

    Color radiance(const Vec3& origin, const Vec3& dir, uint64_t rayIndex) const override {
        if (rays_.size() == 1) return rays_[0]->radiance(origin, dir, rayIndex);
        double samples[spectral::kMaxSamples] = {};
        for (size_t p = 0; p < rays_.size(); ++p)
            passes_[p].placeBands(rays_[p]->radiance(origin, dir, rayIndex), span(samples));
        return spectral::toRgb(span(samples), sampling_);
    }

    // Every pass draws the same sample on each source (the same random streams), so a
    // source's samples meet by their direction; a pass whose bands the source does not
    // reach leaves them black.
    void sourceSamples(const Vec3& point, double offset, uint64_t rayIndex,
                       const SourceVisit& visit) const override {
        if (rays_.size() == 1) return rays_[0]->sourceSamples(point, offset, rayIndex, visit);
        struct Sample {
            Vec3 dir;
            std::array<double, spectral::kMaxSamples> bands{};
        };
        std::vector<Sample> found;
        for (size_t p = 0; p < rays_.size(); ++p)
            rays_[p]->sourceSamples(point, offset, rayIndex, [&](const Vec3& d, const Color& c) {
                auto it = std::find_if(found.begin(), found.end(),
                                       [&](const Sample& s) { return s.dir == d; });
                if (it == found.end()) it = found.insert(found.end(), Sample{d, {}});
                passes_[p].placeBands(c, std::span<double>(it->bands.data(), it->bands.size()));
            });
        for (Sample& s : found) visit(s.dir, spectral::toRgb(span(s.bands.data()), sampling_));
    }
    uint64_t seed() const override { return rays_[0]->seed(); }

private:
    std::span<double> span(double* samples) const { return {samples, size_t(sampling_.n)}; }

    const std::vector<std::unique_ptr<render::IllumRayTracer>>& rays_;
    std::vector<spectral::Pass> passes_;
    spectral::Sampling sampling_;
};

OptionTable mkillumTable(MkillumOptions& o) {
    OptionTable t;
    t.expandArgs = true;
    // RADIANCE compat: mkillum takes no error file (getrenderopt has no -e).
    t.add(customOption("-e", [](OptionReader& r) -> void {
        throw InputError("unknown option '" + r.option() + "'");
    }));
    render::addRenderOptions(t, o.render);
    return t;
}

std::string joined(const std::vector<std::string>& words, size_t count) {
    std::string s;
    for (size_t i = 0; i < count && i < words.size(); ++i) s += (i ? " " : "") + words[i];
    return s;
}

}  // namespace

MkillumOptions mkillumDefaults() {
    MkillumOptions o;
    o.render.uncorrelated = true;
    o.render.direct.jitter = 0.5;
    o.render.direct.relays = 3;
    o.render.ambient.bounces = 2;
    return o;
}

MkillumOptions parseMkillumArgs(std::vector<std::string> args) {
    MkillumOptions o = mkillumDefaults();
    const OptionParse p = mkillumTable(o).parse(args, 1);
    o.printVersion = p.stop == OptionStop::kVersion;
    o.printDefaults = p.stop == OptionStop::kDefaults;
    if (p.stop == OptionStop::kEnd) {
        if (p.next >= args.size()) throw InputError("missing octree argument");
        o.octree = args[p.next];
        o.headerWords = p.next + 1;
        if (p.next + 1 < args.size()) {
            if (args[p.next + 1] != "<" || p.next + 2 >= args.size())
                throw InputError("use '< file1 file2 ..' for multiple inputs");
            o.inputs.assign(args.begin() + long(p.next) + 2, args.end());
        }
    }
    o.args = std::move(args);
    return o;
}

std::string formatMkillumDefaults(const MkillumOptions& o) {
    return formatSettings(IllumSettings{}) + render::formatRenderDefaults(o.render);
}

void runMkillum(const MkillumOptions& o, std::istream& in, std::ostream& out) {
    render::RenderOptions ro = o.render;
    ro.irradiance = false;  // RADIANCE compat (mkillum.c: do_irrad = 0 after the options)
    const auto threads = render::threadLimit(ro);
    const LoadOptions load = gen::builtinLoadOptions();
    const Scene scene = loadScene({o.octree}, load);
    const SceneGeometry geometry(scene);
    const spectral::Sampling sampling = render::spectralSampling(ro);
    const render::PassRenderers renderers = render::passRenderers(
        scene, geometry, ro, sampling, calc::defaultSearchPath(projectLibDir()));
    std::vector<std::unique_ptr<render::IllumRayTracer>> rays;
    for (const auto& r : renderers) rays.push_back(std::make_unique<render::IllumRayTracer>(*r));
    const RendererIllumTracer tracer(rays, sampling);
    IllumFilter filter(tracer, out, joined(o.args, o.headerWords), {}, load.commandHook);
    // Keep the ambient records computed so far, as rtrace does (each pass its own file).
    auto keepAmbient = [&] {
        for (const auto& r : renderers) r->flushAmbientFile();
    };
    try {
        if (o.inputs.empty()) {
            const std::string text{std::istreambuf_iterator<char>(in), {}};
            filter.process(text, "standard input");
        }
        for (const std::string& path : o.inputs) filter.process(readFileBytes(path), path);
    } catch (...) {
        keepAmbient();
        throw;
    }
    keepAmbient();
}

}  // namespace rp::illum
