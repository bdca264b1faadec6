// The shading loop of the backward pass (RADIANCE raytrace.c, rayshade and the m_*
// material routines): a ray meets a surface, the modifier chain gives material layers,
// each layer adds emission, ideal/sampled specular rays, direct light and indirect
// (ambient) light. Shadow rays and hemisphere samples are in shadow.cpp.
#include <cmath>

#include "light/light_sources.h"
#include "render/renderer_impl.h"
#include "util/error.h"

namespace rp::render {

namespace {

bool isPlanar(PrimType t) { return t == PrimType::Polygon || t == PrimType::Ring; }

bool passesIrradiance(const material::MaterialParams& m) {
    // RADIANCE irr_ignore: with -i, transparent materials are passed through so that the
    // irradiance is computed on the first opaque surface behind them.
    return std::holds_alternative<material::GlassParams>(m) ||
           std::holds_alternative<material::DielectricParams>(m) ||
           std::holds_alternative<material::AntimatterParams>(m);
}

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

material::Redirection evalRedirect(const Scene& scene, const material::MaterialCalc& calc,
                                   material::MaterialCalcEvaluator& ev, const Hit& hit,
                                   const Vec3& dir, int projection, const Vec3& toSource) {
    int32_t mat = chainMaterial(scene, hit.modifier);
    if (mat == kVoid || !calc.uses(mat)) return {};
    const PrimType t = scene.prims[size_t(mat)].type;
    if (t != PrimType::Prism1 && t != PrimType::Prism2) return {};
    if (projection > 0 && t != PrimType::Prism2) return {};
    ev.setHit(mat, patternPoint(hit, dir));
    return ev.redirect(projection, toSource);
}

Renderer::Context::Context(const Renderer& r, const Impl& i)
    : renderer(r),
      impl(i),
      chains(i.chains),
      materialCalc(i.materialCalc),
      prismCalc(i.materialCalc) {
    directional = [this](const Vec3& l) { return materialCalc.directional(l); };
}

void Renderer::Context::applyMaterialCalc(int32_t material, const Hit& hit, const Vec3& dir,
                                          material::SurfacePoint& sp) {
    if (!impl.materialCalc.uses(material)) return;
    material::prepareHit(impl.materialCalc, materialCalc, material, *impl.material(material).params,
                         patternPoint(hit, dir), sp, &directional);
}

material::ChainResult Renderer::Context::resolve(int32_t modifier, const Hit& hit,
                                                 const Vec3& dir) {
    material::ChainResult r =
        impl.chains.isPlain(modifier)
            ? material::ChainResult::plain(impl.chains.plainMaterial(modifier))
            : chains.resolve(modifier, patternPoint(hit, dir), rng);
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
        t.depth = state.depth;
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

    // Shading point: RADIANCE raynormal (perturbed normal flipped to the ray's side).
    Vec3 ng = hit.front ? hit.normal : -hit.normal;
    Vec3 n = ng;
    if (lengthSquared(layer.perturbation) > 0) {
        n = normalize(hit.normal + layer.perturbation);
        if (!hit.front) n = -n;
    }
    material::SurfacePoint sp = material::makeSurfacePoint(ray.dir, ng, hit.front, layer.pattern);
    sp.normal = n;
    sp.flat = isPlanar(impl.scene.prims[size_t(hit.prim)].type);
    sp.scatteredRay = state.indirect;
    // RADIANCE compat (pmapmat.h ambRayInPmap): specular direct light is in the photons
    // only below the first gather bounce (rlvl > 1); at a final-gather hit itself the
    // light a BSDF window or a glossy surface sends straight to the gathering point is
    // not (issue 43: sensors beside a Klems window read half of RADIANCE's).
    sp.specularInPhotons = impl.photons.active() && state.ambientLevel > 0 &&
                           (impl.ambientOptions.bounces < 0 || state.depth > 1);
    sp.rayWeight = state.weight;
    sp.specJitter = impl.shadeOptions.specJitter;

    auto fillFirst = [&](RayResult* f) {
        recordFirst(f, hit, hit.front || e.reorientsBackHits ? n : -n, layer.material);
    };

    if (e.isLight) {
        const auto& light = std::get<material::LightParams>(params);
        bool source = impl.direct.isSourceSurface(hit.prim, ray.origin);
        // RADIANCE compat (source.c badcomponent, distglow): a ray descended from an
        // ambient or sampled specular ray sees every light material from the front as
        // black, source or not (lights inside instances are not), since the direct
        // calculation counts sources; only a glow farther than its radius shows, and a
        // glow with a negative radius never does (ray.html glow).
        const bool distantGlow = light.kind == material::LightParams::Kind::Glow &&
                                 light.glowMaxRadius >= -1e-6 && hit.t > light.glowMaxRadius;
        if (state.indirect && hit.front && !distantGlow) {
            fillFirst(first);
            passage.uncounted = true;
            return {};
        }
        if (light.kind == material::LightParams::Kind::Illum) {
            // ray.html illum: seen directly (or by specular rays) it is its alternate.
            return shadeAlternate(ray, hit, state, e.alternate, first, passThrough, passage);
        }
        fillFirst(first);
        if (source && !impl.options.direct.visibility && !state.indirect) {  // -dv-
            passage.uncounted = true;
            return {};
        }
        material::BackwardResult b = material::shadeBackward(params, sp, impl.shadeOptions, rng);
        return b.emitted;
    }

    if (state.irradianceHit) {
        if (passesIrradiance(params)) {
            passThrough = true;
            return {};
        }
        // -i: the first surface is white Lambertian (RADIANCE's plastic Lamb, which faces
        // the ray); the value is its irradiance.
        recordFirst(first, hit, n, layer.material);
        return irradianceAt(hit, n, state);
    }

    if (e.hasAlternate && std::holds_alternative<material::MirrorParams>(params)) {
        // ray.html mirror: with an alternate material the mirror only relays sources
        // (virtual sources); every other ray sees the alternate.
        return shadeAlternate(ray, hit, state, e.alternate, first, passThrough, passage);
    }
    if (const auto* mist = std::get_if<material::MistParams>(&params)) {
        // m_mist.c: the ray goes on in the medium it enters or returns to.
        recordFirst(first, hit, hit.normal, layer.material);
        passage.crossing = material::mistCrossing(*mist, hit.front, layer.pattern);
        passage.mist = layer.material;
        passThrough = true;
        return {};
    }

    std::array<material::Redirection, 2> redirections{};
    material::WgmdInputs wgmd;  // WGMDfunc's values at this hit (sp.wgmd)
    if (const auto* prism = std::get_if<material::PrismParams>(&params)) {
        // m_direct.c: a ray not aimed at a source follows each redirection, DxA DyA DzA
        // zero. (Shadow rays toward a prism's virtual sources are direct.cpp's.)
        prismCalc.setHit(layer.material, patternPoint(hit, ray.dir));
        for (int k = 0; k < prism->redirections; ++k)
            redirections[size_t(k)] = prismCalc.redirect(k, Vec3{});
        sp.redirections = &redirections;
    } else if (const auto* w = std::get_if<material::WgmdParams>(&params)) {
        wgmd = material::wgmdHitInputs(impl.materialCalc, materialCalc, chains, layer.material, *w,
                                       patternPoint(hit, ray.dir), sp, rng);
        sp.wgmd = &wgmd;
    } else {
        applyMaterialCalc(layer.material, hit, ray.dir, sp);
    }
    material::BackwardResult b = material::shadeBackward(params, sp, impl.shadeOptions, rng);
    if (b.transparent) {
        passThrough = true;
        return {};
    }
    fillFirst(first);
    Color value = b.emitted;
    Hit farSide = hit;  // where light from behind is gathered (BackwardResult::transmitOffset)
    farSide.point += hit.normal * b.transmitOffset;

    // Specular rays (RADIANCE rayorigin rules for -lr and -lw). RADIANCE compat
    // (pmapmat.h ambRayInPmap): in photon-map mode an ambient ray's specular children are
    // not traced where the photons already carry what they would find: with -ab < 0,
    // below the first gather bounce, or whenever a caustic map holds the light that
    // reaches the gathering point through specular surfaces. With a global map alone a
    // final-gather ray does see through glass and mirrors (daylight README: the sky
    // through the window, otherwise missing from the work plane; MARE 21 % -> 0.9 %).
    const LimitOptions& lim = impl.options.limits;
    const PhotonLighting& pmaps = impl.photons;
    const bool specularInPmap =
        pmaps.active() && state.ambientLevel > 0 &&
        (impl.ambientOptions.bounces < 0 || state.depth > 1 || pmaps.hasCausticLight());
    std::optional<MediaState> childMedia;  // of a child entering or leaving a dielectric
    for (int i = 0; i < (specularInPmap ? 0 : b.numRays); ++i) {
        const material::SpecularRay& sr = b.rays[size_t(i)];
        Color rc = sr.weight;
        RayState child = state;  // the clip set too
        child.depth = state.depth + 1;
        child.weight = state.weight * rc.average();
        child.primary = false;
        child.irradianceHit = false;
        child.indirect = state.indirect || sr.sampled;
        child.contribCoef = state.contribCoef * rc;
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
                child.contribCoef = state.contribCoef * rc;
            }
        }
        Ray out = spawnRay(hit, sr.dir);
        if (sr.kind == material::ScatterKind::SpecularTransmission && b.transmitOffset != 0)
            out.origin += hit.normal * b.transmitOffset;
        double d = kNoHit;
        Color c = radiance(out, child, nullptr, d);
        Color contrib = rc * c;
        value += contrib;
        if (first && first->prim == hit.prim && state.primary) {
            if (sr.kind == material::ScatterKind::SpecularReflection && !sr.sampled) {
                first->mirrored += contrib;
                first->mirroredLength = hit.t + d;
            }
        }
    }

    if (e.diffuseLike) {
        if (impl.photons.hasDirect()) {
            // Direct photons replace the direct calculation (manual 5.4; a debug aid).
            value += b.ambientReflect * impl.photons.directDensity(*photonLookups, hit.point, n);
        } else {
            bool transmits = b.ambientTransmit.max() > 0 || b.directFromBehind;
            shadowBlockedByTransparent_ = shadowInPhotonMap(state);
            // Specular children may have used the function evaluator: set this hit again.
            if (sp.directional) applyMaterialCalc(layer.material, hit, ray.dir, sp);
            if (b.transmitOffset == 0) {
                value += directAt(hit, params, sp, transmits, state);
            } else {
                // m_bsdf.c: reflected light here, transmitted light from the far point.
                value += directAt(hit, params, sp, false, state);
                if (transmits) value += directAt(farSide, params, sp, true, state, true);
            }
        }
    }
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
    at.scatterLoss = impl.photons.hasGlobal();
    shadowBase_ = shadowClip_ = state.clip;  // shadow rays start with the ray's set
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
        *this, rng);
}

namespace {

// RADIANCE compat (ambient.c plugaleak): a cached record plugged by the first surface on
// the test segment that stops light: one with a material that is neither transparent
// (initotypes.c T_TRANSP) nor a thick BSDF's proxy, and not hidden by the query ray's
// antimatter.
class QueryLeakTest final : public LeakTest {
public:
    QueryLeakTest(const Scene& scene, const SceneGeometry& geometry, const ClipSet& clip)
        : scene_(scene), geometry_(geometry), clip_(clip) {}
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
        const int32_t m = chainMaterial(scene_, modifier);
        if (m == kVoid) return false;
        const Primitive& p = scene_.prims[size_t(m)];
        const bool bsdfProxy = p.type == PrimType::BSDF && !p.sargs.empty() && p.sargs[0] != "0";
        return !isTransparentMaterial(p.type) && !bsdfProxy;
    }
    const Scene& scene_;
    const SceneGeometry& geometry_;
    const ClipSet& clip_;
};

}  // namespace

Color Renderer::Context::ambientAt(const Hit& hit, const Vec3& normal, int32_t modifier,
                                   const RayState& state, const Color& coef) {
    QueryLeakTest leaks(impl.scene, impl.geometry, state.clip);
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
    if (pm.active()) {
        // RADIANCE pmapamb.c: a final-gather sample's hit (or any hit with -ab -1) reads
        // the global map, which holds caustic light too; hits of other rays add the
        // caustic map and gather the rest. Without a global map the caustic map fills in
        // at the samples' hits as well (ambPmapCaustic), or that light would be lost.
        // A contribution map plays both parts, its caustic photons the caustic map's.
        if (pm.hasContrib()) {
            const bool gather = state.ambientLevel > 0 || impl.ambientOptions.bounces < 0;
            Color d = pm.contribDensity(*photonLookups, hit.point, normal, state.contribCoef * coef,
                                        state.contrib, !gather);
            if (gather) return d;
            c += d;
        }
        if (pm.hasGlobal() && (state.ambientLevel > 0 || impl.ambientOptions.bounces < 0))
            return pm.globalDensity(*photonLookups, hit.point, normal);
        if (pm.hasCaustic() && (state.ambientLevel == 0 || !pm.hasGlobal()))
            c += pm.causticDensity(*photonLookups, hit.point, normal);
    }
    const RayState* saved = sampleParent_;
    std::optional<RayState> parent;  // with the ambient coefficient in its path (rcontrib)
    if (state.contrib) {
        parent = state;
        parent->contribCoef = state.contribCoef * coef;
    }
    sampleParent_ = parent ? &*parent : &state;
    c += impl.ambient.indirect(ap, *this, rng);
    sampleParent_ = saved;
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
    at.scatterLoss = impl.photons.hasGlobal();
    shadowBlockedByTransparent_ = shadowInPhotonMap(state);
    shadowBase_ = shadowClip_ = state.clip;
    // Direct photons replace the direct calculation here too (manual 5.4; RADIANCE's
    // direct() multiplies the receiver's coefficient at its normal, pi for this white
    // Lambertian one, by the direct photons' irradiance / pi).
    Color e = impl.photons.hasDirect()
                  ? impl.photons.directDensity(*photonLookups, hit.point, normal) * kPi
                  : impl.direct.compute(
                        at,
                        [&](const Vec3& toLight, double) {
                            double c = dot(normal, toLight);
                            return c > 0 ? Color{c, c, c} : Color{};
                        },
                        *this, rng);
    RayState st;
    st.ambientLevel = state.ambientLevel;
    st.weight = state.weight;
    st.depth = sampleParent_ ? sampleParent_->depth : 0;
    st.clip = state.clip;
    st.media = state.media;
    st.contrib = state.contrib;
    st.contribCoef = state.contribCoef;
    return e + ambientAt(hit, normal, kVoid, st, Color::grey(kPi)) * kPi;
}

bool Renderer::Context::shadowInPhotonMap(const RayState& state) const {
    // pmapmat.h shadowRayInPmap: with -ab < 0, or below an ambient ray in any photon
    // mode, or on the primary path when a caustic map carries diffuse-specular-light.
    const PhotonLighting& pm = impl.photons;
    if (!pm.active()) return false;
    if (impl.ambientOptions.bounces < 0) return true;
    return state.ambientLevel > 0 ? true : pm.hasCausticLight();
}

}  // namespace rp::render
