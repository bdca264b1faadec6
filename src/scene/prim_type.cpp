// Names and categories of RADIANCE primitive types (ray.html).
#include <array>

#include "scene/primitive.h"

namespace rp {

namespace {
struct TypeInfo {
    PrimType type;
    std::string_view name;
    PrimCategory category;
};

using C = PrimCategory;
constexpr std::array kTypes{
    TypeInfo{PrimType::Source, "source", C::Surface},
    TypeInfo{PrimType::Sphere, "sphere", C::Surface},
    TypeInfo{PrimType::Bubble, "bubble", C::Surface},
    TypeInfo{PrimType::Polygon, "polygon", C::Surface},
    TypeInfo{PrimType::Cone, "cone", C::Surface},
    TypeInfo{PrimType::Cup, "cup", C::Surface},
    TypeInfo{PrimType::Cylinder, "cylinder", C::Surface},
    TypeInfo{PrimType::Tube, "tube", C::Surface},
    TypeInfo{PrimType::Ring, "ring", C::Surface},
    TypeInfo{PrimType::Instance, "instance", C::Surface},
    TypeInfo{PrimType::Mesh, "mesh", C::Surface},
    TypeInfo{PrimType::Light, "light", C::Material},
    TypeInfo{PrimType::Illum, "illum", C::Material},
    TypeInfo{PrimType::Glow, "glow", C::Material},
    TypeInfo{PrimType::Spotlight, "spotlight", C::Material},
    TypeInfo{PrimType::Mirror, "mirror", C::Material},
    TypeInfo{PrimType::Prism1, "prism1", C::Material},
    TypeInfo{PrimType::Prism2, "prism2", C::Material},
    TypeInfo{PrimType::Plastic, "plastic", C::Material},
    TypeInfo{PrimType::Metal, "metal", C::Material},
    TypeInfo{PrimType::Trans, "trans", C::Material},
    TypeInfo{PrimType::Plastic2, "plastic2", C::Material},
    TypeInfo{PrimType::Metal2, "metal2", C::Material},
    TypeInfo{PrimType::Trans2, "trans2", C::Material},
    TypeInfo{PrimType::Ashik2, "ashik2", C::Material},
    TypeInfo{PrimType::Mist, "mist", C::Material},
    TypeInfo{PrimType::Dielectric, "dielectric", C::Material},
    TypeInfo{PrimType::Interface, "interface", C::Material},
    TypeInfo{PrimType::Glass, "glass", C::Material},
    TypeInfo{PrimType::Plasfunc, "plasfunc", C::Material},
    TypeInfo{PrimType::Metfunc, "metfunc", C::Material},
    TypeInfo{PrimType::Transfunc, "transfunc", C::Material},
    TypeInfo{PrimType::BRTDfunc, "BRTDfunc", C::Material},
    TypeInfo{PrimType::Plasdata, "plasdata", C::Material},
    TypeInfo{PrimType::Metdata, "metdata", C::Material},
    TypeInfo{PrimType::Transdata, "transdata", C::Material},
    TypeInfo{PrimType::BSDF, "BSDF", C::Material},
    TypeInfo{PrimType::ABSDF, "aBSDF", C::Material},
    TypeInfo{PrimType::WGMDfunc, "WGMDfunc", C::Material},
    TypeInfo{PrimType::Antimatter, "antimatter", C::Material},
    TypeInfo{PrimType::Texfunc, "texfunc", C::Texture},
    TypeInfo{PrimType::Texdata, "texdata", C::Texture},
    TypeInfo{PrimType::Colorfunc, "colorfunc", C::Pattern},
    TypeInfo{PrimType::Brightfunc, "brightfunc", C::Pattern},
    TypeInfo{PrimType::Colordata, "colordata", C::Pattern},
    TypeInfo{PrimType::Brightdata, "brightdata", C::Pattern},
    TypeInfo{PrimType::Colorpict, "colorpict", C::Pattern},
    TypeInfo{PrimType::Colortext, "colortext", C::Pattern},
    TypeInfo{PrimType::Brighttext, "brighttext", C::Pattern},
    TypeInfo{PrimType::Spectrum, "spectrum", C::Pattern},
    TypeInfo{PrimType::Specfile, "specfile", C::Pattern},
    TypeInfo{PrimType::Specfunc, "specfunc", C::Pattern},
    TypeInfo{PrimType::Specdata, "specdata", C::Pattern},
    TypeInfo{PrimType::Specpict, "specpict", C::Pattern},
    TypeInfo{PrimType::Mixfunc, "mixfunc", C::Mixture},
    TypeInfo{PrimType::Mixdata, "mixdata", C::Mixture},
    TypeInfo{PrimType::Mixpict, "mixpict", C::Mixture},
    TypeInfo{PrimType::Mixtext, "mixtext", C::Mixture},
    TypeInfo{PrimType::Alias, "alias", C::Alias},
};

constexpr bool tableInEnumOrder() {
    for (size_t i = 0; i < kTypes.size(); ++i)
        if (static_cast<size_t>(kTypes[i].type) != i) return false;
    return true;
}
static_assert(tableInEnumOrder(), "kTypes must list PrimType in declaration order");
}  // namespace

std::string_view primTypeName(PrimType t) { return kTypes[static_cast<size_t>(t)].name; }

PrimCategory primCategory(PrimType t) { return kTypes[static_cast<size_t>(t)].category; }

int32_t chainMaterial(const Scene& scene, int32_t modifier) {
    int32_t m = modifier;
    // Bounded walk: the reader resolves aliases, so chains are short and acyclic.
    for (size_t guard = 0; m != kVoid && guard < scene.prims.size(); ++guard) {
        PrimCategory c = primCategory(scene.prims[size_t(m)].type);
        if (c == PrimCategory::Material || c == PrimCategory::Mixture) return m;
        m = scene.prims[size_t(m)].modifier;
    }
    return kVoid;
}

bool isTransparentMaterial(PrimType t) {
    switch (t) {
        case PrimType::Trans:
        case PrimType::Trans2:
        case PrimType::Dielectric:
        case PrimType::Interface:
        case PrimType::Mist:
        case PrimType::Glass:
        case PrimType::ABSDF:
            return true;
        default:
            return false;
    }
}

bool primTypeFromName(std::string_view name, PrimType& out) {
    for (const auto& info : kTypes) {
        if (info.name == name) {
            out = info.type;
            return true;
        }
    }
    return false;
}

}  // namespace rp
