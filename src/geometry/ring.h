// RADIANCE `ring`: a disk or annulus "xc yc zc xdir ydir zdir r0 r1" facing along its
// direction vector. Exact double-precision intersection and surface frame.
#pragma once

#include <cstdint>

#include "geometry/surface.h"
#include "scene/primitive.h"

namespace rp {

struct RingShape {
    Vec3 centre;
    Vec3 normal;    // unit; the front side
    double r0, r1;  // inner and outer radius, 0 <= r0 < r1
    Vec3 e1, e2;    // frame about the normal for u
    int32_t prim;
    int32_t modifier;
};

// RADIANCE compat (cone.c): radii are swapped if r0 > r1; equal radii or a zero
// direction warn and return false; negative radii are an InputError for rings.
bool makeRing(const Primitive& prim, int32_t primIndex, RingShape& shape);

bool intersectRing(const RingShape& r, const Vec3& o, const Vec3& d, double tmin, double tmax,
                   double& t);

Bounds3 ringBounds(const RingShape& r);

}  // namespace rp
