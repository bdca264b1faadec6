// Participating media along backward rays (RADIANCE raytrace.c rayparticipate,
// source.c srcscatter, m_mist.c): extinction over each ray segment and the light
// scattered into it at -ms spaced, jittered points: from the sources a mist names plus
// the ambient value (-av), or, with a volume photon map, from the volume photons alone.
#include <algorithm>
#include <cmath>

#include "material/mist_probe.h"
#include "render/renderer_impl.h"
#include "util/henyey_greenstein.h"

namespace rp::render {

namespace {

constexpr int kMaxScatterSamples = 16;  // RADIANCE MAXSSAMP: per ray segment and source

// Samples along a segment of length t (RADIANCE srcscatter: -ms apart, at most
// MAXSSAMP, at least one).
int scatterSamples(double t, double spacing) {
    int n = spacing <= kFtiny ? 1 : int(t / spacing + 0.5);
    return std::clamp(n, 1, kMaxScatterSamples);
}

}  // namespace

Color Renderer::Context::participate(const Ray& ray, double t, const RayState& state,
                                     Color& transmit) {
    const material::Medium& m = mediumOf(state);
    transmit = m.transmittance(t);
    if (!m.scatters()) return {};
    if (impl.photonMode.volumeFromPhotons() && photonLookups) return volumeScatter(ray, t, state);
    Color in;
    // Indirect light scattered in: the ambient value over the segment (rayparticipate).
    in += m.albedo * impl.options.ambient.value * (Color{1, 1, 1} - transmit);
    in += sourceScatter(ray, t, state);
    return in;
}

Color Renderer::Context::volumeScatter(const Ray& ray, double t, const RayState& state) {
    // RADIANCE compat (srcscatter with a volume map): the volume photons, stored at every
    // collision including the first, stand for the direct and the indirect in-scattering
    // alike, so neither the named sources nor the ambient value are added, and every
    // scattering medium is lit whether or not a mist names sources. The manual's text
    // (4.5: volume photons "complement the direct inscattering") predates that code.
    // The estimate is flux per volume over extinction (pmap::PhotonLookup::volumeDensity),
    // so it is multiplied by the albedo only. RADIANCE also multiplies by the extinction,
    // which puts its estimate at extinction times the closed form (0.1 of it at 0.1 /m in
    // tests/data/mist/single.rad; golden.mist_analytic checks ours).
    const material::Medium& m = mediumOf(state);
    if (!(t < 0.99e10) || m.eccentricity >= 1 - kFtiny) return {};
    const int n = scatterSamples(t, impl.options.mist.samplingDistance);
    Color total;
    for (int j = 0; j < n; ++j) {
        const double tj = t * (j + rng.uniform()) / n;
        const Color toPoint = m.transmittance(tj);
        if (toPoint.brightness() <= kFtiny) break;
        const Vec3 p = ray.origin + ray.dir * tj;
        total += impl.photons.volumeDensity(*photonLookups, p, -ray.dir, m.eccentricity) * toPoint;
    }
    return total * m.albedo * (t / n);
}

Color Renderer::Context::sourceScatter(const Ray& ray, double t, const RayState& state) {
    if (!state.media) return {};  // in the global medium only: no mist names sources
    const material::Medium& m = state.media->medium;
    const ScatterSources& sources = state.media->scatter;
    // A ray that left the scene has no length to sample; HG with g -> 1 is a delta.
    if (!(t < 0.99e10) || m.eccentricity >= 1 - kFtiny || sources.count == 0) return {};
    const int n = scatterSamples(t, impl.options.mist.samplingDistance);
    Color total;
    DirectPoint at;
    at.transmits = true;
    at.weight = state.weight;
    at.medium = &m;
    at.shadow = shadowStart(state);
    for (int i = 0; i < sources.count; ++i) {
        const size_t source = size_t(sources.index[size_t(i)]);
        for (int j = 0; j < n; ++j) {
            const double tj = t * (j + rng.uniform()) / n;
            const Color toPoint = m.transmittance(tj);  // from the ray's origin
            if (toPoint.brightness() <= kFtiny) break;  // too far in
            at.point = ray.origin + ray.dir * tj;
            at.normal = at.geomNormal = -ray.dir;
            Vec3 toLight;
            Color l = impl.direct.sampleWhole(source, at, *this, rng, toLight);
            if (l.brightness() <= kFtiny) continue;
            // Light travelling along -toLight scattered into -ray.dir: cos theta is
            // dot(toLight, ray.dir).
            const double p = henyeyGreenstein4Pi(m.eccentricity, dot(ray.dir, toLight));
            total += l * m.extinction * m.albedo * toPoint * (p * t / (4 * kPi * n));
        }
    }
    return total;
}

void Renderer::Context::cross(MediaState& state, const Passage& passage,
                              MediaState& segment) const {
    using K = material::MediumChange::Kind;
    const material::MediumChange& c = passage.crossing;
    const std::vector<int32_t>& mine = impl.mistSources.at(passage.mist);
    const material::MistParams* mist = passage.mistParams;
    if (c.kind == K::EnterMist) {
        state.mists.enter(passage.mist);
        state.medium = material::changeMedium(state.medium, c, impl.globalMedium, mist);
        addSources(state.scatter, passage.mist);
        return;
    }
    if (!state.mists.leave(passage.mist)) {
        // Leaving a mist it never entered, the ray started inside it (m_mist.c "fix old"):
        // the segment just travelled was in that medium, lit by its sources. RADIANCE
        // compat, except that it is the mist that counts, not its sources: RADIANCE does
        // this only for a mist that names sources, leaving a view inside a plain fog box
        // without extinction up to the box's wall.
        material::MediumChange enter = c;
        enter.kind = K::EnterMist;
        segment.medium = material::changeMedium(segment.medium, enter, impl.globalMedium, mist);
        addSources(segment.scatter, passage.mist);
        state.medium = segment.medium;
    }
    state.medium = material::changeMedium(state.medium, c, impl.globalMedium, mist);
    int kept = 0;
    for (int i = 0; i < state.scatter.count; ++i) {
        int32_t s = state.scatter.index[size_t(i)];
        if (std::find(mine.begin(), mine.end(), s) == mine.end())
            state.scatter.index[size_t(kept++)] = s;
    }
    state.scatter.count = kept;
}

void Renderer::Context::addSources(ScatterSources& to, int32_t mist) const {
    for (int32_t s : impl.mistSources.at(mist))
        if (!to.contains(s) && to.count < ScatterSources::kMax) to.index[size_t(to.count++)] = s;
}

std::optional<MediaState> Renderer::Context::mediaAt(const Vec3& p) {
    if (!impl.hasMists) return std::nullopt;
    const std::vector<material::EnclosingMist> around =
        material::enclosingMists(impl.geometry, impl.chains, p, rng);
    if (around.empty()) return std::nullopt;
    MediaState m{impl.globalMedium, {}, {}};
    m.medium = material::mediumWithin(around, impl.globalMedium, impl.chains.materials(), m.mists);
    for (const material::EnclosingMist& e : around) addSources(m.scatter, e.material);
    return m;
}

}  // namespace rp::render
