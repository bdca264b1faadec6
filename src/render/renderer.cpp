#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_set>

#include "material/mist_probe.h"
#include "material/type_traits.h"
#include "render/rcontrib.h"
#include "render/renderer_impl.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::render {

namespace {

material::Medium globalMediumOf(const MistOptions& m) {
    return material::Medium{m.extinction, m.albedo, m.eccentricity};
}

// m_mist.c: each mist's string arguments name the sources that scatter into rays inside
// it (an object name; RADIANCE's "a>b" relayed virtual sources are not matched, as there
// are no virtual sources in the list of a mist's scene in photon-map mode either).
std::unordered_map<int32_t, std::vector<int32_t>> mistSourceLists(const Scene& scene,
                                                                  const DirectLighting& direct) {
    std::unordered_map<int32_t, std::vector<int32_t>> out;
    const SourceList& list = direct.sourceList();
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        const Primitive& p = scene.prims[i];
        if (!material::typeTraits(p.type).mist) continue;
        std::vector<int32_t>& ids = out[int32_t(i)];
        for (const std::string& name : p.sargs) {
            int32_t found = -1;
            for (size_t s = list.realCount; s-- > 0;) {
                int32_t prim = list.sources[s].light.prim;
                if (prim >= 0 && scene.prims[size_t(prim)].name == name) {
                    found = int32_t(s);
                    break;
                }
            }
            const std::string where = "mist '" + p.name + "': ";
            if (found < 0)
                warn(p.loc.str() + ": " + where + "unknown source \"" + name + "\"");
            else if (std::find(ids.begin(), ids.end(), found) != ids.end())
                warn(p.loc.str() + ": " + where + "duplicate source \"" + name + "\"");
            else if (ids.size() >= size_t(ScatterSources::kMax))
                throw InputError(p.loc, where + "more than " +
                                            std::to_string(ScatterSources::kMax) + " sources");
            else
                ids.push_back(found);
        }
    }
    return out;
}

// The -a options as used: photon-map mode fixes -ab (PhotonMode::ambientBounces).
AmbientOptions ambientOptionsIn(const RenderOptions& o, const PhotonMode& mode) {
    AmbientOptions a = o.ambient;
    a.bounces = mode.ambientBounces();
    return a;
}

// rcontrib: which light sources (light::findLightSources order, as a contribution map's
// primaries count them) have a tracked light material.
std::vector<bool> trackedLightSources(const Scene& s, const SceneGeometry& g,
                                      const RenderOptions& o) {
    std::vector<bool> out;
    if (!o.contributions || o.photonMaps.empty()) return out;
    const std::unordered_set<std::string> names(o.contribModifiers.begin(),
                                                o.contribModifiers.end());
    for (const PhotonSource& src : contributionSources(s, g))
        out.push_back(names.count(src.material) != 0);
    return out;
}

// How the photon maps' stores are sized (-ac, -aC, -n).
pmap::StoreOptions photonStoreOptions(const RenderOptions& o) {
    pmap::StoreOptions s;
    s.cachePhotons = o.photonCache;
    s.pageSize = o.photonPageSize;
    s.threads = std::max(1, o.threads);
    return s;
}

}  // namespace

Renderer::Impl::Impl(const Scene& s, const SceneGeometry& g, const RenderOptions& o,
                     std::vector<std::string> searchPath)
    : scene(s),
      geometry(g),
      options(o),
      chains(s, searchPath, o.pass),
      materialCalc(s, std::move(searchPath), o.pass),
      trackedSources(trackedLightSources(s, g, o)),
      photons(o.photonMaps, o.photonMaxRadius, s, o.contributions ? &trackedSources : nullptr,
              photonStoreOptions(o), o.contribModifiers),
      photonMode(photons.kinds(), o.ambient.bounces),
      ambientOptions(ambientOptionsIn(o, photonMode)),
      direct(
          s, g, o.direct, photonMode.virtualSources(),
          [this](const Hit& hit, const Vec3& dir, int projection, const Vec3& toSource) {
              material::MaterialCalcEvaluator ev(materialCalc);
              return evalRedirect(chains.materials(), materialCalc, ev, hit, dir, projection,
                                  toSource);
          },
          globalMediumOf(o.mist)),
      ambient(ambientOptions, g.sceneCube().size, s, o.limits.minWeight),
      antimatter(s, true),
      globalMedium(globalMediumOf(o.mist)),
      mistSources(mistSourceLists(s, direct)),
      hasMists(material::sceneHasMist(s)) {
    prepares.resize(s.prims.size());
    for (size_t i = 0; i < s.prims.size(); ++i)
        prepares[i] = chains.materials().usable(int32_t(i)) &&
                      material::needsPreparation(&materialCalc, int32_t(i),
                                                 *chains.materials()[int32_t(i)].params);
    // Every surface's chain must be evaluable (RADIANCE checks modifiers as it loads).
    for (const Primitive& p : s.prims)
        if (isSurface(p.type) && p.type != PrimType::Source) chains.checkChain(p.modifier);
    // -u+: a new random base per run (RADIANCE's uncorrelated sampling); -u-: fixed, so
    // that a ray's result depends only on its input position.
    seed = o.uncorrelated ? (uint64_t(std::random_device{}()) << 32 | std::random_device{}()) : 0;
    shadeOptions.specThreshold = o.specular.threshold;
    shadeOptions.specJitter = o.specular.sampling;
    shadeOptions.minWeight = o.limits.minWeight;
    shadeOptions.backVisible = o.backVisible;
}

Renderer::Renderer(const Scene& scene, const SceneGeometry& geometry, const RenderOptions& options,
                   std::vector<std::string> searchPath)
    : scene_(scene), geometry_(geometry), options_(options) {
    // A spectral sampling is rendered in passes (passOptions), which rtrace, rpict and
    // rcontrib run; the other tools render RGB.
    if (options.spectralSamples > 3 && options.pass.sampling.isRgb())
        throw InputError(
            "-cs above 3: this program renders RGB only (rtrace, rpict and rcontrib render "
            "spectra)");
    impl_ = std::make_unique<Impl>(scene_, geometry_, options_, std::move(searchPath));
}

Renderer::~Renderer() = default;

Renderer::ContextPtr Renderer::makeContext() const {
    ContextPtr ctx(new Context(*this, *impl_));
    if (impl_->photons.active()) ctx->photonLookups = impl_->photons.makeLookups();
    return ctx;
}

void Renderer::ContextDeleter::operator()(Context* c) const { delete c; }

const PhotonLighting& Renderer::photons() const { return impl_->photons; }

RayResult Renderer::trace(Context& ctx, const Vec3& origin, const Vec3& dir, uint64_t rayIndex,
                          std::vector<TracedRay>* tree, double maxDistance,
                          ContributionSink* contrib) const {
    ctx.rng = Rng(impl_->seed, RngDomain::Sampling, rayIndex);
    if (ctx.photonLookups) ctx.photonLookups->startRay();  // like the random numbers
    ctx.tree = tree;
    ctx.treeDepth = 0;
    RayResult result;
    result.origin = origin;
    result.direction = dir;
    RayState state;
    state.irradianceHit = options_.irradiance;
    state.contrib = contrib;
    const std::optional<MediaState> start = ctx.mediaAt(origin);
    if (start) state.media = &*start;
    double distance = 1e10;
    result.value = ctx.radiance(Ray{origin, dir, maxDistance}, state, &result, distance);
    ctx.tree = nullptr;
    return result;
}

Color Renderer::traceToSource(Context& ctx, size_t source, const Vec3& origin, const Vec3& dir,
                              uint64_t rayIndex, double* distance) const {
    ctx.rng = Rng(impl_->seed, RngDomain::Sampling, rayIndex);
    impl_->rays.fetch_add(1, std::memory_order_relaxed);
    RayState state;  // a primary ray's: no clipping, no ambient level
    const std::optional<MediaState> media = ctx.mediaAt(origin);
    DirectPoint at;
    at.point = origin;
    at.normal = at.geomNormal = dir;
    at.medium = media ? &media->medium : &impl_->globalMedium;
    at.shadow = ctx.shadowStart(state);
    return impl_->direct.traceToward(source, at, dir, ctx, distance);
}

const SourceList& Renderer::directSources() const { return impl_->direct.sourceList(); }

RayResult Renderer::irradiance(Context& ctx, const Vec3& point, const Vec3& normal,
                               uint64_t rayIndex, ContributionSink* contrib) const {
    ctx.rng = Rng(impl_->seed, RngDomain::Sampling, rayIndex);
    if (ctx.photonLookups) ctx.photonLookups->startRay();
    RayResult result;
    result.origin = point;
    result.direction = normal;
    Vec3 n = normalize(normal);
    // RADIANCE's rtrace -I evaluates the pretend surface 1e-4 in front of the given
    // point (rop = org + 1e-4 dir), and -op prints that point. It matters for photon
    // lookups on the surface itself: at a sharp caustic the 50 nearest photons lie
    // within ~0.1 mm, so this offset sets the search radius (caustic README: 114 W/m2
    // at the focus with the offset, ~330 without).
    const Vec3 at = point + n * kIrradianceOffset;
    Hit hit;
    hit.point = at;
    hit.normal = n;
    hit.front = true;
    hit.t = 0;
    hit.offset = std::fmax(maxAbs(at), 1e-3) * kFloatOffsetRel;
    result.hit = true;
    result.distance = result.effectiveLength = 0;
    result.point = at;
    result.normal = result.unperturbedNormal = n;
    const std::optional<MediaState> around = ctx.mediaAt(at);
    RayState state;
    state.media = around ? &*around : nullptr;
    state.contrib = contrib;
    result.value = ctx.irradianceAt(hit, n, state);
    return result;
}

long Renderer::raysTraced() const { return impl_->rays.load(std::memory_order_relaxed); }

long Renderer::ambientRecords() const { return impl_->ambient.recordCount(); }

void Renderer::flushAmbientFile() const { impl_->ambient.save(); }

}  // namespace rp::render
