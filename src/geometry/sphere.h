// RADIANCE `sphere` and `bubble` (an inside-out sphere): exact double-precision ray
// intersection and surface frame. The accelerator calls these from its user geometry.
#pragma once

#include <cstdint>

#include "geometry/surface.h"
#include "scene/primitive.h"

namespace rp {

struct SphereShape {
    Vec3 center;
    double radius;
    bool inward;  // bubble: normal points to the centre
    int32_t prim;
    int32_t modifier;
};

// From `sphere`/`bubble` args "xc yc zc radius". Negative radius: warning, orientation
// flipped (RADIANCE compat, sphere.c). Zero radius: warning, returns false.
bool makeSphere(const Primitive& prim, int32_t primIndex, SphereShape& shape);

// Nearest t in (tmin, tmax) where o + t*d meets the sphere. Tangent rays miss.
bool intersectSphere(const SphereShape& s, const Vec3& o, const Vec3& d, double tmin, double tmax,
                     double& t);

// The unit normal at p (outward for a sphere, inward for a bubble).
Vec3 sphereNormal(const SphereShape& s, const Vec3& p);

Bounds3 sphereBounds(const SphereShape& s);

}  // namespace rp
