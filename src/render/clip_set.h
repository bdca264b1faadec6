// Antimatter in the backward pass (RADIANCE ray.html, "Antimatter"; m_clip.c): which
// surface modifiers lead to an antimatter and what it clips (AntimatterTable), and the
// modifiers a ray cannot see because it is inside such volumes (ClipSet). Rays, shadow
// rays and the -dp pretest use them; photons keep a set of their own (pmap/trace.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "scene/primitive.h"

namespace rp::render {

// RADIANCE compat (raytrace.c rayorigin and raycont, m_clip.c): a ray crossing an
// antimatter surface from its front enters the volume, and the modifiers it clips become
// invisible to the continuing ray; crossing from the back leaves it. Rays spawned at a
// surface (shadow, reflected, transmitted, ambient) start with the set of the ray that
// hit it, so light reaches a point through a hole just as the eye sees through it.
//
// RADIANCE compat: an antimatter's first modifier, unless void, is meant (ray.html) to
// shade its surface where a ray from inside the clipped object meets it, but m_clip.c
// compares the ray's type with the whole RAYREFL mask, which no single type equals, so
// RADIANCE 5.4 never does so. Neither do we: antimatter surfaces only pass rays on.
//
// The fixed capacity keeps the state a plain value copied with every ray; modifiers
// beyond it are ignored (RADIANCE stops with an error at its MAXSET, far larger; scenes
// nest antimatter a few levels deep at most).
class ClipSet {
public:
    static constexpr int kCapacity = 16;

    bool contains(int32_t modifier) const {
        for (int i = 0; i < n_; ++i)
            if (mods_[size_t(i)] == modifier) return true;
        return false;
    }
    bool empty() const { return n_ == 0; }

    // The ray crosses an antimatter surface that clips `modifiers`: from the front
    // (`entering`) they are added, from the back removed.
    void cross(std::span<const int32_t> modifiers, bool entering) {
        for (int32_t m : modifiers) {
            if (entering) {
                if (!contains(m) && n_ < kCapacity) mods_[size_t(n_++)] = m;
                continue;
            }
            for (int i = 0; i < n_; ++i)
                if (mods_[size_t(i)] == m) {
                    mods_[size_t(i)] = mods_[size_t(--n_)];
                    break;
                }
        }
    }

private:
    std::array<int32_t, kCapacity> mods_{};
    uint8_t n_ = 0;
};

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
