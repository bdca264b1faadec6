// How the atmosphere's tables are laid out and read (internal to atmosphere*.cpp): the
// geometry of rays in a spherical shell, Bruneton's parametrisation of each table by
// distances to the shell's boundaries (which puts grid points where the light changes
// fastest, near the horizon), and multilinear lookups. Every axis runs over [0, 1] with
// its n grid points at k / (n - 1). The scattering tables keep rays that meet the ground
// and rays that do not in separate halves of the mu axis, never interpolated across.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "gen/atmosphere.h"

namespace rp::gen::atmos::grid {

inline const double kH = std::sqrt(kTopRadius * kTopRadius - kGroundRadius * kGroundRadius);

inline double clampCosine(double mu) { return std::clamp(mu, -1.0, 1.0); }
inline double safeSqrt(double a) { return std::sqrt(std::max(a, 0.0)); }

inline double distanceToTop(double r, double mu) {
    return std::max(0.0, -r * mu + safeSqrt(r * r * (mu * mu - 1) + kTopRadius * kTopRadius));
}
inline double distanceToGround(double r, double mu) {
    return std::max(0.0, -r * mu - safeSqrt(r * r * (mu * mu - 1) + kGroundRadius * kGroundRadius));
}
inline bool hitsGround(double r, double mu) {
    return mu < 0 && r * r * (mu * mu - 1) + kGroundRadius * kGroundRadius >= 0;
}
inline double distanceToBoundary(double r, double mu, bool ground) {
    return ground ? distanceToGround(r, mu) : distanceToTop(r, mu);
}
// Radius and cosines a distance d along the ray (r, mu); muS and nu give the sun.
inline double radiusAt(double r, double mu, double d) {
    return std::clamp(std::sqrt(d * d + 2 * r * mu * d + r * r), kGroundRadius, kTopRadius);
}

inline double rayleighPhase(double nu) { return 3.0 / (16.0 * kPi) * (1 + nu * nu); }
// Cornette-Shanks, as Bruneton's model.
inline double miePhase(double nu) {
    const double g = kMieEccentricity;
    const double k = 3.0 / (8.0 * kPi) * (1 - g * g) / (2 + g * g);
    return k * (1 + nu * nu) / std::pow(1 + g * g - 2 * g * nu, 1.5);
}

// Transmittance table: x over mu, y over r.
struct Unit2 {
    double x, y;
};
inline Unit2 transmittanceUnit(double r, double mu) {
    const double rho = safeSqrt(r * r - kGroundRadius * kGroundRadius);
    const double dMin = kTopRadius - r, dMax = rho + kH;
    return {std::clamp((distanceToTop(r, mu) - dMin) / (dMax - dMin), 0.0, 1.0),
            std::clamp(rho / kH, 0.0, 1.0)};
}
inline void transmittanceParams(Unit2 u, double& r, double& mu) {
    const double rho = kH * u.y;
    r = std::sqrt(rho * rho + kGroundRadius * kGroundRadius);
    const double dMin = kTopRadius - r, dMax = rho + kH;
    const double d = dMin + u.x * (dMax - dMin);
    mu = d == 0 ? 1.0 : clampCosine((kH * kH - rho * rho - d * d) / (2 * r * d));
}

// Scattering tables: r, mu (within its half), muS, nu.
struct Unit4 {
    double r, mu, muS, nu;
};
double muSUnit(double muS);
double muSOfUnit(double x);
Unit4 scatteringUnit(double r, double mu, double muS, double nu, bool ground);
// Inverse; nu is brought within what mu and muS allow.
void scatteringParams(const Unit4& u, bool ground, double& r, double& mu, double& muS, double& nu);
// r of the scattering tables' unit coordinate.
inline double scatteringRadius(double x) {
    const double rho = kH * x;
    return std::sqrt(rho * rho + kGroundRadius * kGroundRadius);
}

// Irradiance table: x over muS, y over height.
inline Unit2 irradianceUnit(double r, double muS) {
    return {std::clamp(0.5 * muS + 0.5, 0.0, 1.0),
            std::clamp((r - kGroundRadius) / (kTopRadius - kGroundRadius), 0.0, 1.0)};
}

// One axis of a multilinear lookup: the lower grid point and the weight of the upper.
struct Span {
    int i0;
    double w;
};
inline Span span(double x, int n) {
    const double f = std::clamp(x, 0.0, 1.0) * (n - 1);
    const int i0 = std::min(static_cast<int>(f), n - 2);
    return {i0, f - i0};
}
inline double gridUnit(int i, int n) { return static_cast<double>(i) / (n - 1); }

inline void addScaled(const float* p, double w, Spectrum& out) {
    for (int b = 0; b < kBands; ++b) out[b] += w * p[b];
}

// Lookups in the three kinds of table (sizes from `res`).
Spectrum lookup2(const std::vector<float>& t, int ny, int nx, Unit2 u);
Spectrum lookupScattering(const std::vector<float>& t, const Resolution& res, double r, double mu,
                          double muS, double nu, bool ground);
inline size_t scatteringSize(const Resolution& res) {
    return size_t(res.scatteringR) * res.scatteringMu * res.scatteringMuS * res.scatteringNu *
           kBands;
}
// Offset of a grid cell; mu indexes the whole axis (the ground half first).
inline size_t scatteringIndex(const Resolution& res, int r, int mu, int muS, int nu) {
    return (((size_t(r) * res.scatteringMu + mu) * res.scatteringMuS + muS) * res.scatteringNu +
            nu) *
           kBands;
}

// Transmittance between the ray's origin and the point d along it, from the table `t`.
Spectrum transmittanceAlong(const std::vector<float>& t, const Resolution& res, double r, double mu,
                            double d, bool ground);
// Transmittance to the sun, faded out as the sun's disc sets behind the horizon.
Spectrum transmittanceToSun(const std::vector<float>& t, const Resolution& res, double r,
                            double muS);

}  // namespace rp::gen::atmos::grid
