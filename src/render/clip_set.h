// Antimatter in the backward pass (RADIANCE ray.html, "Antimatter"; m_clip.c): which
// surface modifiers lead to an antimatter and what it clips (AntimatterTable), and the
// modifiers a ray cannot see because it is inside such volumes (ClipSet, shared with the
// photon tracer). Rays, shadow rays and the -dp pretest use them.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "material/clip_set.h"
#include "scene/primitive.h"

namespace rp::render {

// The set of modifiers a ray or photon cannot see (material/clip_set.h).
using material::ClipSet;

// Per surface modifier, the modifiers clipped by the antimatter it leads to (through
// patterns, textures and aliases; a mixture stops the walk, as RADIANCE mixes materials
// only after m_clip would have been reached).
class AntimatterTable {
public:
    AntimatterTable() = default;
    // Each name of an antimatter is the modifier last defined before it (RADIANCE
    // lastmod); "void" names none. With `warnUnknown`, names that match no modifier are
    // reported (RADIANCE warns and goes on without them).
    explicit AntimatterTable(const Scene& scene, bool warnUnknown = false);

    // The modifiers clipped by the antimatter that `modifier` leads to; null if none.
    const std::vector<int32_t>* clips(int32_t modifier) const {
        if (modifier < 0 || size_t(modifier) >= of_.size() || of_[size_t(modifier)] < 0)
            return nullptr;
        return &lists_[size_t(of_[size_t(modifier)])];
    }
    bool empty() const { return lists_.empty(); }

private:
    std::vector<int32_t> of_;                  // by modifier: index into lists_, or -1
    std::vector<std::vector<int32_t>> lists_;  // one per antimatter material
};

}  // namespace rp::render
