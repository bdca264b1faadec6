// Shadow rays at a surface (material.h shadowPass): one case per material family, as
// each RADIANCE m_* routine answers a SHADOW ray. Refraction, Fresnel losses and
// WGMDfunc's ideal transmission come from shadeBackward, so a shadow ray sees exactly
// the transmitted ray the backward pass would spawn.
#include <cmath>
#include <optional>

#include "material/detail.h"

namespace rp::material {

using namespace detail;

namespace {

ShadowPass clear() {
    ShadowPass s;
    s.kind = ShadowPass::Kind::Transmit;
    s.colour = Color{1, 1, 1};
    return s;
}

// The ideal transmitted ray of shadeBackward, if any (RADIANCE dielectric.c, glass.c and
// m_wgmdf.c: a shadow ray goes on in the transmitted direction and is not reflected).
// Rough lobes are never sampled for shadow rays: -st is taken as infinite.
ShadowPass transmittedRay(const MaterialParams& m, const SurfacePoint& sp, const ShadeOptions& opt,
                          Rng& rng) {
    ShadeOptions o = opt;
    o.specThreshold = HUGE_VAL;
    const BackwardResult b = shadeBackward(m, sp, o, rng);
    if (b.transparent) return clear();
    ShadowPass s;
    for (int i = 0; i < b.numRays; ++i) {
        const SpecularRay& r = b.rays[size_t(i)];
        if (r.kind != ScatterKind::SpecularTransmission) continue;
        s.kind = ShadowPass::Kind::Transmit;
        s.colour = r.weight;
        if (dot(r.dir, sp.dir) <= 1 - 1e-9) s.bent = r.dir;
        s.medium = r.medium;
    }
    return s;
}

ShadowPass lightPass(const LightParams& m, bool front, const Vec3& dir, const Color& pattern,
                     bool passIllum) {
    ShadowPass s;
    if (m.kind == LightParams::Kind::Illum) {
        if (passIllum) {
            if (!m.alternate || *m.alternate == "void") return clear();
            s.kind = ShadowPass::Kind::Alternate;
            return s;
        }
        // Aimed at the illum itself: a source for shadow rays, from either side.
        s.kind = ShadowPass::Kind::Emit;
        s.colour = m.radiance * pattern;
        return s;
    }
    s.kind = ShadowPass::Kind::Emit;
    s.colour = lightEmitted(m, front, dir, pattern);  // black from behind, outside a spot's cone
    return s;
}

// plastic, metal, trans (normal.c): only trans passes a shadow ray, straight through with
// its specular transmission (the diffuse part is lit, not transparent).
ShadowPass normalPass(const NormalParams& m, const SurfacePoint& sp) {
    ShadowPass s;
    if (m.kind == NormalParams::Kind::Trans && m.tspec > 0) {
        s.kind = ShadowPass::Kind::Transmit;
        s.colour = m.color * sp.pattern * m.tspec;
    }
    return s;
}

// BRTDfunc (m_brdf.c): on through the specular transmission, its colour expressions at
// this hit and not scaled by the pattern; the rest is shadow.
ShadowPass brtdPass(const BrtdParams& m, const SurfacePoint& sp) {
    ShadowPass s;
    const Color t = sp.brtdSpecularTransmission.value_or(m.specularTransmission.value_or(Color{}));
    if (t.max() > kFtiny) {
        s.kind = ShadowPass::Kind::Transmit;
        s.colour = t;
    }
    return s;
}

ShadowPass bsdfPass(const BsdfParams& m, const SurfacePoint& sp, bool backVisible) {
    ShadowPass s;
    Color c;
    if (bsdfShadowPass(m, sp, backVisible, c)) {
        s.kind = ShadowPass::Kind::Transmit;
        s.colour = c;
    }
    return s;
}

}  // namespace

ShadowPass shadowPass(const MaterialParams& m, const SurfacePoint& sp, bool passIllum,
                      const ShadeOptions& opt, Rng& rng) {
    // normal.c, m_wgmdf.c: with -bv- an opaque material's back face lets light through.
    const bool hiddenBack = !sp.front && !opt.backVisible;
    return std::visit(
        Overloaded{
            [&](const NormalParams& p) { return hiddenBack ? clear() : normalPass(p, sp); },
            // aniso.c, ashikhmin.c, m_brdf.c m_brdf2: the rest is shadow.
            [](const AnisoParams&) { return ShadowPass{}; },
            [](const AshikParams&) { return ShadowPass{}; },
            [](const FuncParams&) { return ShadowPass{}; },
            [&](const MirrorParams& p) {
                ShadowPass s;  // a relay: reflects on its front only
                if (!sp.front) return s;
                s.kind = ShadowPass::Kind::Reflect;
                s.colour = p.color * sp.pattern;
                return s;
            },
            [&](const GlassParams&) { return transmittedRay(m, sp, opt, rng); },
            [&](const DielectricParams&) { return transmittedRay(m, sp, opt, rng); },
            [&](const LightParams& p) {
                return lightPass(p, sp.front, sp.dir, sp.pattern, passIllum);
            },
            [](const AntimatterParams&) { return clear(); },  // clip sets: the tracer's
            [&](const BrtdParams& p) { return brtdPass(p, sp); },
            // m_direct.c: only shadow rays toward its virtual sources pass (as relays).
            [](const PrismParams&) { return ShadowPass{}; },
            [&](const BsdfParams& p) { return bsdfPass(p, sp, opt.backVisible); },
            [&](const WgmdParams&) {
                return hiddenBack ? clear() : transmittedRay(m, sp, opt, rng);
            },
            [&](const MistParams& p) {
                ShadowPass s = clear();  // m_mist.c: T_TRANSP, the medium changes
                s.medium = mistCrossing(p, sp.front, sp.pattern);
                s.mist = &p;
                return s;
            },
        },
        m);
}

std::optional<ShadowPass> shadowPassWithoutSurface(const MaterialParams& m, bool front,
                                                   const Vec3& dir, const Color& pattern,
                                                   bool passIllum, bool backVisible) {
    const bool hiddenBack = !front && !backVisible;
    const std::optional<ShadowPass> opaque = ShadowPass{};
    const std::optional<ShadowPass> needsSurface;
    return std::visit(Overloaded{
                          [&](const NormalParams& p) {
                              return !hiddenBack &&
                                             !(p.kind == NormalParams::Kind::Trans && p.tspec > 0)
                                         ? opaque
                                         : needsSurface;
                          },
                          [&](const AnisoParams&) { return opaque; },
                          [&](const AshikParams&) { return opaque; },
                          [&](const FuncParams&) { return opaque; },
                          [&](const PrismParams&) { return opaque; },
                          [&](const LightParams& p) -> std::optional<ShadowPass> {
                              return lightPass(p, front, dir, pattern, passIllum);
                          },
                          [&](const MirrorParams&) { return needsSurface; },
                          [&](const GlassParams&) { return needsSurface; },
                          [&](const DielectricParams&) { return needsSurface; },
                          [&](const AntimatterParams&) { return needsSurface; },
                          [&](const BrtdParams&) { return needsSurface; },
                          [&](const BsdfParams&) { return needsSurface; },
                          [&](const WgmdParams&) { return needsSurface; },
                          [&](const MistParams&) { return needsSurface; },
                      },
                      m);
}

}  // namespace rp::material
