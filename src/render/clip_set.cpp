// Which modifiers lead to antimatter and what it clips (see clip_set.h).
#include "render/clip_set.h"

#include <algorithm>

#include "util/warnings.h"

namespace rp::render {

AntimatterTable::AntimatterTable(const Scene& scene, bool warnUnknown) {
    const std::vector<Primitive>& prims = scene.prims;
    of_.assign(prims.size(), -1);
    std::vector<int32_t> listOf(prims.size(), -1);  // by antimatter material
    for (size_t i = 0; i < prims.size(); ++i) {
        if (prims[i].type != PrimType::Antimatter) continue;
        listOf[i] = int32_t(lists_.size());
        std::vector<int32_t>& clips = lists_.emplace_back();
        for (const std::string& name : prims[i].sargs) {
            if (name == "void") continue;
            int32_t m = kVoid;
            for (size_t k = i; k-- > 0;)
                if (isModifier(prims[k].type) && prims[k].name == name) {
                    m = int32_t(k);
                    break;
                }
            if (m == kVoid) {
                if (warnUnknown)
                    warn(prims[i].loc,
                         "antimatter '" + prims[i].name + "': unknown modifier '" + name + "'");
                continue;
            }
            if (std::find(clips.begin(), clips.end(), m) == clips.end()) clips.push_back(m);
        }
    }
    if (lists_.empty()) return;
    for (size_t i = 0; i < prims.size(); ++i) {
        if (!isModifier(prims[i].type)) continue;
        int32_t m = int32_t(i);
        for (size_t guard = 0; m != kVoid && guard < prims.size(); ++guard) {
            PrimCategory c = primCategory(prims[size_t(m)].type);
            if (c == PrimCategory::Material || c == PrimCategory::Mixture) break;
            m = prims[size_t(m)].modifier;
        }
        if (m != kVoid) of_[i] = listOf[size_t(m)];
    }
}

}  // namespace rp::render
