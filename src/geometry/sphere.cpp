// Sphere and bubble (see sphere.h).
#include "geometry/sphere.h"

#include <cmath>
#include <string>

#include "util/warnings.h"

namespace rp {

bool makeSphere(const Primitive& prim, int32_t primIndex, SphereShape& shape) {
    const std::string kind(primTypeName(prim.type));
    if (prim.rargs.size() != 4)
        throw InputError(prim.loc, kind + " '" + prim.name + "': expected 4 real arguments, got " +
                                       std::to_string(prim.rargs.size()));
    const std::vector<double>& r = prim.rargs;
    shape.center = {r[0], r[1], r[2]};
    shape.radius = r[3];
    shape.inward = prim.type == PrimType::Bubble;
    shape.prim = primIndex;
    shape.modifier = prim.modifier;
    if (shape.radius < 0) {
        // RADIANCE compat: a negative radius turns a sphere into a bubble and vice versa.
        warn(prim.loc, kind + " '" + prim.name + "': negative radius");
        shape.radius = -shape.radius;
        shape.inward = !shape.inward;
    }
    if (!(shape.radius > 0)) {
        warn(prim.loc, kind + " '" + prim.name + "': zero radius, ignored");
        return false;
    }
    return true;
}

bool intersectSphere(const SphereShape& s, const Vec3& o, const Vec3& d, double tmin, double tmax,
                     double& t) {
    // Origin relative to the centre, and the discriminant from the distance of closest
    // approach (r^2 - |l|^2 factored), which stays accurate for rays that start far away
    // or nearly graze (Haines et al., Ray Tracing Gems ch. 7).
    Vec3 oc = o - s.center;
    double a = dot(d, d);
    double bHalf = dot(oc, d);
    double c = dot(oc, oc) - s.radius * s.radius;
    // Starting outside and moving away: both roots are negative (their product c/a > 0,
    // their sum -2 bHalf/a < 0), and so are the computed ones below (q < 0, t1 = c/q).
    // Why first: every photon a spherical lamp emits starts on it, moving out.
    if (c > 0 && bHalf > 0 && tmin >= 0) return false;
    Vec3 l = oc - d * (bHalf / a);
    // Clear misses without the square root (the accelerator calls this for every ray
    // through the sphere's bounding box): |l|^2 above r^2 by more than rounding means
    // |l| > r, so disc below is negative. Same answers as without the test.
    const double ll2 = dot(l, l);
    if (ll2 > s.radius * s.radius * (1 + 1e-9)) return false;
    double ll = std::sqrt(ll2);
    double disc = a * (s.radius - ll) * (s.radius + ll);
    if (!(disc > 0)) return false;
    double q = -(bHalf + std::copysign(std::sqrt(disc), bHalf));
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tmin && t0 < tmax) {
        t = t0;
        return true;
    }
    if (t1 > tmin && t1 < tmax) {
        t = t1;
        return true;
    }
    return false;
}

Vec3 sphereNormal(const SphereShape& s, const Vec3& p) {
    Vec3 n = normalize((p - s.center) / s.radius);
    return s.inward ? -n : n;
}

Bounds3 sphereBounds(const SphereShape& s) {
    Vec3 r{s.radius, s.radius, s.radius};
    return Bounds3{s.center - r, s.center + r};
}

}  // namespace rp
