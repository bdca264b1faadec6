// One irradiance computation of the ambient calculation: stratified cosine-weighted
// hemisphere sampling over (theta, phi) divisions, -as super-sampling of the divisions
// that vary most, and Ward & Heckbert's (1992) rotational and translational gradients.
// Caching, record radii and the -a option logic live in ambient.cpp / irradiance_cache.h.
#pragma once

#include <vector>

#include "render/ambient.h"
#include "util/color.h"
#include "util/rng.h"
#include "util/vec.h"

namespace rp::render {

// RADIANCE's assumed average reflectance (ambient.h AVGREFL): the factor by which a
// hemisphere sample's weight drops, and the per-level weight of cached values.
constexpr double kAverageReflectance = 0.5;

struct HemisphereParams {
    int thetaDivisions = 1;   // M: rows in sin^2(theta) (equal cosine-weighted measure)
    int phiDivisions = 1;     // N: columns in phi
    int superSamples = 0;     // extra samples, given to the divisions with largest variance
    int sampleLevel = 1;      // ambient level of the sample rays
    double sampleWeight = 1;  // RADIANCE weight of each sample ray
    bool gradients = true;    // compute the Ward & Heckbert gradients
};

// Division counts for `divisions` (-ad) times `weight`, and the -as super-sample count
// as*wt + .5.
//  - For the irradiance cache (`cached`): RADIANCE 3 inithemi's M = sqrt(ad*wt/pi) + .5
//    rows (at least 3), N = pi*M + .5 columns: cells about square, as the gradients want.
//  - Without it: RADIANCE 5 (ambcomp.c samp_hemi) traces n*n samples, n = sqrt(ad*wt) +
//    .5 and at least 1, so a ray of little weight gets one sample; the same count here,
//    laid out in as square cells as M x N allows (M = n/sqrt(pi) + .5, N = n*n/M + .5:
//    n*n for n = 1, 2, 4, 6, 10 for 9, and within 4 % from n = 5 on).
HemisphereParams hemisphereDivisions(int divisions, int supersamples, double weight, bool cached);

struct HemisphereEstimate {
    Color value;                    // mean radiance over the cosine-weighted hemisphere (E / pi)
    double sumInverseDistance = 0;  // sum of 1/distance over every sample (radius: harmonic mean)
    int samples = 0;                // rays traced
    int hits = 0;                   // of which met a surface (the others escaped to sources/sky)
    // Divisions whose first sample was not traced (HemisphereTracer::Sample::traced): a
    // value with any is not cached, one with all of them not used (ambcomp.c sampOK).
    int untraced = 0;
    int divisions = 0;
    // Gradients of brightness(value) (Color::brightness), not yet normalised:
    Vec3 gradPosition;   // d value / d position (tangent plane), per unit length
    Vec3 gradDirection;  // rotation vector gradient: value(N') ~ value + g . (N x N')
    // Hessian of value under translation in the tangent plane, in the (u, v) frame of
    // tangentFrame(normal): xx, xy, yy (per unit length squared; see sampleHemisphere).
    double hessian[3] = {0, 0, 0};
    // Largest |eigenvalue| of `hessian`: the strongest curvature of the value.
    double maxCurvature() const;
    // What the leak test of a record needs (ambient.cpp corralFlags): per phi column (the
    // first centred at phi = pi/N from tangentFrame's u), the nearest surface seen near the
    // horizon (rows with sin^2 theta above 0.8; 1e10 where none was), and the mean of
    // 1/distance over the divisions overhead (sin theta <= 1/2; 0 where rays escaped).
    std::vector<double> horizonDistance;
    double overheadInverseDistance = 0;
};

// Traces the hemisphere above unit `normal` from `origin`. Allocates its division table
// per call (not on the lookup hot path; the tracer may recurse into another computation
// on the same thread, so per-thread scratch could not be shared safely).
HemisphereEstimate sampleHemisphere(const Vec3& origin, const Vec3& normal,
                                    const HemisphereParams& params, HemisphereTracer& tracer,
                                    Rng& rng);

// An orthonormal tangent frame (u, v, n) with u x v = n (Duff et al. 2017, branchless).
void tangentFrame(const Vec3& n, Vec3& u, Vec3& v);

}  // namespace rp::render
