// Ideal specular families in both directions: mirror (m_mirror.c), thin glass (glass.c)
// and dielectric/interface (dielectric.c), with photon counterparts from pmapmat.c; the
// non-source rays of prism1/prism2 (m_direct.c). Virtual light sources through mirrors
// and prisms are not here (render/source_list.h; photon mapping disables them).
#include <cmath>

#include "material/detail.h"

namespace rp::material::detail {

namespace {
bool perturbed(const SurfacePoint& sp) { return lengthSquared(sp.normal - sp.geomNormal) > 1e-12; }
double cosIncidence(const SurfacePoint& sp) { return -dot(sp.dir, sp.normal); }

// m_mirror.c: reflect about the perturbed normal unless that penetrates the surface.
Vec3 mirrorDir(const SurfacePoint& sp) {
    if (perturbed(sp)) {
        Vec3 r = reflect(sp.dir, sp.normal);
        if (dot(r, sp.geomNormal) > kFtiny) return normalize(r);
    }
    return normalize(reflect(sp.dir, sp.geomNormal));
}
}  // namespace

// --- prism1, prism2 -----------------------------------------------------------------------

// m_direct.c for a ray not aimed at a source: each redirection continues the ray in its
// direction with its (grey) coefficient, a transmitted ray. No pattern applies and the
// surface takes neither direct nor ambient light.
BackwardResult shadePrism(const PrismParams& m, const SurfacePoint& sp) {
    BackwardResult r;
    if (!sp.redirections) return r;
    for (int k = 0; k < m.redirections; ++k) {
        const Redirection& d = (*sp.redirections)[size_t(k)];
        if (d.ok) r.add(makeRay(d.dir, Color::grey(d.coef), ScatterKind::SpecularTransmission));
    }
    return r;
}

// --- mirror ------------------------------------------------------------------------------

BackwardResult shadeMirror(const MirrorParams& m, const SurfacePoint& sp, const ShadeOptions& opt) {
    BackwardResult r;
    // The alternate material shades non-source rays; the caller knows the ray type and
    // decides (m_mirror.c). We only flag that one exists.
    r.useAlternate = m.alternate.has_value();
    if (!sp.front) {  // back is black, or invisible without -bv
        r.transparent = !opt.backVisible;
        return r;
    }
    r.add(makeRay(mirrorDir(sp), m.color * sp.pattern, ScatterKind::SpecularReflection));
    return r;
}

PhotonScatter scatterMirror(const MirrorParams& m, const SurfacePoint& sp, Rng& rng) {
    PhotonScatter s;
    if (!sp.front) return s;  // pmapmat.c: back is black
    int pick;
    if (sp.pattern == Color{1, 1, 1}) {
        pick = roulette(m.photonRoulette, rng, s.fluxFactor);  // makeMaterial's table
    } else {
        const Component c{ScatterKind::SpecularReflection, m.color * sp.pattern};
        pick = roulette(&c, 1, rng, s.fluxFactor);
    }
    if (pick < 0) return s;
    s.kind = ScatterKind::SpecularReflection;
    s.dir = mirrorDir(sp);
    return s;
}

// --- glass -------------------------------------------------------------------------------

void glassCoefficients(const GlassParams& m, double pdot, const Color& pattern, Color& refl,
                       Color& trans) {
    double n = m.index;
    // cos of the refracted angle inside the pane; the path length grows as 1/cos2.
    double cos2 = std::sqrt((1 - 1 / (n * n)) + pdot * pdot / (n * n));
    Color t = m.transmission;
    if (m.hasTransmission) {
        // Grey glass (the usual case) needs one pow, not three: same values.
        if (t.r == t.g && t.g == t.b)
            t.r = t.g = t.b = std::pow(t.r, 1 / cos2);
        else
            for (int i = 0; i < 3; ++i) t[i] = std::pow(t[i], 1 / cos2);
    }
    // Fresnel reflectances of one interface for the two polarisations.
    double r1e = (pdot - n * cos2) / (pdot + n * cos2);
    r1e *= r1e;
    double r1m = (1 / pdot - n / cos2) / (1 / pdot + n / cos2);
    r1m *= r1m;
    // Sum over all internal reflections (geometric series), averaged over polarisations.
    for (int i = 0; i < 3; ++i) {
        double d = t[i], d2 = d * d;
        trans[i] = m.hasTransmission ? 0.5 * (1 - r1e) * (1 - r1e) * d / (1 - r1e * r1e * d2) +
                                           0.5 * (1 - r1m) * (1 - r1m) * d / (1 - r1m * r1m * d2)
                                     : 0.0;
        refl[i] = 0.5 * r1e * (1 + (1 - 2 * r1e) * d2) / (1 - r1e * r1e * d2) +
                  0.5 * r1m * (1 + (1 - 2 * r1m) * d2) / (1 - r1m * r1m * d2);
    }
    // RADIANCE compat: glass.c applies the pattern to transmission only (ray.html: "a
    // pattern modifying glass will affect the transmissivity"), after the angular pow.
    // pmapmat.c multiplies before the pow and to both; we follow glass.c in both directions.
    trans *= pattern;
}

namespace {
// glass.c: a texture bends the transmitted ray by 2 (1 - n) pert.
Vec3 glassTransmitDir(const GlassParams& m, const SurfacePoint& sp) {
    if (!perturbed(sp)) return sp.dir;
    Vec3 t = normalize(sp.dir + sp.perturbation * (2 * (1 - m.index)));
    return lengthSquared(t) > 0 ? t : sp.dir;
}
}  // namespace

BackwardResult shadeGlass(const GlassParams& m, const SurfacePoint& sp, const ShadeOptions& opt) {
    BackwardResult r;
    if (!sp.front && !opt.backVisible) {
        r.transparent = true;
        return r;
    }
    Color refl, trans;
    glassCoefficients(m, cosIncidence(sp), sp.pattern, refl, trans);
    if (m.hasTransmission)
        r.add(makeRay(glassTransmitDir(m, sp), trans, ScatterKind::SpecularTransmission));
    r.add(makeRay(normalize(reflect(sp.dir, sp.normal)), refl, ScatterKind::SpecularReflection));
    return r;
}

PhotonScatter scatterGlass(const GlassParams& m, const SurfacePoint& sp, Rng& rng) {
    PhotonScatter s;
    Color refl, trans;
    glassCoefficients(m, cosIncidence(sp), sp.pattern, refl, trans);
    Component c[2] = {{ScatterKind::SpecularTransmission, trans},
                      {ScatterKind::SpecularReflection, refl}};
    int i = roulette(c, 2, rng, s.fluxFactor);
    if (i < 0) return s;
    s.kind = c[i].kind;
    s.dir = i == 0 ? glassTransmitDir(m, sp) : normalize(reflect(sp.dir, sp.normal));
    return s;
}

// --- dielectric / interface ------------------------------------------------------------

namespace {
struct DielectricHit {
    double refl = 1;    // Fresnel reflectance (1: total internal reflection)
    double nratio = 1;  // n_incident / n_transmitted
    Vec3 refracted, reflected;
    MediumChange transmittedMedium, reflectedMedium;
};

MediumChange given(const Color& t, const Color& pattern) {
    Color tp = t * pattern;
    return {MediumChange::Kind::Given,
            {extinctionOf(tp.r), extinctionOf(tp.g), extinctionOf(tp.b)}};
}

DielectricHit setupDielectric(const DielectricParams& m, const SurfacePoint& sp) {
    DielectricHit h;
    // The pattern modifies the transmission per unit length (dielectric.c, ray.html).
    if (sp.front) {  // outside -> inside
        h.nratio = m.outsideIndex / m.insideIndex;
        h.transmittedMedium = given(m.insideTransmission, sp.pattern);
        if (m.isInterface) h.reflectedMedium = given(m.outsideTransmission, sp.pattern);
    } else {  // inside -> outside
        h.nratio = m.insideIndex / m.outsideIndex;
        h.reflectedMedium = given(m.insideTransmission, sp.pattern);
        h.transmittedMedium = m.isInterface ? given(m.outsideTransmission, sp.pattern)
                                            : MediumChange{MediumChange::Kind::Global, {}};
    }
    double cos1 = cosIncidence(sp);
    const Vec3& n = sp.normal;
    h.reflected = sp.dir + n * (2 * cos1);
    if (perturbed(sp) && dot(h.reflected, sp.geomNormal) <= kFtiny)
        h.reflected = reflect(sp.dir, sp.geomNormal);
    h.reflected = normalize(h.reflected);
    double d2 = 1 - h.nratio * h.nratio * (1 - cos1 * cos1);
    if (d2 < kFtiny) return h;  // total internal reflection
    double cos2 = std::sqrt(d2);
    double rs = (cos1 - h.nratio * cos2) / (cos1 + h.nratio * cos2);
    double rp = (1 / cos1 - h.nratio / cos2) / (1 / cos1 + h.nratio / cos2);
    h.refl = 0.5 * (rs * rs + rp * rp);
    double k = h.nratio * cos1 - cos2;
    h.refracted = sp.dir * h.nratio + n * k;
    if (perturbed(sp) && dot(h.refracted, sp.geomNormal) >= -kFtiny)  // accidental refl.
        h.refracted = sp.dir * h.nratio + sp.geomNormal * k;
    h.refracted = normalize(h.refracted);
    return h;
}
}  // namespace

BackwardResult shadeDielectric(const DielectricParams& m, const SurfacePoint& sp) {
    BackwardResult r;
    DielectricHit h = setupDielectric(m, sp);
    if (h.refl < 1) {
        // Radiance is compressed into the smaller solid angle: (1 - R) (n1/n2)^2.
        double t = (1 - h.refl) * h.nratio * h.nratio;
        r.add(makeRay(h.refracted, Color::grey(t), ScatterKind::SpecularTransmission, false,
                      h.transmittedMedium));
    }
    r.add(makeRay(h.reflected, Color::grey(h.refl), ScatterKind::SpecularReflection, false,
                  h.reflectedMedium));
    return r;
}

PhotonScatter scatterDielectric(const DielectricParams& m, const SurfacePoint& sp, Rng& rng) {
    // Flux (not radiance) is conserved: refract with probability 1 - R, weight 1.
    DielectricHit h = setupDielectric(m, sp);
    PhotonScatter s;
    s.fluxFactor = Color{1, 1, 1};
    if (rng.uniform() >= h.refl) {
        s.kind = ScatterKind::SpecularTransmission;
        s.dir = h.refracted;
        s.setMedium(h.transmittedMedium);
    } else {
        s.kind = ScatterKind::SpecularReflection;
        s.dir = h.reflected;
        s.setMedium(h.reflectedMedium);
    }
    return s;
}

}  // namespace rp::material::detail
