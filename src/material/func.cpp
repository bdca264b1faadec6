// The function/data-driven families with their plain parameters: plasfunc, metfunc,
// transfunc, plasdata, metdata, transdata (m_brdf.c m_brdf2; pmapmat.c brdf2PhotonScatter)
// and BRTDfunc (m_brdf.c m_brdf; pmapmat.c brdfPhotonScatter). Their .cal functions and
// data files are evaluated by the caller (material_calc.h) and arrive through
// SurfacePoint: the ideal specular colours (BRTDfunc) and `directional`, the function's
// value for a light direction, which evaluate() weights here as m_brdf.c dirbrdf does.
#include <cmath>

#include "material/detail.h"

namespace rp::material::detail {

namespace {
bool perturbed(const SurfacePoint& sp) { return lengthSquared(sp.normal - sp.geomNormal) > 1e-12; }

Color lambert(const Vec3& n, const Vec3& l, const Color& rdiff, const Color& tdiff) {
    double ldot = dot(n, l);
    if (ldot > kFtiny) return rdiff * (ldot / kPi);
    if (ldot < -kFtiny) return tdiff * (-ldot / kPi);
    return {};
}
}  // namespace

// --- plasfunc & co ---------------------------------------------------------------------

Color evaluateFunc(const FuncParams& m, const SurfacePoint& sp, const Vec3& l) {
    Color c = lambert(sp.normal, l, m.diffuseReflectance * sp.pattern,
                      m.diffuseTransmittance * sp.pattern);
    if (!sp.directional) return c;
    // m_brdf.c dirbrdf (per unit source solid angle): the function value f times the
    // cosine and the specular fraction; reflection is white for plasfunc/plasdata and the
    // (patterned) material colour for metfunc/metdata, transmission is coloured.
    double ldot = dot(sp.normal, l);
    if (std::fabs(ldot) <= kFtiny) return c;                             // grazing
    if (ldot < 0 ? m.trans <= kFtiny : m.trans >= 1 - kFtiny) return c;  // wrong side
    if (ldot > 0 ? m.rspec <= kFtiny : m.tspec <= kFtiny) return c;      // diffuse only
    double f = (*sp.directional)(l).r;
    if (!(f > kFtiny)) return c;  // RADIANCE skips values <= FTINY (and math errors)
    if (ldot > 0) {
        bool metal = m.type == PrimType::Metfunc || m.type == PrimType::Metdata;
        Color s = metal ? m.color * sp.pattern : Color{1, 1, 1};
        c += s * (f * ldot * m.rspec);
    } else {
        c += m.color * sp.pattern * (f * -ldot * m.tspec);
    }
    return c;
}

BackwardResult shadeFunc(const FuncParams& m, const SurfacePoint& sp, const ShadeOptions& opt) {
    BackwardResult r;
    if (!sp.front && !opt.backVisible) {
        r.transparent = true;
        return r;
    }
    // ray.html plasfunc: only direct light is considered for the specular part, so no
    // specular rays are spawned. Indirect light, though, meets the whole reflectance and
    // transmittance, specular fraction included (RADIANCE 5.4 m_brdf.c m_brdf2: the
    // material colour times 1 - trans, and times trans from the other side).
    if (m.trans < 1 - kFtiny) r.ambientReflect = m.color * sp.pattern * (1 - m.trans);
    if (m.trans > kFtiny) r.ambientTransmit = m.color * sp.pattern * m.trans;
    return r;
}

PhotonScatter scatterFunc(const FuncParams& m, const SurfacePoint& sp, Rng& rng) {
    // Photon-map manual 3.1: these "currently only scatter photons diffusely"; the
    // specular fraction is absorbed (pmapmat.c brdf2PhotonScatter).
    PhotonScatter s;
    Component c[2] = {{ScatterKind::DiffuseReflection, m.diffuseReflectance * sp.pattern},
                      {ScatterKind::DiffuseTransmission, m.diffuseTransmittance * sp.pattern}};
    s.store = c[0].coef.average() > kFtiny || c[1].coef.average() > kFtiny;
    int i = roulette(c, 2, rng, s.fluxFactor);
    if (i < 0) return s;
    s.kind = c[i].kind;
    s.dir = sampleCosine(i == 0 ? sp.normal : -sp.normal, rng);
    return s;
}

// --- BRTDfunc ------------------------------------------------------------------------------

namespace {
struct BrtdHit {
    Color rdiff, tdiff, rspec, tspec;
};
BrtdHit setupBrtd(const BrtdParams& m, const SurfacePoint& sp) {
    // ray.html: the normal is not flipped for BRTDfunc; front and back have their own
    // diffuse reflectance. The pattern modifies the diffuse values only.
    BrtdHit h;
    h.rdiff = (sp.front ? m.frontDiffuse : m.backDiffuse) * sp.pattern;
    h.tdiff = m.diffuseTransmittance * sp.pattern;
    h.rspec = sp.brtdSpecularReflection ? *sp.brtdSpecularReflection
                                        : m.specularReflection.value_or(Color{});
    h.tspec = sp.brtdSpecularTransmission ? *sp.brtdSpecularTransmission
                                          : m.specularTransmission.value_or(Color{});
    return h;
}
Vec3 brtdTransmitDir(const SurfacePoint& sp) {
    if (!perturbed(sp)) return sp.dir;
    Vec3 t = normalize(sp.dir - (sp.normal - sp.geomNormal));
    return lengthSquared(t) > 0 ? t : sp.dir;
}
}  // namespace

Color evaluateBrtd(const BrtdParams& m, const SurfacePoint& sp, const Vec3& l) {
    BrtdHit h = setupBrtd(m, sp);
    Color c = lambert(sp.normal, l, h.rdiff, h.tdiff);
    if (!sp.directional || !m.directionalDiffuse) return c;
    // m_brdf.c dirbrdf for BRTDfunc: the rbrtd gbrtd bbrtd values times |cos| on either
    // side, neither scaled by the pattern nor by a specular fraction (RADIANCE uses 1);
    // skipped when their brightness is <= FTINY.
    double ldot = dot(sp.normal, l);
    if (std::fabs(ldot) <= kFtiny) return c;
    Color f = (*sp.directional)(l);
    if (!(f.brightness() > kFtiny)) return c;
    return c + f * std::fabs(ldot);
}

BackwardResult shadeBrtd(const BrtdParams& m, const SurfacePoint& sp) {
    BackwardResult r;
    BrtdHit h = setupBrtd(m, sp);
    if (h.tspec.max() > kFtiny)
        r.add(makeRay(brtdTransmitDir(sp), h.tspec, ScatterKind::SpecularTransmission));
    if (h.rspec.max() > kFtiny)
        r.add(makeRay(normalize(reflect(sp.dir, sp.normal)), h.rspec,
                      ScatterKind::SpecularReflection));
    r.ambientReflect = h.rdiff;
    r.ambientTransmit = h.tdiff;
    return r;
}

PhotonScatter scatterBrtd(const BrtdParams& m, const SurfacePoint& sp, Rng& rng) {
    // Photon-map manual 3.1: caustics only via ideal specular reflection/transmission.
    PhotonScatter s;
    BrtdHit h = setupBrtd(m, sp);
    Component c[4] = {{ScatterKind::DiffuseReflection, h.rdiff},
                      {ScatterKind::DiffuseTransmission, h.tdiff},
                      {ScatterKind::SpecularReflection, h.rspec},
                      {ScatterKind::SpecularTransmission, h.tspec}};
    s.store = h.rdiff.average() > kFtiny || h.tdiff.average() > kFtiny;
    int i = roulette(c, 4, rng, s.fluxFactor);
    if (i < 0) return s;
    s.kind = c[i].kind;
    switch (i) {
        case 0:
            s.dir = sampleCosine(sp.normal, rng);
            break;
        case 1:
            s.dir = sampleCosine(-sp.normal, rng);
            break;
        case 2:
            s.dir = normalize(reflect(sp.dir, sp.normal));
            break;
        default:
            s.dir = brtdTransmitDir(sp);
            break;
    }
    return s;
}

}  // namespace rp::material::detail
