// The world-space ray values at a point where a modifier is evaluated (a shaded hit, a
// shadow ray meeting a light, a photon leaving one). Carrying them into a modifier's
// own space is function_space.h; walking a chain of modifiers is surface_chain.h.
#pragma once

#include "util/vec.h"

namespace rp::material {

// World-space values at the point being shaded or emitting (ray.html, "Function Files").
struct PatternPoint {
    Vec3 dir;             // D: ray direction. At a light it points towards the source:
                          // the shadow ray's direction, or minus the photon's direction
                          // for photon emission (photon-map manual 3.1.2)
    Vec3 point;           // P
    Vec3 normal;          // N: the surface normal, not flipped toward the ray
    double distance = 0;  // T (undefined for emission: 0)
    double rdot = 0;      // Rdot = -D.N: positive in front; at a light, the cosine between
                          // the emitted direction and the surface normal

    // Where a ray travelling `dir` met a surface at `distance`: Rdot follows from D and N.
    static PatternPoint atHit(const Vec3& dir, const Vec3& point, const Vec3& normal,
                              double distance) {
        return {dir, point, normal, distance, -dot(dir, normal)};
    }
};

}  // namespace rp::material
