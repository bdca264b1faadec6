// The Henyey-Greenstein phase function of participating media (RADIANCE's mist, -mg):
// evaluated for backward in-scattering and photon density estimates, sampled for photons
// scattering in a medium. One definition for the renderer and mkpmap.
#pragma once

#include <cmath>

#include "util/rng.h"
#include "util/vec.h"

namespace rp {

// RADIANCE compat (source.c srcscatter, pmap.c photonParticipate): an eccentricity at or
// below FTINY scatters isotropically, so a negative g does not favour back-scattering.
inline bool isotropicPhase(double g) { return g <= 1e-6; }

// The phase function times 4 pi (1 for isotropic scattering) for light travelling along
// `in` scattered into `out`, with cosTheta = dot(in, out): RADIANCE's P(theta).
inline double henyeyGreenstein4Pi(double g, double cosTheta) {
    if (isotropicPhase(g)) return 1;
    const double d = 1 + g * g - 2 * g * cosTheta;
    return (1 - g * g) / (d * std::sqrt(d));
}

// A direction scattered from unit `in` with the phase function's density (inverse
// transform of its cosine, uniform azimuth).
inline Vec3 sampleHenyeyGreenstein(const Vec3& in, double g, Rng& rng) {
    const double xi = rng.uniform();
    double c;
    if (isotropicPhase(g)) {
        c = 2 * xi - 1;
    } else {
        const double s = (1 - g * g) / (1 + g * (2 * xi - 1));
        c = (1 + g * g - s * s) / (2 * g);
    }
    c = std::fmax(-1.0, std::fmin(1.0, c));
    const double sinTheta = std::sqrt(std::fmax(0.0, 1 - c * c));
    const double phi = 2 * kPi * rng.uniform();
    Vec3 u, v;
    orthonormalFrame(in, u, v);
    return normalize(u * (sinTheta * std::cos(phi)) + v * (sinTheta * std::sin(phi)) + in * c);
}

}  // namespace rp
