// Which modifiers lead to antimatter and what it clips (see clip_set.h).
#include "render/clip_set.h"

#include "material/material_table.h"
#include "material/type_traits.h"

namespace rp::render {

AntimatterTable::AntimatterTable(const Scene& scene, bool warnUnknown) {
    const std::vector<Primitive>& prims = scene.prims;
    of_.assign(prims.size(), -1);
    std::vector<int32_t> listOf(prims.size(), -1);  // by antimatter material
    for (size_t i = 0; i < prims.size(); ++i) {
        if (!material::typeTraits(prims[i].type).antimatter) continue;
        listOf[i] = int32_t(lists_.size());
        lists_.push_back(material::antimatterClips(scene, int32_t(i), warnUnknown));
    }
    if (lists_.empty()) return;
    for (size_t i = 0; i < prims.size(); ++i) {
        if (!isModifier(prims[i].type)) continue;
        int32_t m = chainMaterial(scene, int32_t(i));
        if (m != kVoid) of_[i] = listOf[size_t(m)];
    }
}

}  // namespace rp::render
