// Dispatch of the public API over the MaterialParams variant, plus the shared sampling
// helpers of detail.h (Ward half-vector sampling, Russian roulette). Families that are
// too small for a file of their own (lights, antimatter) are handled inline here.
#include <algorithm>
#include <cmath>

#include "material/detail.h"
#include "util/error.h"

namespace rp::material {

namespace detail {

namespace {
// One Ward-Gaussian facet slope (Walter 2005, as RADIANCE's normal.c/aniso.c sample it):
// the in-plane azimuth (cosp, sinp) and tangent length d of the perturbed normal.
void sampleWardSlope(double au, double av, Rng& rng, double spread, double& cosp, double& sinp,
                     double& d) {
    double phi = 2 * kPi * rng.uniform();
    cosp = std::cos(phi) * au;
    sinp = std::sin(phi) * av;
    double len = std::sqrt(cosp * cosp + sinp * sinp);
    cosp /= len;
    sinp /= len;
    double xi = rng.uniform();
    if (spread < 1) xi = 1 - spread * xi;
    d = xi <= kFtiny
            ? 1.0
            : std::sqrt(-std::log(xi) / (cosp * cosp / (au * au) + sinp * sinp / (av * av)));
}
}  // namespace

bool tryWardReflection(const Vec3& dir, const Vec3& n, const Vec3& u, const Vec3& v, double au,
                       double av, const Vec3& geomN, Rng& rng, Vec3& out, double spread) {
    double cosp, sinp, d;
    sampleWardSlope(au, av, rng, spread, cosp, sinp, d);
    Vec3 h = n + (u * cosp + v * sinp) * d;  // |h|^2 = 1 + d^2
    Vec3 r = dir + h * (-2 * dot(h, dir) / (1 + d * d));
    if (!(dot(r, geomN) > kFtiny)) return false;
    out = normalize(r);
    return true;
}

bool tryWardTransmission(const Vec3& through, const Vec3& u, const Vec3& v, double au, double av,
                         const Vec3& geomN, Rng& rng, Vec3& out, double spread) {
    double cosp, sinp, d;
    sampleWardSlope(au, av, rng, spread, cosp, sinp, d);
    Vec3 t = through + (u * cosp + v * sinp) * d;
    if (!(dot(t, geomN) < -kFtiny)) return false;
    out = normalize(t);
    return true;
}

bool sampleWardReflection(const Vec3& dir, const Vec3& n, const Vec3& u, const Vec3& v, double au,
                          double av, const Vec3& geomN, Rng& rng, Vec3& out, double spread) {
    for (int iter = 0; iter < kMaxIter; ++iter)
        if (tryWardReflection(dir, n, u, v, au, av, geomN, rng, out, spread)) return true;
    return false;
}

bool sampleWardTransmission(const Vec3& through, const Vec3& u, const Vec3& v, double au, double av,
                            const Vec3& geomN, Rng& rng, Vec3& out, double spread) {
    for (int iter = 0; iter < kMaxIter; ++iter)
        if (tryWardTransmission(through, u, v, au, av, geomN, rng, out, spread)) return true;
    return false;
}

int roughSampleCount(const ShadeOptions& opt, double rayWeight, const Color& coef) {
    if (!(opt.specJitter > 1.5)) return 1;
    // RADIANCE's int conversions truncate; both quotients are positive where they count.
    double n = std::floor(opt.specJitter * rayWeight + .5);
    const double w = rayWeight * spawnedWeight(coef);  // the unshared sample ray's weight
    if (opt.minWeight > 0 && w <= opt.minWeight * n) n = std::floor(w / opt.minWeight);
    return n > 1 ? int(std::min(n, double(kMaxRoughSamples))) : 1;
}

namespace {
// The table's probabilities and scale, without the flux factors.
void setRouletteProbabilities(const Component* c, int n, RouletteTable& t) {
    // Each probability is computed once (divisions are a visible part of a photon's
    // scatter); the callers pass at most 4 components.
    RP_CHECK(n <= RouletteTable::kMaxComponents);
    t.n = n;
    double total = 0;
    for (int i = 0; i < n; ++i) {
        // Absent components (black, e.g. the specular parts of a plain plastic) skip the
        // division in average(); their probability is 0 either way.
        const Color& k = c[i].coef;
        t.prob[i] = k.r == 0 && k.g == 0 && k.b == 0 ? 0.0 : std::max(k.average(), 0.0);
        total += t.prob[i];
    }
    // Probabilities avg(C_i) as pmapmat.c; normalised only if they exceed 1 in sum
    // (non-physical input), so that the expectation stays exact either way.
    t.scale = total > 1 ? total : 1;
}

Color rouletteFactor(const Color& coef, double prob, double scale) { return coef / (prob / scale); }
}  // namespace

RouletteTable makeRouletteTable(const Component* c, int n) {
    RouletteTable t;
    setRouletteProbabilities(c, n, t);
    for (int i = 0; i < n; ++i)
        if (t.prob[i] > 0) t.factor[i] = rouletteFactor(c[i].coef, t.prob[i], t.scale);
    return t;
}

namespace {
// The component a draw picks by the table's probabilities, or -1 (absorbed).
int rouletteIndex(const RouletteTable& t, Rng& rng) {
    double xi = rng.uniform() * t.scale;
    for (int i = 0; i < t.n; ++i) {
        const double p = t.prob[i];
        if (p <= 0) continue;
        if (xi < p) return i;
        xi -= p;
    }
    return -1;
}
}  // namespace

int roulette(const RouletteTable& t, Rng& rng, Color& factor) {
    const int i = rouletteIndex(t, rng);
    if (i >= 0) factor = t.factor[i];
    return i;
}

int roulette(const Component* c, int n, Rng& rng, Color& factor) {
    // As roulette(makeRouletteTable(c, n), ...), but only the picked component's factor is
    // divided out: no table is built per glass or mirror hit.
    RouletteTable t;
    setRouletteProbabilities(c, n, t);
    const int i = rouletteIndex(t, rng);
    if (i >= 0) factor = rouletteFactor(c[i].coef, t.prob[i], t.scale);
    return i;
}

void setPhotonRoulette(NormalParams& m) {
    const Component c[4] = {
        {ScatterKind::DiffuseReflection, m.diffuseReflectance},
        {ScatterKind::DiffuseTransmission, m.diffuseTransmittance},
        {ScatterKind::SpecularReflection, m.specularColor * (m.rspec > kFtiny ? 1.0 : 0.0)},
        {ScatterKind::SpecularTransmission, m.specularTransmittance}};
    m.photonRoulette = makeRouletteTable(c, 4);
    m.photonStore = c[0].coef.average() > kFtiny || c[1].coef.average() > kFtiny;
}

BackwardResult shadeLight(const LightParams& m, const SurfacePoint& sp) {
    BackwardResult r;
    // RADIANCE compat (source.c badcomponent, distglow): a ray descended from an ambient
    // or sampled specular ray sees every light material from the front as black, source
    // or not (lights inside instances are not), since the direct calculation counts
    // sources; only a glow farther than its radius shows, and a glow with a negative
    // radius never does (ray.html glow).
    const bool distantGlow = m.kind == LightParams::Kind::Glow && m.glowMaxRadius >= -1e-6 &&
                             sp.distance > m.glowMaxRadius;
    if (sp.scatteredRay && sp.front && !distantGlow) {
        r.uncounted = true;
        return r;
    }
    if (m.kind == LightParams::Kind::Illum) {
        // ray.html illum: seen directly it is its alternate material, or invisible.
        if (m.alternate && *m.alternate != "void")
            r.useAlternate = true;
        else
            r.transparent = true;
        return r;
    }
    r.emitted = lightEmitted(m, sp.front, sp.dir, sp.pattern);
    return r;
}

Color lightEmitted(const LightParams& m, bool front, const Vec3& dir, const Color& pattern) {
    // RADIANCE compat (source.c m_light): a light seen from behind is black.
    if (!front) return {};
    // srcsupp.c spotout: outside the cone when 2 pi (1 - cos theta) > solid angle, theta
    // between the aim and the emitted direction (-dir).
    if (m.kind == LightParams::Kind::Spotlight &&
        m.spotSolidAngle < 2 * kPi * (1 + dot(m.spotAim, dir)))
        return {};
    return m.radiance * pattern;
}

}  // namespace detail

using namespace detail;

Color evaluate(const MaterialParams& m, const SurfacePoint& sp, const Vec3& toLight,
               double sourceOmega) {
    return std::visit(
        Overloaded{
            [&](const NormalParams& p) { return evaluateNormal(p, sp, toLight, sourceOmega); },
            [&](const AnisoParams& p) { return evaluateAniso(p, sp, toLight, sourceOmega); },
            [&](const AshikParams& p) { return evaluateAshik(p, sp, toLight); },
            [&](const FuncParams& p) { return evaluateFunc(p, sp, toLight); },
            [&](const BrtdParams& p) { return evaluateBrtd(p, sp, toLight); },
            [&](const BsdfParams& p) { return evaluateBsdf(p, sp, toLight, sourceOmega); },
            [&](const WgmdParams& p) { return evaluateWgmd(p, sp, toLight, sourceOmega); },
            // Purely specular, emitting or invisible: nothing for a direct-light sample.
            [](const MirrorParams&) { return Color{}; },
            [](const GlassParams&) { return Color{}; },
            [](const DielectricParams&) { return Color{}; },
            [](const LightParams&) { return Color{}; },
            [](const AntimatterParams&) { return Color{}; },
            [](const PrismParams&) { return Color{}; },
            [](const MistParams&) { return Color{}; },
        },
        m);
}

namespace {
// Whether evaluate() has light from behind beyond a diffuse transmission (which shows in
// ambientTransmit): the rough or function-driven transmitted part of trans, trans2,
// transfunc and transdata (normal.c, aniso.c, m_brdf.c: sources behind count wherever
// the material transmits at all). BSDF and WGMDfunc say so themselves.
bool transmitsDirect(const MaterialParams& m) {
    if (const auto* p = std::get_if<NormalParams>(&m)) return p->trans > kFtiny;
    if (const auto* p = std::get_if<AnisoParams>(&m)) return p->trans > kFtiny;
    if (const auto* p = std::get_if<FuncParams>(&m)) return p->trans > kFtiny;
    return false;
}
}  // namespace

BackwardResult shadeBackward(const MaterialParams& m, const SurfacePoint& sp,
                             const ShadeOptions& opt, Rng& rng) {
    BackwardResult r =
        std::visit(Overloaded{
                       [&](const NormalParams& p) { return shadeNormal(p, sp, opt, rng); },
                       [&](const AnisoParams& p) { return shadeAniso(p, sp, opt, rng); },
                       [&](const AshikParams& p) { return shadeAshik(p, sp, opt, rng); },
                       [&](const MirrorParams& p) { return shadeMirror(p, sp, opt); },
                       [&](const GlassParams& p) { return shadeGlass(p, sp, opt); },
                       [&](const DielectricParams& p) { return shadeDielectric(p, sp); },
                       [&](const LightParams& p) { return shadeLight(p, sp); },
                       [&](const AntimatterParams&) {
                           BackwardResult r;  // clip sets are the ray tracer's business
                           r.transparent = true;
                           return r;
                       },
                       [&](const FuncParams& p) { return shadeFunc(p, sp, opt); },
                       [&](const BrtdParams& p) { return shadeBrtd(p, sp); },
                       [&](const PrismParams& p) { return shadePrism(p, sp); },
                       [&](const BsdfParams& p) { return shadeBsdf(p, sp, opt, rng); },
                       [&](const WgmdParams& p) { return shadeWgmd(p, sp, opt, rng); },
                       [&](const MistParams& p) {
                           BackwardResult r;  // m_mist.c: on in the medium entered or left
                           r.transparent = true;
                           r.passMedium = mistCrossing(p, sp.front, sp.pattern);
                           r.mist = &p;
                           return r;
                       },
                   },
                   m);
    r.directFromBehind = r.directFromBehind || transmitsDirect(m);
    return r;
}

PhotonScatter scatterPhoton(const MaterialParams& m, const SurfacePoint& sp, Rng& rng) {
    return std::visit(
        Overloaded{
            [&](const NormalParams& p) { return scatterNormal(p, sp, rng); },
            [&](const AnisoParams& p) { return scatterAniso(p, sp, rng); },
            [&](const AshikParams& p) { return scatterAshik(p, sp, rng); },
            [&](const MirrorParams& p) { return scatterMirror(p, sp, rng); },
            [&](const GlassParams& p) { return scatterGlass(p, sp, rng); },
            [&](const DielectricParams& p) { return scatterDielectric(p, sp, rng); },
            // pmapmat.c lightPhotonScatter: light, illum, glow and spotlight absorb
            // photons ("Light sources doan' reflect"); nothing is stored on them.
            [&](const LightParams&) { return PhotonScatter{}; },
            [&](const AntimatterParams&) {
                PhotonScatter s;  // PMAP_XFER: same direction and flux, caustic flag kept
                s.kind = ScatterKind::PassThrough;
                s.dir = sp.dir;
                s.fluxFactor = Color{1, 1, 1};
                return s;
            },
            [&](const FuncParams& p) { return scatterFunc(p, sp, rng); },
            [&](const BrtdParams& p) { return scatterBrtd(p, sp, rng); },
            // RADIANCE's photon tracer has no prism1/prism2 (pmapmat.c); the photon
            // tracer refuses them at load, so a photon never gets here.
            [&](const PrismParams&) { return PhotonScatter{}; },
            [&](const BsdfParams& p) { return scatterBsdf(p, sp, rng); },
            [&](const WgmdParams& p) { return scatterWgmd(p, sp, rng); },
            [&](const MistParams&) {
                PhotonScatter s;  // a mist boundary: the tracer changes the medium
                s.kind = ScatterKind::PassThrough;
                s.dir = sp.dir;
                s.fluxFactor = Color{1, 1, 1};
                return s;
            },
        },
        m);
}

std::optional<Emission> emissionOf(const MaterialParams& m) {
    const auto* light = std::get_if<LightParams>(&m);
    if (!light) return std::nullopt;
    return Emission{light->radiance, light->glow()};
}

Color Medium::transmittance(double t, bool absorptionOnly) const {
    Color out;
    for (int k = 0; k < 3; ++k) {
        const double e = t * extinction[k] * (absorptionOnly ? 1 - albedo[k] : 1);
        out[k] = e <= kFtiny ? 1 : e > 92 ? 0 : std::exp(-e);
    }
    return out;
}

Medium changeMedium(const Medium& cur, const MediumChange& c, const Medium& global,
                    const MistParams* mist) {
    using K = MediumChange::Kind;
    switch (c.kind) {
        case K::Unchanged:
            return cur;
        case K::Global: {
            Medium m = global;
            m.eccentricity = cur.eccentricity;  // dielectric.c sets cext and albedo only
            return m;
        }
        case K::Given:
            return Medium{c.extinction, Color{}, 0};  // dielectric.c: no scattering
        case K::EnterMist: {
            Medium m = cur;
            m.extinction += c.extinction;
            RP_CHECK(mist);
            if (mist->albedo) m.albedo = *mist->albedo;
            if (mist->eccentricity) m.eccentricity = *mist->eccentricity;
            return m;
        }
        case K::LeaveMist: {
            Medium m = cur;
            for (int k = 0; k < 3; ++k)
                m.extinction[k] =
                    std::max(cur.extinction[k] - c.extinction[k], global.extinction[k]);
            RP_CHECK(mist);
            if (mist->albedo) m.albedo = global.albedo;
            if (mist->eccentricity) m.eccentricity = global.eccentricity;
            return m;
        }
    }
    return cur;
}

MediumChange mistCrossing(const MistParams& m, bool entering, const Color& pattern) {
    MediumChange c;
    c.kind = entering ? MediumChange::Kind::EnterMist : MediumChange::Kind::LeaveMist;
    c.extinction = m.extinction * pattern;
    return c;
}

bool storesPhotons(const MaterialParams& m) {
    return std::visit(Overloaded{
                          [](const NormalParams& p) {
                              return p.diffuseReflectance.average() > kFtiny ||
                                     p.diffuseTransmittance.average() > kFtiny;
                          },
                          [](const AnisoParams& p) {
                              return p.diffuseReflectance.average() > kFtiny ||
                                     p.diffuseTransmittance.average() > kFtiny;
                          },
                          [](const AshikParams& p) { return p.diffuse.average() > kFtiny; },
                          [](const FuncParams& p) {
                              return p.diffuseReflectance.average() > kFtiny ||
                                     p.diffuseTransmittance.average() > kFtiny;
                          },
                          [](const BrtdParams& p) {
                              return p.frontDiffuse.average() > kFtiny ||
                                     p.backDiffuse.average() > kFtiny ||
                                     p.diffuseTransmittance.average() > kFtiny;
                          },
                          // Per hit (the data's Lambertian parts): stores decides.
                          [](const BsdfParams&) { return true; },
                          [](const WgmdParams& p) {
                              return p.frontDiffuse.average() > kFtiny ||
                                     p.backDiffuse.average() > kFtiny ||
                                     p.diffuseTransmittance.average() > kFtiny;
                          },
                          // Specular, emitting or invisible: photons pass or bounce.
                          [](const MirrorParams&) { return false; },
                          [](const GlassParams&) { return false; },
                          [](const DielectricParams&) { return false; },
                          [](const LightParams&) { return false; },
                          [](const AntimatterParams&) { return false; },
                          [](const PrismParams&) { return false; },
                          [](const MistParams&) { return false; },
                      },
                      m);
}

}  // namespace rp::material
