// The scene's material records (see material_table.h).
#include "material/material_table.h"

#include <algorithm>

#include "material/type_traits.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::material {

namespace {

bool isLightType(PrimType t) { return typeTraits(t).light != TypeTraits::Light::None; }

bool takesDirect(const MaterialParams& m) {
    return std::holds_alternative<NormalParams>(m) || std::holds_alternative<AnisoParams>(m) ||
           std::holds_alternative<AshikParams>(m) || std::holds_alternative<FuncParams>(m) ||
           std::holds_alternative<BrtdParams>(m) || std::holds_alternative<BsdfParams>(m) ||
           std::holds_alternative<WgmdParams>(m);
}

bool opaqueBackAbsorbs(const MaterialParams& m) {
    // pmapmat.c normalPhotonScatter / anisoPhotonScatter: the back of an opaque
    // material absorbs unless -bv; trans* is lit from both sides.
    if (auto* p = std::get_if<NormalParams>(&m)) return p->kind != NormalParams::Kind::Trans;
    if (auto* p = std::get_if<AnisoParams>(&m)) return p->kind != AnisoParams::Kind::Trans2;
    if (std::holds_alternative<AshikParams>(m)) return true;  // ashik2 is opaque
    if (auto* p = std::get_if<FuncParams>(&m))
        return p->type != PrimType::Transfunc && p->type != PrimType::Transdata;
    return false;
}

bool reorientsBackHits(const MaterialParams& m) {
    return std::holds_alternative<NormalParams>(m) || std::holds_alternative<AnisoParams>(m) ||
           std::holds_alternative<AshikParams>(m) || std::holds_alternative<GlassParams>(m) ||
           std::holds_alternative<FuncParams>(m) || std::holds_alternative<WgmdParams>(m);
}

MaterialRecord makeRecord(const Scene& scene, int32_t index, bool warnUnknown,
                          const spectral::Pass& pass) {
    MaterialRecord e;
    const Primitive& p = scene.prims[size_t(index)];
    e.isLight = isLightType(p.type);
    e.antimatter = typeTraits(p.type).antimatter;
    const bool bsdfProxy = p.type == PrimType::BSDF && !p.sargs.empty() && p.sargs[0] != "0";
    e.plugsLeaks = !isTransparentMaterial(p.type) && !bsdfProxy;
    try {
        e.params = makeMaterial(p, pass);
    } catch (const InputError& err) {
        e.error = err.what();
        return e;
    }
    e.diffuseLike = takesDirect(*e.params);
    e.backAbsorbs = opaqueBackAbsorbs(*e.params);
    e.reorientsBackHits = reorientsBackHits(*e.params);
    e.passesIrradiance = std::holds_alternative<GlassParams>(*e.params) ||
                         std::holds_alternative<DielectricParams>(*e.params) ||
                         std::holds_alternative<AntimatterParams>(*e.params);
    e.passesPhotonShadows = std::holds_alternative<AntimatterParams>(*e.params) ||
                            std::holds_alternative<MistParams>(*e.params);
    e.scattersPhotons = !std::holds_alternative<PrismParams>(*e.params);
    std::optional<std::string> alt;
    if (auto* m = std::get_if<MirrorParams>(&*e.params)) alt = m->alternate;
    if (auto* l = std::get_if<LightParams>(&*e.params)) alt = l->alternate;
    if (alt) {
        e.hasAlternate = true;
        e.alternate = lastModifier(scene, index, *alt);
        if (e.alternate == kVoid && *alt != "void")
            e.error = InputError(p.loc, std::string(primTypeName(p.type)) + " '" + p.name +
                                            "': undefined alternate material '" + *alt + "'")
                          .what();
    }
    if (e.antimatter) e.clips = antimatterClips(scene, index, warnUnknown);
    return e;
}

}  // namespace

int32_t lastModifier(const Scene& scene, int32_t before, const std::string& name) {
    if (name == "void") return kVoid;
    for (int32_t i = before - 1; i >= 0; --i) {
        const Primitive& p = scene.prims[size_t(i)];
        if (isModifier(p.type) && p.name == name) return i;
    }
    return kVoid;
}

std::vector<int32_t> antimatterClips(const Scene& scene, int32_t index, bool warnUnknown) {
    const Primitive& p = scene.prims[size_t(index)];
    std::vector<int32_t> clips;
    for (const std::string& name : p.sargs) {
        if (name == "void") continue;
        int32_t m = lastModifier(scene, index, name);
        if (m == kVoid) {
            if (warnUnknown)
                warn(p.loc, "antimatter '" + p.name + "': unknown modifier '" + name + "'");
            continue;
        }
        if (std::find(clips.begin(), clips.end(), m) == clips.end()) clips.push_back(m);
    }
    return clips;
}

MaterialTable::MaterialTable(const Scene& scene, bool warnUnknown, const spectral::Pass& pass)
    : scene_(scene), pass_(pass) {
    records_.resize(scene.prims.size());
    for (size_t i = 0; i < scene.prims.size(); ++i)
        if (primCategory(scene.prims[i].type) == PrimCategory::Material)
            records_[i] = makeRecord(scene, int32_t(i), warnUnknown, pass);
}

const MaterialRecord& MaterialTable::at(int32_t index) const {
    const MaterialRecord& e = records_[size_t(index)];
    if (!e.params) {
        if (!e.error.empty()) throw InputError(e.error);
        throw InputError(scene_.prims[size_t(index)].loc,
                         "'" + scene_.prims[size_t(index)].name + "' is not a material");
    }
    return e;
}

}  // namespace rp::material
