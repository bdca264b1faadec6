// Small helpers shared by the analytic shapes (sphere.h, cone.h, ring.h).
#pragma once

#include <cmath>

#include "util/vec.h"

namespace rp {

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
