// The world-space ray values at a point where a modifier is evaluated (a shaded hit, a
// shadow ray meeting a light, a photon leaving one). Carrying them into a modifier's
// own space is function_space.h; walking a chain of modifiers is surface_chain.h.
#pragma once

#include "geometry/ray.h"
#include "scene/xform.h"
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
    // Inside an instance or mesh, the space its function files see (RADIANCE ray.rox:
    // their coordinates move with the object); null for world space.
    const TransformPair* object = nullptr;
    double lu = 0, lv = 0;  // Lu, Lv: a mesh's (u, v) (0 elsewhere)

    // Where a ray travelling `dir` met a surface at `distance`: Rdot follows from D and N.
    static PatternPoint atHit(const Vec3& dir, const Vec3& point, const Vec3& normal,
                              double distance) {
        return {dir, point, normal, distance, -dot(dir, normal)};
    }
    // Where a ray travelling `dir` made `hit`, with the object space and (u, v) it carries.
    static PatternPoint atHit(const Vec3& dir, const Hit& hit) {
        PatternPoint at = atHit(dir, hit.point, hit.normal, hit.t);
        at.object = hit.objectSpace;
        at.lu = hit.u;
        at.lv = hit.v;
        return at;
    }
};

}  // namespace rp::material
