// Shadow rays (ShadowOracle: what a ray toward a light source meets), rays that leave
// the scene (distant sources and skies), and ambient hemisphere samples
// (HemisphereTracer) for the renderer core.
#include <cmath>

#include "render/renderer_impl.h"

namespace rp::render {

namespace {
constexpr double kNoHit = 1e10;

// What rtrace reports of a ray from `origin` along `dir` that left the scene through
// distant source `src`. RADIANCE compat (source.c sourcehit, rtrace.c oputn/oputp): ro
// is the source, ron = -rdir, rop stays the origin; -0 becomes +0 in n as RADIANCE adds
// pert.
void recordDistantSource(RayResult& r, const Scene& scene, const DistantSource& src,
                         const Vec3& origin, const Vec3& dir) {
    r.distantSource = true;
    r.prim = src.prim;
    r.modifier = src.modifier;
    r.material = chainMaterial(scene, src.modifier);
    r.unperturbedNormal = -dir;
    r.normal = Vec3{} + r.unperturbedNormal;
    r.point = origin;
}
}  // namespace

std::optional<Hit> Renderer::Context::closestHit(const Ray& ray) {
    return impl.geometry.closestHit(ray);
}

ShadowEvent Renderer::Context::layerEvent(const Hit& hit, const Vec3& dir,
                                          const material::ShadingLayer& layer, bool passIllum) {
    if (layer.material == kVoid) {
        ShadowEvent ev;
        ev.kind = ShadowEvent::Kind::Transmit;
        ev.colour = Color{1, 1, 1};
        return ev;
    }
    const material::MaterialRecord& e = impl.material(layer.material);
    std::optional<ShadowEvent> pass = material::shadowPassWithoutSurface(
        *e.params, hit.front, dir, layer.pattern, passIllum, impl.shadeOptions.backVisible);
    if (!pass) {  // the material needs its prepared surface point
        material::SurfacePoint sp = surfaceAt(hit, dir, layer);
        std::optional<material::HitScratch> scratch;
        prepare(layer.material, *e.params, hit, dir, sp, scratch);
        pass = material::shadowPass(*e.params, sp, passIllum, impl.shadeOptions, rng);
    }
    const ShadowEvent& ev = *pass;
    if (ev.kind == ShadowEvent::Kind::Alternate)
        return chainEvent(resolve(e.alternate, hit, dir), hit, dir, false);
    return ev;
}

ShadowEvent Renderer::Context::event(const Hit& hit, const Vec3& dir, ShadowPath& path,
                                     bool passIllum) {
    // Antimatter as for any ray (shade.cpp radiance): clipped surfaces pass the shadow
    // ray unchanged, and so do antimatter surfaces, changing what it clips.
    ShadowEvent ev;
    const bool clipped = path.clip.contains(hit.modifier);
    const std::vector<int32_t>* clips = clipped ? nullptr : impl.antimatter.clips(hit.modifier);
    if (clipped || clips) {
        if (clips) path.clip.cross(*clips, hit.front);
        ev.kind = ShadowEvent::Kind::Transmit;
        ev.colour = Color{1, 1, 1};
        return ev;
    }
    const material::ChainResult chain = resolve(hit.modifier, hit, dir);
    ev = chainEvent(chain, hit, dir, passIllum);
    if (path.transparentBlocks && ev.kind != ShadowEvent::Kind::Emit) {
        // PhotonMode::shadowsStopAtTransparent: light through glass, trans or mirrors
        // comes from the photons; void, antimatter and mists still pass it.
        for (int i = 0; i < chain.count; ++i) {
            const int32_t m = chain.layers[size_t(i)].material;
            if (m != kVoid && !impl.material(m).passesPhotonShadows) return ShadowEvent{};
        }
    }
    return ev;
}

ShadowEvent Renderer::Context::chainEvent(const material::ChainResult& chain, const Hit& hit,
                                          const Vec3& dir, bool passIllum) {
    if (chain.count == 1) return layerEvent(hit, dir, chain.layers[0], passIllum);
    // Mixtures: emission wins (the shadow ray reached a source); otherwise the layers'
    // transmission (or reflection) is averaged by weight, opaque layers counting zero.
    ShadowEvent out;
    Color emit, pass;
    bool anyEmit = false;
    ShadowEvent::Kind passKind = ShadowEvent::Kind::Transmit;
    for (int i = 0; i < chain.count; ++i) {
        const material::ShadingLayer& l = chain.layers[size_t(i)];
        ShadowEvent ev = layerEvent(hit, dir, l, passIllum);
        if (ev.kind == ShadowEvent::Kind::Emit) {
            anyEmit = true;
            emit += ev.colour * l.weight;
        } else if (ev.kind != ShadowEvent::Kind::Opaque) {
            passKind = ev.kind;
            pass += ev.colour * l.weight;
            out.bent = ev.bent;
            out.medium = ev.medium;
        }
    }
    if (anyEmit) {
        out.kind = ShadowEvent::Kind::Emit;
        out.colour = emit;
    } else if (pass.max() > 0) {
        out.kind = passKind;
        out.colour = pass;
    }
    return out;
}

Color Renderer::Context::sourceRadiance(int32_t modifier, const Hit& at, const Vec3& dir,
                                        bool& isGlow, bool& isLight) {
    isGlow = isLight = false;
    material::ChainResult chain = resolve(modifier, at, dir);
    Color value;
    for (int i = 0; i < chain.count; ++i) {
        const material::ShadingLayer& l = chain.layers[size_t(i)];
        if (l.material == kVoid) continue;
        const std::optional<material::Emission> light =
            material::emissionOf(*impl.material(l.material).params);
        if (!light) continue;
        (light->glow ? isGlow : isLight) = true;
        value += light->radiance * l.pattern * l.weight;
    }
    return value;
}

material::Redirection Renderer::Context::redirect(const Hit& hit, const Vec3& dir, int projection,
                                                  const Vec3& toSource) {
    return evalRedirect(impl.chains.materials(), impl.materialCalc, evaluators.calc(), hit, dir,
                        projection, toSource);
}

ShadowTree Renderer::Context::shadowTree() const {
    if (!tree) return ShadowTree::None;
    return impl.options.treeShadowRays ? ShadowTree::All : ShadowTree::Followed;
}

void Renderer::Context::reportShadowRay(const DirectPoint& at,
                                        std::span<const ShadowPiece> pieces) {
    // RADIANCE compat (source.c direct, raytrace.c): each piece is reported once its value
    // is known, the last first; the first has the weight of the ray that reached the
    // point, each further one that weight times what the surfaces before it passed.
    std::vector<double> weights(pieces.size());
    double w = at.weight;
    for (size_t i = 0; i < pieces.size(); ++i) {
        if (i > 0) w *= pieces[i].coefficient.brightness();
        weights[i] = w;
    }
    for (size_t i = pieces.size(); i-- > 0;) {
        const ShadowPiece& p = pieces[i];
        TracedRay t;
        t.depth = at.generation + 1 + int(i);
        RayResult& r = t.result;
        r.origin = p.origin;
        r.direction = p.dir;
        r.value = p.value;
        r.coefficient = p.coefficient;
        r.weight = weights[i];
        if (p.hit) {
            r.hit = true;
            r.distance = r.effectiveLength = p.hit->t;
            r.point = p.hit->point;
            // Turned toward the ray, as materials that pass light turn it (glass).
            r.normal = p.hit->front ? p.hit->normal : -p.hit->normal;
            r.unperturbedNormal = p.hit->normal;
            r.u = p.hit->u;
            r.v = p.hit->v;
            r.prim = p.hit->prim;
            r.modifier = p.hit->modifier;
            r.material = chainMaterial(impl.scene, p.hit->modifier);
        } else if (p.distant >= 0) {
            recordDistantSource(r, impl.scene, impl.geometry.sources()[size_t(p.distant)], p.origin,
                                p.dir);
        }
        tree->push_back(t);
    }
}

Color Renderer::Context::distantRadiance(int32_t source, const Vec3& dir) {
    const DistantSource& src = impl.geometry.sources()[size_t(source)];
    Hit at;
    at.point = dir * kNoHit;
    at.normal = -dir;
    at.t = kNoHit;
    at.prim = src.prim;
    at.modifier = src.modifier;
    bool glow = false, light = false;
    return sourceRadiance(src.modifier, at, dir, glow, light);
}

Color Renderer::Context::escaped(const Ray& ray, const RayState& state, RayResult* record) {
    std::vector<int32_t> matches = impl.geometry.sourcesInDirection(ray.dir);
    if (matches.empty()) return {};
    // RADIANCE compat (source.c): a ray leaving the scene takes the first non-glow
    // source whose disk contains its direction, else the first glow (sky, ground).
    int32_t chosen = -1;
    Color chosenValue;
    bool chosenGlow = false;
    for (int32_t idx : matches) {
        const DistantSource& src = impl.geometry.sources()[size_t(idx)];
        Hit at;
        at.point = ray.origin + ray.dir * kNoHit;
        at.normal = -ray.dir;
        at.t = kNoHit;
        at.prim = src.prim;
        at.modifier = src.modifier;
        bool glow = false, light = false;
        Color v = sourceRadiance(src.modifier, at, ray.dir, glow, light);
        if (!glow && !light) continue;
        if (chosen < 0 || (chosenGlow && !glow)) {
            chosen = idx;
            chosenValue = v;
            chosenGlow = glow;
            if (!glow) break;
        }
    }
    if (chosen < 0) return {};
    const DistantSource& chosenSource = impl.geometry.sources()[size_t(chosen)];
    if (record && !record->hit && !record->distantSource)
        recordDistantSource(*record, impl.scene, chosenSource, ray.origin, ray.dir);
    bool directSource = impl.direct.isDistantSource(chosen);
    if (directSource && state.indirect) return {};  // counted by the direct calculation
    if (directSource && !impl.options.direct.visibility) return {};
    const int32_t modifier = chosenSource.modifier;
    if (state.contrib && state.contrib->tracks(modifier))
        state.contrib->add(modifier, ray.origin + ray.dir * kNoHit, ray.dir, state.contribCoef,
                           chosenValue);
    return chosenValue;
}

HemisphereTracer::Sample Renderer::Context::traceSample(const RayState& parent, const Vec3& origin,
                                                        const Vec3& dir, int ambientLevel,
                                                        double weight, double share) {
    // The parent's clip set, medium and mists, with a sample's own depth and weight.
    RayState st = parent;
    st.depth = parent.depth + 1;
    st.generation = parent.generation + 1;
    st.transits = 0;
    // RADIANCE compat (raytrace.c rayorigin): a sample lighter than -lw is traced with
    // probability weight / -lw and then counts as -lw (Russian roulette, -lr <= 0), or
    // not at all (-lr > 0); -lr < 0 also limits the depth.
    const LimitOptions& lim = impl.options.limits;
    double promote = 1;
    HemisphereTracer::Sample lost;
    lost.traced = false;
    if (lim.maxDepth > 0) {
        if (st.depth > lim.maxDepth || weight < lim.minWeight) return lost;
    } else if (lim.maxDepth < 0 && st.depth > -lim.maxDepth) {
        return lost;
    } else if (weight < lim.minWeight) {
        const double p = weight / lim.minWeight;
        if (!(rng.uniform() < p)) return lost;
        promote = 1 / p;
        weight = lim.minWeight;
    }
    st.weight = weight;
    st.ambientLevel = ambientLevel;
    st.indirect = true;
    st.primary = false;
    st.irradianceHit = false;
    st.contribCoef = parent.contribCoef * (share * promote);
    HemisphereTracer::Sample s;
    double d = kNoHit;
    s.radiance = radiance(Ray{origin, dir}, st, nullptr, d, &s.normal) * promote;
    s.distance = d;
    return s;
}

}  // namespace rp::render
