// RADIANCE cone family: `cone`, `cup` (inside-out cone), `cylinder`, `tube` (inside-out
// cylinder). One truncated-cone shape covers all four; exact double-precision
// intersection and surface frame. End caps are not part of these surfaces (ray.html).
#pragma once

#include <cstdint>

#include "geometry/surface.h"
#include "scene/primitive.h"

namespace rp {

struct ConeShape {
    Vec3 p0;        // first end point (v = 0)
    Vec3 axis;      // unit, from p0 toward p1
    double length;  // |p1 - p0|
    double r0, r1;  // radii at p0 and p1 (>= 0, not both zero)
    double slope;   // (r1 - r0) / length
    Vec3 e1, e2;    // frame about the axis for u
    bool inward;    // cup, tube
    int32_t prim;
    int32_t modifier;
};

// From cone/cup "x0 y0 z0 x1 y1 z1 r0 r1" or cylinder/tube "x0 y0 z0 x1 y1 z1 r".
// RADIANCE compat (cone.c): negative radii warn and swap cone<->cup, cylinder<->tube;
// radii that are both zero or of opposite sign, and a zero-length axis, warn and make
// the primitive be ignored (returns false). Bad argument counts throw InputError.
bool makeCone(const Primitive& prim, int32_t primIndex, ConeShape& shape);

bool intersectCone(const ConeShape& c, const Vec3& o, const Vec3& d, double tmin, double tmax,
                   double& t);

// The unit normal at p (outward for cone and cylinder, inward for cup and tube).
Vec3 coneNormal(const ConeShape& c, const Vec3& p);

Bounds3 coneBounds(const ConeShape& c);

// Bounds of a disk of radius r about centre with unit normal n (cone ends, rings).
Bounds3 diskBounds(const Vec3& centre, const Vec3& n, double r);

}  // namespace rp
