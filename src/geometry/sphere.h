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
bool intersectSphere(const SphereShape& s, const Vec3& o, const Vec3& d, double tmin,
                     double tmax, double& t);

SurfacePoint sphereSurface(const SphereShape& s, const Vec3& p);
// sphereSurface's normal alone (the same bits), for callers that need no (u, v): the
// photon tracer, which would otherwise pay an atan2 and an acos per sphere hit.
Vec3 sphereNormal(const SphereShape& s, const Vec3& p);

Bounds3 sphereBounds(const SphereShape& s);

}  // namespace rp
