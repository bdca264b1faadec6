// Small helpers shared by the analytic shapes (sphere.h, cone.h, ring.h): the local
// surface record they return and the orthonormal frame used for their u coordinate.
#pragma once

#include <cmath>

#include "util/vec.h"

namespace rp {

// Normal and (u, v) at a point of a shape; see Hit in ray.h for what u, v mean.
struct SurfacePoint {
    Vec3 normal;
    double u = 0, v = 0;
};

// A fixed unit vector perpendicular to unit `axis`, so that angles about the axis are
// reproducible (Duff et al. 2017, "Building an orthonormal basis, revisited").
inline void orthonormalFrame(const Vec3& axis, Vec3& e1, Vec3& e2) {
    double sign = std::copysign(1.0, axis.z);
    double a = -1.0 / (sign + axis.z);
    double b = axis.x * axis.y * a;
    e1 = {1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
    e2 = {b, sign + axis.y * axis.y * a, -axis.y};
}

// Angle of radial vector r about the frame, as a fraction of a turn in [0, 1).
inline double turnFraction(const Vec3& r, const Vec3& e1, const Vec3& e2) {
    double f = std::atan2(dot(r, e2), dot(r, e1)) / (2 * kPi);
    return f < 0 ? f + 1 : f;
}

// Smallest root of a*t^2 + 2*bHalf*t + c in (tmin, tmax) accepted by `keep`, using the
// cancellation-free form of the quadratic formula. Returns false if none.
template <class Keep>
bool smallestRoot(double a, double bHalf, double c, double tmin, double tmax, Keep keep,
                  double& t) {
    double roots[2];
    int count = 0;
    if (std::fabs(a) <= 1e-14 * (std::fabs(bHalf) + std::fabs(c))) {
        if (bHalf == 0) return false;  // degenerate: no or infinitely many roots
        roots[count++] = -c / (2 * bHalf);
    } else {
        double disc = bHalf * bHalf - a * c;
        if (!(disc > 0)) return false;  // tangent rays graze: no hit
        double q = -(bHalf + std::copysign(std::sqrt(disc), bHalf));
        double r0 = q / a, r1 = c / q;
        roots[0] = std::fmin(r0, r1);
        roots[1] = std::fmax(r0, r1);
        count = 2;
    }
    for (int i = 0; i < count; ++i)
        if (roots[i] > tmin && roots[i] < tmax && keep(roots[i])) {
            t = roots[i];
            return true;
        }
    return false;
}

}  // namespace rp
