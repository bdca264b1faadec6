// The modifiers a ray or a photon cannot see because it is inside antimatter volumes
// (RADIANCE's clipset; ray.html "Antimatter", m_clip.c). Used by the backward pass
// (render/clip_set.h) and the photon tracer alike.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace rp::material {

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

}  // namespace rp::material
