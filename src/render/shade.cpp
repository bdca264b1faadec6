// The shading loop of the backward pass (RADIANCE raytrace.c, rayshade and the m_*
// material routines): a ray meets a surface, the modifier chain gives material layers,
// each layer adds emission, ideal/sampled specular rays, direct light and indirect
// (ambient) light. Shadow rays and hemisphere samples are in shadow.cpp.
#include <cmath>

#include "light/light_sources.h"
#include "render/renderer_impl.h"
#include "render/surface_coverage.h"
#include "util/error.h"

namespace rp::render {

namespace {

// The hit's geometric normal on the side of `normal` (the side the light comes from).
Vec3 planeNormal(const Hit& hit, const Vec3& normal) {
    return dot(normal, hit.normal) >= 0 ? hit.normal : -hit.normal;
}

bool isPlanar(PrimType t) { return t == PrimType::Polygon || t == PrimType::Ring; }

constexpr double kNoHit = 1e10;

// What rtrace reports of the first surface a ray meets (-o p n N s m M ...); `normal` is
// the perturbed one as RADIANCE reports it (ron + pert, after the material turned the
// surface toward the ray, MaterialRecord::reorientsBackHits).
void recordFirst(RayResult* f, const Hit& hit, const Vec3& normal, int32_t material) {
    if (!f || f->hit) return;
    f->hit = true;
    f->distance = f->effectiveLength = hit.t;
    f->point = hit.point;
    f->normal = normal;
    f->unperturbedNormal = hit.normal;
    f->u = hit.u;
    f->v = hit.v;
    f->prim = hit.prim;
    f->modifier = hit.modifier;
    f->material = material;
}

// The state a mixture's layer `i` is shaded in: its weight joins the path coefficient
// (rcontrib). `storage` holds the copy when one is needed.
const RayState& layerState(const RayState& state, const material::ChainResult& chain, int i,
                           std::optional<RayState>& storage) {
    if (!state.contrib || chain.count < 2) return state;
    storage = state;
    storage->contribCoef = state.contribCoef * chain.layers[size_t(i)].weight;
    return *storage;
}

// The function-space view of a hit that patterns and material functions see.
material::PatternPoint patternPoint(const Hit& hit, const Vec3& dir) {
    return material::PatternPoint::atHit(dir, hit);
}

}  // namespace

material::Redirection evalRedirect(const material::MaterialTable& materials,
                                   const material::MaterialCalc& calc,
                                   material::MaterialCalcEvaluator& ev, const Hit& hit,
                                   const Vec3& dir, int projection, const Vec3& toSource) {
    const int32_t mat = chainMaterial(materials.scene(), hit.modifier);
    if (!materials.usable(mat)) return {};
    return material::prismRedirect(calc, ev, mat, *materials[mat].params, patternPoint(hit, dir),
                                   projection, toSource);
}

Renderer::Context::Context(const Renderer& r, const Impl& i)
    : renderer(r), impl(i), evaluators(&i.materialCalc, i.chains) {}

void Renderer::Context::prepareHit(int32_t material, const material::MaterialParams& params,
                                   const Hit& hit, const Vec3& dir, material::SurfacePoint& sp,
                                   std::optional<material::HitScratch>& scratch) {
    material::prepareHit(evaluators, material, params, patternPoint(hit, dir), sp,
                         scratch.emplace(), rng);
}

ShadowPath Renderer::Context::shadowStart(const RayState& state) const {
    return ShadowPath{state.clip, impl.photonMode.shadowsStopAtTransparent(state.pathDepth())};
}

material::ChainResult Renderer::Context::resolve(int32_t modifier, const Hit& hit,
                                                 const Vec3& dir) {
    material::ChainResult r =
        impl.chains.isPlain(modifier)
            ? material::ChainResult::plain(impl.chains.plainMaterial(modifier))
            : evaluators.chains().resolve(modifier, patternPoint(hit, dir), rng);
    // RADIANCE compat (o_mesh.c): a mesh's vertex normals perturb the surface first,
    // textures add to that.
    if (lengthSquared(hit.perturbation) > 0)
        for (int i = 0; i < r.count; ++i) r.layers[size_t(i)].perturbation += hit.perturbation;
    return r;
}

Color Renderer::Context::radiance(const Ray& ray, const RayState& state, RayResult* first,
                                  double& distance, Vec3* hitNormal) {
    impl.rays.fetch_add(1, std::memory_order_relaxed);
    // For the ray tree (rtrace -o...t), every ray records what it hits the way the input
    // ray does (fillFirst in shadeLayer), in a record of its own.
    RayResult treeRecord;
    RayResult* record = first ? first : tree ? &treeRecord : nullptr;
    Ray r = ray;
    double travelled = 0;
    Color total, coef{1, 1, 1};
    distance = kNoHit;
    // The state of the ray as it goes on: crossing antimatter changes its clip set
    // (RADIANCE's transferred ray takes the antimatter hit's newcset).
    RayState cur = state;
    std::optional<MediaState> crossed;  // cur.media once it crossed a mist boundary
    // Transparent surfaces (antimatter, void mixtures, invisible illums) pass the ray on;
    // bounded so that a pathological stack of them cannot loop.
    for (int pass = 0; pass < 64; ++pass) {
        if (state.contrib) cur.contribCoef = state.contribCoef * coef;
        std::optional<Hit> hit = impl.geometry.closestHit(r);
        Color transmit{1, 1, 1};
        if (!hit) {
            // A ray with a length limit (rtrace -ld) that ends short of every surface is
            // clipped: RADIANCE gives it no value, not the sources or sky behind.
            Color c = r.tmax < HUGE_VAL ? Color{} : escaped(r, cur, record);
            if (mediumOf(cur).active()) total += coef * participate(r, HUGE_VAL, cur, transmit);
            total += coef * transmit * c;
            break;
        }
        Color passWeight;
        Color c;
        Passage passage;
        if (cur.clip.contains(hit->modifier)) {
            passWeight = Color{1, 1, 1};  // inside antimatter that clips it: invisible
        } else if (const auto* clips = impl.antimatter.clips(hit->modifier)) {
            cur.clip.cross(*clips, hit->front);
            passWeight = Color{1, 1, 1};
        } else {
            c = shadeHit(r, *hit, cur, record, passWeight, passage);
            // RADIANCE compat (rcontrib.c trace_contrib): a tracked surface reports what
            // the ray brings back from it.
            if (cur.contrib && !passage.uncounted && cur.contrib->tracks(hit->modifier))
                cur.contrib->add(hit->modifier, hit->point, r.dir, cur.contribCoef, c);
        }
        if (passage.mist >= 0) {
            MediaState segment = mediaOf(cur);  // cross may learn that it was a mist
            MediaState after = segment;
            cross(after, passage, segment);
            RayState travelledIn = cur;
            travelledIn.media = &segment;
            if (segment.medium.active())
                total += coef * participate(r, hit->t, travelledIn, transmit);
            crossed = after;
            cur.media = &*crossed;
        } else if (mediumOf(cur).active()) {
            total += coef * participate(r, hit->t, cur, transmit);
        }
        total += coef * transmit * c;
        if (passWeight.max() <= 0) {
            distance = travelled + hit->t;
            if (hitNormal) *hitNormal = hit->normal;
            break;
        }
        coef *= passWeight * transmit;
        travelled += hit->t;
        r = spawnRay(*hit, r.dir);
        if (ray.tmax < HUGE_VAL) r.tmax = std::max(0.0, ray.tmax - travelled);
    }
    if (tree) {
        // RADIANCE compat (raytrace.c, rtrace.c ourtrace): a ray is reported once its
        // value is known, so the rays it spawned come before it.
        TracedRay t;
        t.depth = state.generation;
        t.result = *record;
        t.result.origin = ray.origin;
        t.result.direction = ray.dir;
        t.result.weight = state.weight;
        t.result.value = total;
        t.result.distance = distance;
        tree->push_back(t);
    }
    return total;
}

Color Renderer::Context::shadeHit(const Ray& ray, const Hit& hit, const RayState& state,
                                  RayResult* first, Color& passWeight, Passage& passage) {
    material::ChainResult chain = resolve(hit.modifier, hit, ray.dir);
    Color value;
    std::optional<RayState> weighted;  // a mixture's layer: its weight in the path coefficient
    for (int i = 0; i < chain.count; ++i) {
        const material::ShadingLayer& layer = chain.layers[size_t(i)];
        bool pass = false;
        Color c = shadeLayer(ray, hit, layerState(state, chain, i, weighted), layer, first, pass,
                             passage);
        value += c * layer.weight;
        if (pass) passWeight += Color{1, 1, 1} * layer.weight;
    }
    return value;
}

Color Renderer::Context::shadeLayer(const Ray& ray, const Hit& hit, const RayState& state,
                                    const material::ShadingLayer& layer, RayResult* first,
                                    bool& passThrough, Passage& passage) {
    if (layer.material == kVoid) {
        // RADIANCE compat (raytrace.c raytrans): the ray reports the surface it passed.
        recordFirst(first, hit, hit.normal, kVoid);
        passThrough = true;
        return {};
    }
    const material::MaterialRecord& e = impl.material(layer.material);
    const material::MaterialParams& params = *e.params;
    material::SurfacePoint sp = surfaceAt(hit, ray.dir, layer);
    sp.flat = isPlanar(impl.scene.prims[size_t(hit.prim)].type);
    sp.scatteredRay = state.indirect;
    sp.specularInPhotons = impl.photonMode.specularDirectInPhotons(state.pathDepth());
    sp.rayWeight = state.weight;
    sp.specJitter = impl.shadeOptions.specJitter;
    if (e.isLight) return shadeLight(ray, hit, state, layer, e, sp, first, passThrough, passage);

    if (state.irradianceHit) {
        if (e.passesIrradiance) {
            passThrough = true;
            return {};
        }
        // -i: the first surface is white Lambertian (RADIANCE's plastic Lamb, which faces
        // the ray); the value is its irradiance.
        recordFirst(first, hit, sp.normal, layer.material);
        return irradianceAt(hit, sp.normal, state);
    }

    std::optional<material::HitScratch> scratch;
    prepare(layer.material, params, hit, ray.dir, sp, scratch);
    const material::BackwardResult b = material::shadeBackward(params, sp, impl.shadeOptions, rng);
    // ray.html mirror: with an alternate material the mirror only relays sources
    // (virtual sources); every other ray sees the alternate.
    if (b.useAlternate)
        return shadeAlternate(ray, hit, state, e.alternate, first, passThrough, passage);
    if (b.transparent) {
        if (b.mist) {
            // m_mist.c: the ray goes on in the medium it enters or returns to.
            recordFirst(first, hit, hit.normal, layer.material);
            passage.crossing = b.passMedium;
            passage.mist = layer.material;
            passage.mistParams = b.mist;
        }
        passThrough = true;
        return {};
    }
    const Vec3& n = sp.normal;
    recordFirst(first, hit, hit.front || e.reorientsBackHits ? n : -n, layer.material);
    // Terms added one by one in RADIANCE's order (the sums' rounding is part of the result).
    Color value = b.emitted;
    addSpecularRays(hit, state, b, first, value);
    if (e.diffuseLike) addDirect(hit, params, sp, b, state, value);
    Hit farSide = hit;  // where light from behind is gathered (BackwardResult::transmitOffset)
    farSide.point += hit.normal * b.transmitOffset;
    if (b.ambientReflect.max() > 0)
        value += b.ambientReflect * ambientAt(hit, n, layer.material, state, b.ambientReflect);
    if (b.ambientTransmit.max() > 0)
        value +=
            b.ambientTransmit * ambientAt(farSide, -n, layer.material, state, b.ambientTransmit);
    if (first && first->prim == hit.prim && state.primary) {
        first->unmirrored = value - first->mirrored;
        first->unmirroredLength = hit.t;
    }
    return value;
}

Color Renderer::Context::shadeLight(const Ray& ray, const Hit& hit, const RayState& state,
                                    const material::ShadingLayer& layer,
                                    const material::MaterialRecord& e,
                                    const material::SurfacePoint& sp, RayResult* first,
                                    bool& passThrough, Passage& passage) {
    const Vec3& n = sp.normal;
    const material::BackwardResult b =
        material::shadeBackward(*e.params, sp, impl.shadeOptions, rng);
    if (b.uncounted) {  // seen by an indirect ray: the direct calculation counts it
        recordFirst(first, hit, hit.front || e.reorientsBackHits ? n : -n, layer.material);
        passage.uncounted = true;
        return {};
    }
    if (b.useAlternate || b.transparent) {
        // ray.html illum: seen directly (or by specular rays) it is its alternate.
        return shadeAlternate(ray, hit, state, e.alternate, first, passThrough, passage);
    }
    recordFirst(first, hit, hit.front || e.reorientsBackHits ? n : -n, layer.material);
    if (!state.indirect && !impl.options.direct.visibility &&
        impl.direct.isSourceSurface(hit.prim, ray.origin)) {  // -dv-
        passage.uncounted = true;
        return {};
    }
    return b.emitted;
}

void Renderer::Context::addSpecularRays(const Hit& hit, const RayState& state,
                                        const material::BackwardResult& b, RayResult* first,
                                        Color& value) {
    // RADIANCE's rayorigin rules for -lr and -lw; in photon-map mode an ambient ray's
    // specular children may be in the photons already (PhotonMode).
    if (impl.photonMode.specularRaysInPhotons(state.pathDepth())) return;
    const LimitOptions& lim = impl.options.limits;
    std::optional<MediaState> childMedia;  // of a child entering or leaving a dielectric
    for (int i = 0; i < b.numRays; ++i) {
        const material::SpecularRay& sr = b.rays[size_t(i)];
        Color rc = sr.weight;
        RayState child = state;  // the clip set too
        // RADIANCE compat (raytrace.c rayorigin): reflected and sampled rays count towards
        // -lr (RAYREFL); light passing on through a surface, straight or refracted (TRANS,
        // REFRACTED: glass, dielectric, trans, prisms, a BSDF's direct component), keeps
        // its parent's level. Counted, the sky behind a window went dark for rays near
        // the limit (a ceiling record at -lr 8 read 1 % of its neighbours), and a final
        // gather through double glazing stopped at the second pane.
        const bool passesOn = sr.kind == material::ScatterKind::SpecularTransmission && !sr.sampled;
        child.depth = state.depth + (passesOn ? 0 : 1);
        child.generation = state.generation + 1;
        child.transits = passesOn ? state.transits + 1 : 0;
        if (child.transits > kMaxTransits) continue;
        child.weight = state.weight * material::spawnedWeight(rc);
        child.primary = false;
        child.irradianceHit = false;
        child.indirect = state.indirect || sr.sampled;
        child.contribCoef = state.contribCoef * rc * sr.valueFactor;
        if (sr.medium.kind != material::MediumChange::Kind::Unchanged) {
            childMedia = mediaOf(state);
            childMedia->medium =
                material::changeMedium(childMedia->medium, sr.medium, impl.globalMedium);
            child.media = &*childMedia;
        }
        if (child.weight <= 0) continue;
        if (lim.maxDepth > 0) {
            if (child.depth > lim.maxDepth || child.weight < lim.minWeight) continue;
        } else {
            if (lim.maxDepth < 0 && child.depth > -lim.maxDepth) continue;
            if (child.weight < lim.minWeight) {
                double p = child.weight / lim.minWeight;
                if (rng.uniform() >= p) continue;
                rc = rc / p;  // promote the survivor (Russian roulette)
                child.weight = lim.minWeight;
                child.contribCoef = state.contribCoef * rc * sr.valueFactor;
            }
        }
        Ray out = spawnRay(hit, sr.dir);
        if (sr.kind == material::ScatterKind::SpecularTransmission && b.transmitOffset != 0)
            out.origin += hit.normal * b.transmitOffset;
        double d = kNoHit;
        // valueFactor: 1 but for several samples of a rough reflection (SpecularRay).
        Color contrib = rc * radiance(out, child, nullptr, d) * sr.valueFactor;
        value += contrib;
        if (first && first->prim == hit.prim && state.primary &&
            sr.kind == material::ScatterKind::SpecularReflection && !sr.sampled) {
            first->mirrored += contrib;
            first->mirroredLength = hit.t + d;
        }
    }
}

void Renderer::Context::addDirect(const Hit& hit, const material::MaterialParams& params,
                                  const material::SurfacePoint& sp,
                                  const material::BackwardResult& b, const RayState& state,
                                  Color& value) {
    if (impl.photonMode.directFromPhotons()) {
        const SurfaceCoverage coverage(impl.chains.materials(), impl.geometry, hit,
                                       planeNormal(hit, sp.normal));
        value += b.ambientReflect *
                 impl.photons.directDensity(*photonLookups, hit.point, sp.normal, &coverage);
        return;
    }
    const bool transmits = b.ambientTransmit.max() > 0 || b.directFromBehind;
    if (b.transmitOffset == 0) {
        value += directAt(hit, params, sp, transmits, state);
        return;
    }
    // m_bsdf.c: reflected light here, transmitted light from the far point.
    Hit farSide = hit;
    farSide.point += hit.normal * b.transmitOffset;
    value += directAt(hit, params, sp, false, state);
    if (transmits) value += directAt(farSide, params, sp, true, state, true);
}

Color Renderer::Context::shadeAlternate(const Ray& ray, const Hit& hit, const RayState& state,
                                        int32_t alternate, RayResult* first, bool& passThrough,
                                        Passage& passage) {
    if (alternate == kVoid) {  // "void": the surface is invisible to this ray
        passThrough = true;
        return {};
    }
    material::ChainResult c = resolve(alternate, hit, ray.dir);
    Color v;
    std::optional<RayState> weighted;
    for (int i = 0; i < c.count; ++i) {
        bool p = false;
        v += shadeLayer(ray, hit, layerState(state, c, i, weighted), c.layers[size_t(i)], first, p,
                        passage) *
             c.layers[size_t(i)].weight;
        if (p) passThrough = true;
    }
    return v;
}

Color Renderer::Context::directAt(const Hit& hit, const material::MaterialParams& params,
                                  const material::SurfacePoint& sp, bool transmits,
                                  const RayState& state, bool behindOnly) {
    DirectPoint at;
    at.weight = state.weight;
    at.contrib = state.contrib;
    at.contribCoef = state.contribCoef;
    at.medium = &mediumOf(state);
    at.scatterLoss = impl.photonMode.mediumScatterInPhotons();
    at.shadow = shadowStart(state);
    at.generation = state.generation;
    at.point = hit.point;
    at.normal = sp.normal;
    at.geomNormal = sp.geomNormal;
    at.hit = &hit;
    at.transmits = transmits;
    return impl.direct.compute(
        at,
        [&](const Vec3& toLight, double omega) {
            if (behindOnly && dot(sp.normal, toLight) >= 0) return Color{};
            return material::evaluate(params, sp, toLight, omega);
        },
        *this, rng, directScratch);
}

namespace {

// RADIANCE compat (ambient.c plugaleak): a cached record plugged by the first surface on
// the test segment that stops light (MaterialRecord::plugsLeaks), unless the query
// ray's antimatter hides it.
class QueryLeakTest final : public LeakTest {
public:
    QueryLeakTest(const material::MaterialTable& materials, const SceneGeometry& geometry,
                  const ClipSet& clip)
        : materials_(materials), geometry_(geometry), clip_(clip) {}
    bool blocked(const Vec3& from, const Vec3& to) override {
        Vec3 d = to - from;
        const double length = rp::length(d);
        if (!(length > 0)) return false;
        d = d / length;
        Ray r{from, d, length};
        for (int pass = 0; pass < 64; ++pass) {
            const std::optional<Hit> hit = geometry_.closestHit(r);
            if (!hit) return false;
            if (stopsLight(hit->modifier)) return true;
            const double left = r.tmax - hit->t;
            r = spawnRay(*hit, d, left);
            if (!(left > 0)) return false;
        }
        return false;
    }

private:
    bool stopsLight(int32_t modifier) const {
        if (clip_.contains(modifier)) return false;
        const int32_t m = chainMaterial(materials_.scene(), modifier);
        return m != kVoid && materials_[m].plugsLeaks;
    }
    const material::MaterialTable& materials_;
    const SceneGeometry& geometry_;
    const ClipSet& clip_;
};

// The ambient hemisphere's samples of one ray (HemisphereTracer for Ambient::indirect):
// they start from `parent`, the ray whose hit is being lit.
class SampleTracer final : public HemisphereTracer {
public:
    SampleTracer(Renderer::Context& ctx, const RayState& parent) : ctx_(ctx), parent_(parent) {}
    Sample trace(const Vec3& origin, const Vec3& dir, int ambientLevel, double weight,
                 double share) override {
        return ctx_.traceSample(parent_, origin, dir, ambientLevel, weight, share);
    }

private:
    Renderer::Context& ctx_;
    const RayState& parent_;
};

}  // namespace

Color Renderer::Context::ambientAt(const Hit& hit, const Vec3& normal, int32_t modifier,
                                   const RayState& state, const Color& coef) {
    QueryLeakTest leaks(impl.chains.materials(), impl.geometry, state.clip);
    AmbientPoint ap;
    ap.leaks = &leaks;
    ap.point = hit.point;
    ap.normal = normal;
    double side = dot(normal, hit.normal) >= 0 ? hit.offset : -hit.offset;
    ap.offsetOrigin = hit.point + hit.normal * side;
    ap.modifier = modifier;
    ap.ambientLevel = state.ambientLevel;
    ap.weight = state.weight;
    ap.coefficient = coef.max();
    Color c;
    const PhotonLighting& pm = impl.photons;
    const PhotonMode::AmbientReads reads = impl.photonMode.ambientReads(state.pathDepth());
    const SurfaceCoverage coverage(impl.chains.materials(), impl.geometry, hit,
                                   planeNormal(hit, normal));
    if (reads.contribGather || reads.contribCaustic) {
        Color d = pm.contribDensity(*photonLookups, hit.point, normal, state.contribCoef * coef,
                                    state.contrib, reads.contribCaustic, &coverage);
        if (reads.contribGather) return d;
        c += d;
    }
    if (reads.global) return pm.globalDensity(*photonLookups, hit.point, normal, &coverage);
    if (reads.caustic) c += pm.causticDensity(*photonLookups, hit.point, normal, &coverage);
    std::optional<RayState> parent;  // with the ambient coefficient in its path (rcontrib)
    if (state.contrib) {
        parent = state;
        parent->contribCoef = state.contribCoef * coef;
    }
    SampleTracer samples(*this, parent ? *parent : state);
    c += impl.ambient.indirect(ap, samples, rng);
    return c;
}

Color Renderer::Context::irradianceAt(const Hit& hit, const Vec3& normal, const RayState& state) {
    // White Lambertian receiver: direct irradiance sum L cos omega, plus pi times the
    // ambient calculation's average radiance.
    DirectPoint at;
    at.point = hit.point;
    at.normal = normal;
    at.geomNormal = normal;
    at.hit = &hit;
    at.weight = state.weight;
    at.contrib = state.contrib;
    at.contribCoef = state.contribCoef;
    at.medium = &mediumOf(state);
    at.scatterLoss = impl.photonMode.mediumScatterInPhotons();
    at.shadow = shadowStart(state);
    at.generation = state.generation;
    // Direct photons replace the direct calculation here too (manual 5.4; RADIANCE's
    // direct() multiplies the receiver's coefficient at its normal, pi for this white
    // Lambertian one, by the direct photons' irradiance / pi).
    const SurfaceCoverage coverage(impl.chains.materials(), impl.geometry, hit,
                                   planeNormal(hit, normal));
    Color e = impl.photonMode.directFromPhotons()
                  ? impl.photons.directDensity(*photonLookups, hit.point, normal, &coverage) * kPi
                  : impl.direct.compute(
                        at,
                        [&](const Vec3& toLight, double) {
                            double c = dot(normal, toLight);
                            return c > 0 ? Color{c, c, c} : Color{};
                        },
                        *this, rng, directScratch);
    RayState st;
    st.ambientLevel = state.ambientLevel;
    st.weight = state.weight;
    st.depth = state.depth;
    st.generation = state.generation;
    st.clip = state.clip;
    st.media = state.media;
    st.contrib = state.contrib;
    st.contribCoef = state.contribCoef;
    return e + ambientAt(hit, normal, kVoid, st, Color::grey(kPi)) * kPi;
}

}  // namespace rp::render
