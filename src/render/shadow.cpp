// Shadow rays (ShadowOracle: what a ray toward a light source meets), rays that leave
// the scene (distant sources and skies), and ambient hemisphere samples
// (HemisphereTracer) for the renderer core.
#include <cmath>

#include "render/renderer_impl.h"

namespace rp::render {

namespace {
constexpr double kNoHit = 1e10;
}

std::optional<Hit> Renderer::Context::closestHit(const Ray& ray) {
    return impl.geometry.closestHit(ray);
}

ShadowEvent Renderer::Context::layerEvent(const Hit& hit, const Vec3& dir,
                                          const material::ShadingLayer& layer, bool passIllum) {
    ShadowEvent ev;
    if (layer.material == kVoid) {
        ev.kind = ShadowEvent::Kind::Transmit;
        ev.colour = Color{1, 1, 1};
        return ev;
    }
    const material::MaterialRecord& e = impl.material(layer.material);
    const material::MaterialParams& params = *e.params;
    Vec3 ng = hit.front ? hit.normal : -hit.normal;
    material::SurfacePoint sp = material::makeSurfacePoint(dir, ng, hit.front, layer.pattern);
    if (lengthSquared(layer.perturbation) > 0) {
        sp.normal = normalize(hit.normal + layer.perturbation);
        if (!hit.front) sp.normal = -sp.normal;
    }
    if (e.isLight) {
        const auto& light = std::get<material::LightParams>(params);
        if (passIllum && light.kind == material::LightParams::Kind::Illum) {
            if (e.alternate == kVoid) {
                ev.kind = ShadowEvent::Kind::Transmit;
                ev.colour = Color{1, 1, 1};
                return ev;
            }
            return chainEvent(resolve(e.alternate, hit, dir), hit, dir, false);
        }
        material::BackwardResult b = material::shadeBackward(params, sp, impl.shadeOptions, rng);
        if (light.kind == material::LightParams::Kind::Illum)
            b.emitted = light.radiance * layer.pattern;  // a source for shadow rays
        ev.kind = ShadowEvent::Kind::Emit;
        ev.colour = b.emitted;
        return ev;
    }
    if (std::holds_alternative<material::AntimatterParams>(params)) {
        ev.kind = ShadowEvent::Kind::Transmit;
        ev.colour = Color{1, 1, 1};
        return ev;
    }
    if (const auto* m = std::get_if<material::MistParams>(&params)) {
        ev.kind = ShadowEvent::Kind::Transmit;  // m_mist.c: T_TRANSP, medium changes
        ev.colour = Color{1, 1, 1};
        ev.medium = material::mistCrossing(*m, hit.front, layer.pattern);
        ev.mist = m;
        return ev;
    }
    if (const auto* m = std::get_if<material::BsdfParams>(&params)) {
        // prismCalc: materialCalc may hold the hit being lit (its functions still to run).
        prismCalc.setHit(layer.material, material::PatternPoint::atHit(dir, hit), sp.normal,
                         sp.pattern);
        prismCalc.setBsdfInputs(sp);
        Color c;
        if (material::bsdfShadowPass(*m, sp, impl.options.backVisible, c)) {
            ev.kind = ShadowEvent::Kind::Transmit;
            ev.colour = c;
        }
        return ev;
    }
    if (const auto* m = std::get_if<material::BrtdParams>(&params)) {
        // m_brdf.c: a shadow ray goes on through the specular transmission (its colour
        // expressions at this hit, not scaled by the pattern); the rest is shadow.
        Color tspec = m->specularTransmission.value_or(Color{});
        if (impl.materialCalc.uses(layer.material)) {
            prismCalc.setHit(layer.material, material::PatternPoint::atHit(dir, hit), sp.normal,
                             sp.pattern);
            Color refl;
            prismCalc.brtdSpecular(refl, tspec);
        }
        if (tspec.max() > kFtiny) {
            ev.kind = ShadowEvent::Kind::Transmit;
            ev.colour = tspec;
        }
        return ev;
    }
    if (const auto* m = std::get_if<material::MirrorParams>(&params)) {
        if (!hit.front) return ev;
        ev.kind = ShadowEvent::Kind::Reflect;
        ev.colour = m->color * layer.pattern;
        return ev;
    }
    if (const auto* t = std::get_if<material::NormalParams>(&params)) {
        if (!hit.front && !impl.options.backVisible) {
            ev.kind = ShadowEvent::Kind::Transmit;
            ev.colour = Color{1, 1, 1};
            return ev;
        }
        // RADIANCE normal.c: a shadow ray passes trans straight through with the
        // specular transmission (the diffuse part is lit, not transparent).
        if (t->kind == material::NormalParams::Kind::Trans && t->tspec > 0) {
            ev.kind = ShadowEvent::Kind::Transmit;
            ev.colour = t->color * layer.pattern * t->tspec;
        }
        return ev;
    }
    if (const auto* w = std::get_if<material::WgmdParams>(&params)) {
        // m_wgmdf.c: a shadow ray passes only an ideal specular transmission, with its
        // colour; rough lobes are never sampled here (an infinite -st). prismCalc, as
        // materialCalc may hold the hit being lit.
        if (!hit.front && !impl.options.backVisible) {
            ev.kind = ShadowEvent::Kind::Transmit;
            ev.colour = Color{1, 1, 1};
            return ev;
        }
        material::WgmdInputs in =
            material::wgmdHitInputs(impl.materialCalc, prismCalc, chains, layer.material, *w,
                                    material::PatternPoint::atHit(dir, hit), sp, rng);
        sp.wgmd = &in;
        material::ShadeOptions opt = impl.shadeOptions;
        opt.specThreshold = HUGE_VAL;
        material::BackwardResult b = material::shadeBackward(params, sp, opt, rng);
        for (int i = 0; i < b.numRays; ++i)
            if (b.rays[size_t(i)].kind == material::ScatterKind::SpecularTransmission) {
                ev.kind = ShadowEvent::Kind::Transmit;
                ev.colour = b.rays[size_t(i)].weight;
                if (dot(b.rays[size_t(i)].dir, dir) <= 1 - 1e-9) ev.bent = b.rays[size_t(i)].dir;
            }
        return ev;
    }
    if (std::holds_alternative<material::GlassParams>(params) ||
        std::holds_alternative<material::DielectricParams>(params)) {
        material::BackwardResult b = material::shadeBackward(params, sp, impl.shadeOptions, rng);
        if (b.transparent) {
            ev.kind = ShadowEvent::Kind::Transmit;
            ev.colour = Color{1, 1, 1};
            return ev;
        }
        for (int i = 0; i < b.numRays; ++i) {
            const material::SpecularRay& r = b.rays[size_t(i)];
            // RADIANCE dielectric.c: a shadow ray goes on in the refracted direction
            // (and is not reflected), losing the Fresnel reflection and absorbed inside.
            if (r.kind == material::ScatterKind::SpecularTransmission) {
                ev.kind = ShadowEvent::Kind::Transmit;
                ev.colour = r.weight;
                if (dot(r.dir, dir) <= 1 - 1e-9) ev.bent = r.dir;
                ev.medium = r.medium;
            }
        }
        return ev;
    }
    return ev;  // opaque
}

ShadowEvent Renderer::Context::event(const Hit& hit, const Vec3& dir, bool passIllum) {
    // Antimatter as for any ray (shade.cpp radiance): clipped surfaces pass the shadow
    // ray unchanged, and so do antimatter surfaces, changing what it clips.
    ShadowEvent ev;
    const bool clipped = shadowClip_.contains(hit.modifier);
    const std::vector<int32_t>* clips = clipped ? nullptr : impl.antimatter.clips(hit.modifier);
    if (clipped || clips) {
        if (clips) shadowClip_.cross(*clips, hit.front);
        ev.kind = ShadowEvent::Kind::Transmit;
        ev.colour = Color{1, 1, 1};
        return ev;
    }
    ev = chainEvent(resolve(hit.modifier, hit, dir), hit, dir, passIllum);
    if (shadowBlockedByTransparent_ && ev.kind != ShadowEvent::Kind::Emit) {
        // Photon-map mode: light through glass, trans or mirrors comes from the photons
        // (pmapmat.h shadowRayInPmap); antimatter and void still pass it.
        material::ChainResult chain = resolve(hit.modifier, hit, dir);
        bool clear = true;
        for (int i = 0; i < chain.count; ++i) {
            int32_t m = chain.layers[size_t(i)].material;
            if (m != kVoid &&
                !std::holds_alternative<material::AntimatterParams>(*impl.material(m).params) &&
                !std::holds_alternative<material::MistParams>(*impl.material(m).params))
                clear = false;
        }
        if (!clear) return ShadowEvent{};
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
        const material::MaterialRecord& e = impl.material(l.material);
        if (!e.isLight) continue;
        const auto& light = std::get<material::LightParams>(*e.params);
        if (light.kind == material::LightParams::Kind::Glow)
            isGlow = true;
        else
            isLight = true;
        value += light.radiance * l.pattern * l.weight;
    }
    return value;
}

material::Redirection Renderer::Context::redirect(const Hit& hit, const Vec3& dir, int projection,
                                                  const Vec3& toSource) {
    return evalRedirect(impl.scene, impl.materialCalc, prismCalc, hit, dir, projection, toSource);
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
    if (record && !record->hit && !record->distantSource) {
        // RADIANCE compat (source.c sourcehit, rtrace.c oputn/oputp): ro is the source,
        // ron = -rdir, rop stays the origin; -0 becomes +0 in n as RADIANCE adds pert.
        record->distantSource = true;
        record->prim = chosenSource.prim;
        record->modifier = chosenSource.modifier;
        record->material = chainMaterial(impl.scene, chosenSource.modifier);
        record->unperturbedNormal = -ray.dir;
        record->normal = Vec3{} + record->unperturbedNormal;
        record->point = ray.origin;
    }
    bool directSource = impl.direct.isDistantSource(chosen);
    if (directSource && state.indirect) return {};  // counted by the direct calculation
    if (directSource && !impl.options.direct.visibility) return {};
    const int32_t modifier = chosenSource.modifier;
    if (state.contrib && state.contrib->tracks(modifier))
        state.contrib->add(modifier, ray.origin + ray.dir * kNoHit, ray.dir, state.contribCoef,
                           chosenValue);
    return chosenValue;
}

HemisphereTracer::Sample Renderer::Context::trace(const Vec3& origin, const Vec3& dir,
                                                  int ambientLevel, double weight, double share) {
    // The parent's clip set, medium and mists, with a sample's own depth and weight
    // (ambientAt, which set sampleParent_, restores it after its own samples).
    RayState st = *sampleParent_;
    st.depth = sampleParent_->depth + 1;
    // RADIANCE compat (raytrace.c rayorigin): a sample lighter than -lw is traced with
    // probability weight / -lw and then counts as -lw (Russian roulette, -lr <= 0), or
    // not at all (-lr > 0); -lr < 0 also limits the depth.
    const LimitOptions& lim = impl.options.limits;
    double promote = 1;
    if (lim.maxDepth > 0) {
        if (st.depth > lim.maxDepth || weight < lim.minWeight) return Sample{};
    } else if (lim.maxDepth < 0 && st.depth > -lim.maxDepth) {
        return Sample{};
    } else if (weight < lim.minWeight) {
        const double p = weight / lim.minWeight;
        if (!(rng.uniform() < p)) return Sample{};
        promote = 1 / p;
        weight = lim.minWeight;
    }
    st.weight = weight;
    st.ambientLevel = ambientLevel;
    st.indirect = true;
    st.primary = false;
    st.irradianceHit = false;
    st.contribCoef = sampleParent_->contribCoef * (share * promote);
    Sample s;
    double d = kNoHit;
    s.radiance = radiance(Ray{origin, dir}, st, nullptr, d, &s.normal) * promote;
    s.distance = d;
    return s;
}

}  // namespace rp::render
