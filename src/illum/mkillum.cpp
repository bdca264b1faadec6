// mkillum's command line and run (see mkillum.h).
#include "illum/mkillum.h"

#include <iterator>

#include "calc/search_path.h"
#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "illum/illum_filter.h"
#include "render/illum_rays.h"
#include "render/renderer.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/file_read.h"
#include "util/options.h"
#include "util/paths.h"

namespace rp::illum {

namespace {

// The renderer as the sampling sees it.
class RendererIllumTracer : public IllumTracer {
public:
    explicit RendererIllumTracer(const render::IllumRayTracer& rays)
        : rays_(rays), seed_(rays.seed()) {}
    Color radiance(const Vec3& origin, const Vec3& dir, uint64_t rayIndex) const override {
        return rays_.radiance(origin, dir, rayIndex);
    }
    void sourceSamples(const Vec3& point, double offset, uint64_t rayIndex,
                       const SourceVisit& visit) const override {
        rays_.sourceSamples(point, offset, rayIndex, visit);
    }
    uint64_t seed() const override { return seed_; }

private:
    const render::IllumRayTracer& rays_;
    uint64_t seed_;
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
    const render::Renderer renderer(scene, geometry, ro, calc::defaultSearchPath(projectLibDir()));
    const render::IllumRayTracer rays(renderer);
    const RendererIllumTracer tracer(rays);
    IllumFilter filter(tracer, out, joined(o.args, o.headerWords), {}, load.commandHook);
    try {
        if (o.inputs.empty()) {
            const std::string text{std::istreambuf_iterator<char>(in), {}};
            filter.process(text, "standard input");
        }
        for (const std::string& path : o.inputs) filter.process(readFileBytes(path), path);
    } catch (...) {
        renderer.flushAmbientFile();  // keep the records computed so far, as rtrace does
        throw;
    }
    renderer.flushAmbientFile();
}

}  // namespace rp::illum
