// Ring (see ring.h).
#include "geometry/ring.h"

#include <cmath>
#include <string>
#include <utility>

#include "geometry/cone.h"
#include "util/warnings.h"

namespace rp {

bool makeRing(const Primitive& prim, int32_t primIndex, RingShape& shape) {
    const std::string what = "ring '" + prim.name + "'";
    const std::vector<double>& a = prim.rargs;
    if (a.size() != 8)
        throw InputError(prim.loc,
                         what + ": expected 8 real arguments, got " + std::to_string(a.size()));
    constexpr double kFtiny = 1e-6;
    if (a[6] < -kFtiny || a[7] < -kFtiny) throw InputError(prim.loc, what + ": negative radii");
    double r0 = std::fmax(0.0, a[6]), r1 = std::fmax(0.0, a[7]);
    if (r0 > r1) std::swap(r0, r1);
    if (r1 - r0 <= kFtiny) {
        warn(prim.loc, what + ": illegal radii, ignored");
        return false;
    }
    Vec3 n{a[3], a[4], a[5]};
    if (!(length(n) > 0)) {
        warn(prim.loc, what + ": unknown orientation (zero direction), ignored");
        return false;
    }
    shape.centre = {a[0], a[1], a[2]};
    shape.normal = normalize(n);
    shape.r0 = r0;
    shape.r1 = r1;
    orthonormalFrame(shape.normal, shape.e1, shape.e2);
    shape.prim = primIndex;
    shape.modifier = prim.modifier;
    return true;
}

bool intersectRing(const RingShape& r, const Vec3& o, const Vec3& d, double tmin, double tmax,
                   double& t) {
    double dn = dot(d, r.normal);
    if (dn == 0) return false;  // ray in the ring's plane
    Vec3 oc = o - r.centre;     // relative coordinates keep precision far from 0
    double tt = -dot(oc, r.normal) / dn;
    if (!(tt > tmin && tt < tmax)) return false;
    Vec3 rel = oc + d * tt;
    rel -= r.normal * dot(rel, r.normal);  // remove the rounding off the plane
    double rr = lengthSquared(rel);
    if (rr < r.r0 * r.r0 || rr > r.r1 * r.r1) return false;
    t = tt;
    return true;
}

Bounds3 ringBounds(const RingShape& r) { return diskBounds(r.centre, r.normal, r.r1); }

}  // namespace rp
