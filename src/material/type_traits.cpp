// The per-type table (type_traits.h): one exhaustive switch, so a new PrimType is a
// compile warning (-Wswitch) until its row is written.
#include "material/type_traits.h"

namespace rp::material {

namespace {

using L = TypeTraits::Light;
using R = TypeTraits::Relay;
using P = TypeTraits::Preview;

TypeTraits row(L light, R relay, P preview, bool opaqueToPretest) {
    TypeTraits t;
    t.material = true;
    t.light = light;
    t.relay = relay;
    t.preview = preview;
    t.opaqueToPretest = opaqueToPretest;
    return t;
}

TypeTraits opaque(P preview = P::Grey) { return row(L::None, R::None, preview, true); }
TypeTraits passing(P preview = P::Grey) { return row(L::None, R::None, preview, false); }
TypeTraits emitter(L light) { return row(light, R::None, P::Emitter, false); }

}  // namespace

TypeTraits typeTraits(PrimType t) {
    switch (t) {
        case PrimType::Light:
            return emitter(L::Light);
        case PrimType::Illum:
            return emitter(L::Illum);
        case PrimType::Glow:
            return emitter(L::Glow);
        case PrimType::Spotlight:
            return emitter(L::Spotlight);
        case PrimType::Mirror:
            return row(L::None, R::Mirror, P::Reflectance, true);
        case PrimType::Prism1:
            return row(L::None, R::Prism1, P::Grey, false);
        case PrimType::Prism2:
            return row(L::None, R::Prism2, P::Grey, false);
        case PrimType::Plastic:
        case PrimType::Metal:
        case PrimType::Plastic2:
        case PrimType::Metal2:
        case PrimType::Ashik2:
        case PrimType::Plasfunc:
        case PrimType::Metfunc:
            return opaque(P::Reflectance);
        case PrimType::Plasdata:
        case PrimType::Metdata:
            return opaque();
        case PrimType::Trans:
        case PrimType::Trans2:
        case PrimType::Glass:
        case PrimType::Dielectric:
        case PrimType::Interface:
        case PrimType::Transfunc:
            return passing(P::Reflectance);
        case PrimType::Mist: {
            TypeTraits m = passing();
            m.mist = true;
            return m;
        }
        case PrimType::Transdata:
        case PrimType::BRTDfunc:
        case PrimType::BSDF:
        case PrimType::ABSDF:
        case PrimType::WGMDfunc:
            return passing();
        case PrimType::Antimatter: {
            TypeTraits a = opaque();  // the pretest follows it (clearPath)
            a.antimatter = true;
            return a;
        }
        case PrimType::Source:
        case PrimType::Sphere:
        case PrimType::Bubble:
        case PrimType::Polygon:
        case PrimType::Cone:
        case PrimType::Cup:
        case PrimType::Cylinder:
        case PrimType::Tube:
        case PrimType::Ring:
        case PrimType::Instance:
        case PrimType::Mesh:
        case PrimType::Texfunc:
        case PrimType::Texdata:
        case PrimType::Colorfunc:
        case PrimType::Brightfunc:
        case PrimType::Colordata:
        case PrimType::Brightdata:
        case PrimType::Colorpict:
        case PrimType::Colortext:
        case PrimType::Brighttext:
        case PrimType::Spectrum:
        case PrimType::Specfile:
        case PrimType::Specfunc:
        case PrimType::Specdata:
        case PrimType::Specpict:
        case PrimType::Mixfunc:
        case PrimType::Mixdata:
        case PrimType::Mixpict:
        case PrimType::Mixtext:
        case PrimType::Alias:
            return {};
    }
    return {};
}

}  // namespace rp::material
