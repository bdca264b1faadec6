// mkpmap -apE: the classic calculation behind a port's exterior table (port_exterior.h).
#include "render/port_exterior.h"

#include <memory>

#include "render/renderer.h"

namespace rp::render {

RenderOptions portExteriorOptions() {
    RenderOptions o;
    o.ambient.bounces = 2;
    o.ambient.divisions = 128;
    o.ambient.supersamples = 32;
    o.ambient.accuracy = 0.1;
    o.ambient.resolution = 512;
    o.limits.minWeight = 1e-3;
    o.direct.jitter = 0;
    o.uncorrelated = false;
    o.threads = 1;
    return o;
}

namespace {

// The options as the pass renders them.
RenderOptions inPass(RenderOptions o, const spectral::Pass& pass) {
    o.spectralSamples = pass.sampling.n;
    return passOptions(o, pass);
}

// What the direct calculation counts and a global photon must not: the light sources'
// own irradiance. The same settings as the full calculation but no ambient bounce, so
// that the difference of the two is the ambient part (the same shadow rays either way).
RenderOptions directOnly(const spectral::Pass& pass) {
    RenderOptions o = inPass(portExteriorOptions(), pass);
    o.ambient.bounces = 0;
    return o;
}

bool emitsPhotons(PrimType t) {
    return t == PrimType::Light || t == PrimType::Glow || t == PrimType::Spotlight;
}

}  // namespace

light::PortExterior portExterior(const Scene& scene, const SceneGeometry& geometry,
                                 std::vector<std::string> searchPath, const spectral::Pass& pass) {
    struct State {
        Renderer full, direct;
        Renderer::ContextPtr fullContext, directContext;
        State(const Scene& s, const SceneGeometry& g, const std::vector<std::string>& path,
              const spectral::Pass& p)
            : full(s, g, inPass(portExteriorOptions(), p), path),
              direct(s, g, directOnly(p), path),
              fullContext(full.makeContext()),
              directContext(direct.makeContext()) {}
    };
    auto state = std::make_shared<State>(scene, geometry, searchPath, pass);
    light::PortExterior e;
    e.view = [state, &scene](const Vec3& from, const Vec3& w, uint64_t index) {
        light::ExteriorView v;
        const RayResult r = state->full.trace(*state->fullContext, from, w, index);
        // The sky and the sun (distant sources) are emitted through the port by their own
        // groups, light sources and glows outside by theirs.
        if (!r.hit || r.distantSource || r.material < 0 ||
            emitsPhotons(scene.prims[size_t(r.material)].type))
            return v;
        v.surface = true;
        v.radiance = r.value;
        v.point = r.point;
        v.normal = dot(r.unperturbedNormal, w) > 0 ? -r.unperturbedNormal : r.unperturbedNormal;
        v.distance = r.distance;
        const Color all =
            state->full.irradiance(*state->fullContext, v.point, v.normal, index).value;
        const Color own =
            state->direct.irradiance(*state->directContext, v.point, v.normal, index).value;
        for (int c = 0; c < 3; ++c) v.ambient[c] = std::fmax(0.0, all[c] - own[c]);
        return v;
    };
    return e;
}

}  // namespace rp::render
