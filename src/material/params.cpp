// makeMaterial: a scene Primitive's arguments -> typed MaterialParams, with the value
// checks RADIANCE makes when it first shades the material (so errors arrive at load with
// file:line) and the derived constants. Argument counts were checked by scene/arg_rules.
// Shading and scattering live in the per-family files, not here.
#include <cmath>
#include <cstdlib>

#include "material/detail.h"
#include "scene/arg_rules.h"
#include "util/error.h"

namespace rp::material {

using detail::kFtiny;

namespace {

std::string header(const Primitive& p) {
    return std::string(primTypeName(p.type)) + " '" + p.name + "': ";
}
[[noreturn]] void fail(const Primitive& p, const std::string& what) {
    throw InputError(p.loc, header(p) + what);
}
// An RGB argument triple as the pass renders it (spectral.h Pass).
Color rgb(const Primitive& p, size_t at, const spectral::Pass& pass) {
    return pass.ofRgb({p.rargs[at], p.rargs[at + 1], p.rargs[at + 2]});
}
std::optional<std::string> alternateOf(const Primitive& p) {
    if (p.sargs.empty()) return std::nullopt;
    return p.sargs[0];
}
// A BRTDfunc colour expression that is a plain number ("0", ".05") is a constant.
std::optional<double> constantExpr(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return v;
}
std::optional<Color> constantColor(const std::vector<std::string>& s, size_t at,
                                   const spectral::Pass& pass) {
    auto r = constantExpr(s[at]), g = constantExpr(s[at + 1]), b = constantExpr(s[at + 2]);
    if (!r || !g || !b) return std::nullopt;
    return pass.ofRgb({*r, *g, *b});
}

// Splits shared by normal.c, aniso.c and m_brdf.c: trans = T (1 - rspec), tspec = trans
// Ts, tdiff = trans - tspec, rdiff = 1 - trans - rspec.
template <class P>
void split(P& m, double rspec, double T, double Ts) {
    m.rspec = rspec;
    m.trans = T * (1 - rspec);
    m.tspec = m.trans * Ts;
    m.tdiff = m.trans - m.tspec;
    m.rdiff = 1 - m.trans - rspec;
}

// The colours both Ward families derive once from the splits: metals tint their
// specular reflection, plastics and trans keep it white.
template <class Params>
void deriveWardColours(Params& m, bool metal) {
    split(m, m.specularity, m.transmissivity, m.transSpecular);
    m.specularColor = metal ? m.color * m.rspec : Color::grey(m.rspec);
    m.diffuseReflectance = m.color * m.rdiff;
    m.diffuseTransmittance = m.color * m.tdiff;
    m.specularTransmittance = m.color * m.tspec;
}

NormalParams makeNormal(const Primitive& p, const spectral::Pass& pass) {
    NormalParams m;
    m.kind = p.type == PrimType::Metal   ? NormalParams::Kind::Metal
             : p.type == PrimType::Trans ? NormalParams::Kind::Trans
                                         : NormalParams::Kind::Plastic;
    m.color = rgb(p, 0, pass);
    m.specularity = p.rargs[3];
    // RADIANCE compat: normal.c squares the roughness and never rejects a negative one.
    m.roughness = p.rargs[4];
    m.alpha2 = m.roughness * m.roughness;
    m.pureSpecular = m.alpha2 <= kFtiny;
    if (m.kind == NormalParams::Kind::Trans) {
        m.transmissivity = p.rargs[5];
        m.transSpecular = p.rargs[6];
    }
    deriveWardColours(m, m.kind == NormalParams::Kind::Metal);
    detail::setPhotonRoulette(m);
    return m;
}

AnisoParams makeAniso(const Primitive& p, const spectral::Pass& pass) {
    AnisoParams m;
    m.kind = p.type == PrimType::Metal2   ? AnisoParams::Kind::Metal2
             : p.type == PrimType::Trans2 ? AnisoParams::Kind::Trans2
                                          : AnisoParams::Kind::Plastic2;
    for (int i = 0; i < 3; ++i) m.uExpr[i] = p.sargs[i];
    m.funcFile = p.sargs[3];
    m.transform.assign(p.sargs.begin() + 4, p.sargs.end());
    m.color = rgb(p, 0, pass);
    m.specularity = p.rargs[3];
    m.uRoughness = p.rargs[4];
    m.vRoughness = p.rargs[5];
    // aniso.c: "roughness too small" (ray.html: zero is not allowed, use plastic).
    if (m.uRoughness <= kFtiny || m.vRoughness <= kFtiny) fail(p, "roughness too small");
    if (m.kind == AnisoParams::Kind::Trans2) {
        m.transmissivity = p.rargs[6];
        m.transSpecular = p.rargs[7];
    }
    deriveWardColours(m, m.kind == AnisoParams::Kind::Metal2);
    return m;
}

AshikParams makeAshik(const Primitive& p, const spectral::Pass& pass) {
    AshikParams m;
    for (int i = 0; i < 3; ++i) m.uExpr[i] = p.sargs[i];
    m.funcFile = p.sargs[3];
    m.transform.assign(p.sargs.begin() + 4, p.sargs.end());
    m.diffuse = rgb(p, 0, pass);
    m.specular = rgb(p, 3, pass);
    m.uPower = p.rargs[6];
    m.vPower = p.rargs[7];
    // Deliberately stricter than ashikhmin.c, which takes any value: a negative exponent
    // makes the lobe's normalisation sqrt((nu + 1)(nv + 1)) meaningless or NaN.
    if (!(m.uPower >= 0) || !(m.vPower >= 0)) fail(p, "u-power and v-power must not be negative");
    return m;
}

GlassParams makeGlass(const Primitive& p, const spectral::Pass& pass) {
    GlassParams m;
    m.transmission = rgb(p, 0, pass);
    if (p.rargs.size() == 4) m.index = p.rargs[3];
    // Deliberately stricter than glass.c, which divides by the index unchecked.
    if (!(m.index > kFtiny)) fail(p, "index of refraction must be positive");
    m.hasTransmission = m.transmission.max() > 1e-15;
    if (m.hasTransmission)  // glass.c keeps every channel above 1e-15 for pow()
        for (int i = 0; i < 3; ++i) m.transmission[i] = std::max(m.transmission[i], 1e-15);
    return m;
}

DielectricParams makeDielectric(const Primitive& p, const spectral::Pass& pass) {
    DielectricParams m;
    m.isInterface = p.type == PrimType::Interface;
    m.insideTransmission = rgb(p, 0, pass);
    if (m.isInterface) {
        m.insideIndex = p.rargs[3];
        m.outsideTransmission = rgb(p, 4, pass);
        m.outsideIndex = p.rargs[7];
    } else {
        m.hartmann = p.rargs[4];
        m.insideIndex = p.rargs[3] + m.hartmann / 500;  // dielectric.c MLAMBDA = 500 nm
    }
    // Deliberately stricter than dielectric.c (a zero index divides by zero there).
    if (!(m.insideIndex > kFtiny) || !(m.outsideIndex > kFtiny))
        fail(p, "index of refraction must be positive");
    return m;
}

LightParams makeLight(const Primitive& p, const spectral::Pass& pass) {
    LightParams m;
    m.radiance = rgb(p, 0, pass);
    switch (p.type) {
        case PrimType::Illum:
            m.kind = LightParams::Kind::Illum;
            m.alternate = alternateOf(p);
            break;
        case PrimType::Glow:
            m.kind = LightParams::Kind::Glow;
            m.glowMaxRadius = p.rargs[3];
            break;
        case PrimType::Spotlight: {
            m.kind = LightParams::Kind::Spotlight;
            m.spotAngleDeg = p.rargs[3];
            if (m.spotAngleDeg <= kFtiny) fail(p, "zero angle");  // srcsupp.c makespot
            m.spotSolidAngle = 2 * kPi * (1 - std::cos(kPi / 180 / 2 * m.spotAngleDeg));
            Vec3 aim{p.rargs[4], p.rargs[5], p.rargs[6]};
            m.spotFocalLength = length(aim);
            if (m.spotFocalLength == 0) fail(p, "zero focus vector");
            m.spotAim = aim / m.spotFocalLength;
            break;
        }
        default:
            break;
    }
    return m;
}

FuncParams makeFunc(const Primitive& p, const spectral::Pass& pass) {
    FuncParams m;
    m.type = p.type;
    m.sargs = p.sargs;
    m.rargs = p.rargs;
    m.color = rgb(p, 0, pass);
    bool trans = p.type == PrimType::Transfunc || p.type == PrimType::Transdata;
    split(m, p.rargs[3], trans ? p.rargs[4] : 0.0, trans ? p.rargs[5] : 0.0);
    m.diffuseReflectance = m.color * m.rdiff;
    m.diffuseTransmittance = m.color * m.tdiff;
    return m;
}

BrtdParams makeBrtd(const Primitive& p, const spectral::Pass& pass) {
    BrtdParams m;
    m.sargs = p.sargs;
    m.rargs = p.rargs;
    m.frontDiffuse = rgb(p, 0, pass);
    m.backDiffuse = rgb(p, 3, pass);
    m.diffuseTransmittance = rgb(p, 6, pass);
    m.specularReflection = constantColor(p.sargs, 0, pass);
    m.specularTransmission = constantColor(p.sargs, 3, pass);
    // ray.html: three '0' function names mean no directional diffuse component.
    m.directionalDiffuse = !(p.sargs[6] == "0" && p.sargs[7] == "0" && p.sargs[8] == "0");
    return m;
}

}  // namespace

MaterialParams makeMaterial(const Primitive& p, const spectral::Pass& pass) {
    // Counts are the reader's job; a short record here is a programming error.
    RP_CHECK(argRule(p.type).reals.allows(p.rargs.size()));
    switch (p.type) {
        case PrimType::Plastic:
        case PrimType::Metal:
        case PrimType::Trans:
            return makeNormal(p, pass);
        case PrimType::Plastic2:
        case PrimType::Metal2:
        case PrimType::Trans2:
            return makeAniso(p, pass);
        case PrimType::Ashik2:
            return makeAshik(p, pass);
        case PrimType::Mirror: {
            MirrorParams m{rgb(p, 0, pass), alternateOf(p), {}};
            const detail::Component c{ScatterKind::SpecularReflection, m.color};
            m.photonRoulette = detail::makeRouletteTable(&c, 1);
            return m;
        }
        case PrimType::Glass:
            return makeGlass(p, pass);
        case PrimType::Dielectric:
        case PrimType::Interface:
            return makeDielectric(p, pass);
        case PrimType::Light:
        case PrimType::Illum:
        case PrimType::Glow:
        case PrimType::Spotlight:
            return makeLight(p, pass);
        case PrimType::Antimatter:
            return AntimatterParams{p.sargs};
        case PrimType::Plasfunc:
        case PrimType::Metfunc:
        case PrimType::Transfunc:
        case PrimType::Plasdata:
        case PrimType::Metdata:
        case PrimType::Transdata:
            return makeFunc(p, pass);
        case PrimType::BRTDfunc:
            return makeBrtd(p, pass);
        case PrimType::Prism1:
        case PrimType::Prism2:
            // The expressions and the function file are checked by MaterialCalc at load.
            return PrismParams{p.type == PrimType::Prism2 ? 2 : 1};
        case PrimType::BSDF:
        case PrimType::ABSDF: {
            // The strings (thickness, file, up vector, function file) are MaterialCalc's.
            BsdfParams m;
            m.absdf = p.type == PrimType::ABSDF;
            if (p.rargs.size() >= 3) m.frontDiffuse = rgb(p, 0, pass);
            if (p.rargs.size() >= 6) m.backDiffuse = rgb(p, 3, pass);
            if (p.rargs.size() >= 9) m.diffuseTransmittance = rgb(p, 6, pass);
            m.hasBackDiffuse = p.rargs.size() >= 6;
            m.dataBands = pass.primary;
            return m;
        }
        case PrimType::WGMDfunc:
            return detail::makeWgmd(p, pass);  // wgmd.cpp; expressions and modifiers: MaterialCalc
        case PrimType::Mist: {
            // Counts 0, 3, 6 or 7 were checked by the reader.
            MistParams m;
            m.sources = p.sargs;
            if (p.rargs.size() >= 3) m.extinction = rgb(p, 0, pass);
            if (p.rargs.size() >= 6) m.albedo = rgb(p, 3, pass);
            if (p.rargs.size() >= 7) m.eccentricity = p.rargs[6];
            if (m.extinction.min() < 0) fail(p, "negative extinction");
            if (m.albedo && (m.albedo->min() < 0 || m.albedo->max() > 1))
                fail(p, "albedo outside [0,1]");
            if (m.eccentricity && !(std::fabs(*m.eccentricity) < 1))
                fail(p, "eccentricity outside (-1,1)");
            return m;
        }
        default:
            fail(p, "not a material");
    }
}

SurfacePoint makeSurfacePoint(const Vec3& dir, const Vec3& normalFacingRay, bool front,
                              const Color& pattern) {
    SurfacePoint sp;
    setSurfaceHit(sp, dir, normalFacingRay, front);
    sp.pattern = pattern;
    return sp;
}

Vec3 perturbedNormal(const Vec3& normal, const Vec3& perturbation, bool front, const Vec3& dir) {
    const Vec3 facing = front ? normal : -normal;
    Vec3 n = normal + perturbation;
    const double len = length(n);
    if (!(len > 0)) return facing;  // RADIANCE: "illegal normal perturbation"
    n = n / len;
    if (!front) n = -n;
    const double newdot = -dot(n, dir);
    if (!(newdot > 0)) n = n + dir * (2 * newdot);
    return n;
}

void perturbSurface(SurfacePoint& sp, const Vec3& normal, const Vec3& perturbation) {
    sp.normal = perturbedNormal(normal, perturbation, sp.front, sp.dir);
    sp.perturbation = sp.front ? perturbation : -perturbation;
}

}  // namespace rp::material
