// Cone integrals, cone sampling and -dp direction tables (see aperture.h).
#include "light/aperture.h"

#include <algorithm>
#include <cmath>

#include "geometry/surface.h"
#include "util/fast_minmax.h"

namespace rp::light {

namespace {

// 8-point Gauss-Legendre on [-1, 1] (Abramowitz & Stegun 25.4.30).
constexpr double kGaussX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                               0.9602898564975363};
constexpr double kGaussW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                               0.1012285362903763};

// Integral over psi in [0, 2 pi) of max(0, A + B cos psi), B >= 0.
double azimuthal(double A, double B) {
    if (A >= B) return 2 * kPi * A;
    if (A <= -B) return 0;
    double psi0 = std::acos(std::clamp(-A / B, -1.0, 1.0));
    return 2 * (A * psi0 + B * std::sin(psi0));
}

// Composite Gauss-Legendre of f over [lo, hi] with `pieces` equal subintervals.
template <class F>
double gauss(F f, double lo, double hi, int pieces) {
    double sum = 0, h = (hi - lo) / pieces;
    for (int i = 0; i < pieces; ++i) {
        double mid = lo + (i + 0.5) * h, half = 0.5 * h;
        for (int k = 0; k < 4; ++k)
            sum += kGaussW[k] * half * (f(mid - half * kGaussX[k]) + f(mid + half * kGaussX[k]));
    }
    return sum;
}

}  // namespace

double projectedSolidAngle(const Vec3& a, double cosHalf, const Vec3& n) {
    double an = std::clamp(dot(a, n), -1.0, 1.0);
    double r = std::sqrt(std::fmax(0.0, 1 - an * an));
    double c0 = std::clamp(cosHalf, -1.0, 1.0);
    // Cone wholly above the surface: n . integral(w dw) = pi sin^2 (a.n).
    double sinHalf = std::sqrt(std::fmax(0.0, 1 - c0 * c0));
    if (c0 >= 0 && an * c0 - r * sinHalf >= 0) return kPi * (1 - c0 * c0) * an;
    // t = cos(theta) about the axis; the integrand h(t an, sqrt(1 - t^2) r) has kinks
    // where |t an| = sqrt(1 - t^2) r, i.e. t = +-r.
    auto integrand = [&](double t) {
        return azimuthal(t * an, std::sqrt(std::fmax(0.0, 1 - t * t)) * r);
    };
    double cuts[4] = {c0, -r, r, 1.0};
    std::sort(cuts, cuts + 4);
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
        double lo = std::fmax(cuts[i], c0), hi = cuts[i + 1];
        if (hi > lo) sum += gauss(integrand, lo, hi, 64);
    }
    return sum;
}

void coneFrame(const Vec3& w, Vec3& u, Vec3& v) { orthonormalFrame(w, u, v); }

namespace {

Vec3 fromCone(const Vec3& axis, double cosTheta, double phi) {
    Vec3 u, v;
    coneFrame(axis, u, v);
    double sinTheta = std::sqrt(fastMax(0.0, 1 - cosTheta * cosTheta));
    return normalize(u * (std::cos(phi) * sinTheta) + v * (std::sin(phi) * sinTheta) +
                     axis * cosTheta);
}

// Malley's method: a point uniform in the disc of `radius` (drawn by rejection from its
// square, no trigonometry), projected up onto the hemisphere about n.
Vec3 projectDiscPoint(const Vec3& n, const Vec3& u, const Vec3& v, double radius, Rng& rng) {
    double x, y;
    const double r2 = uniformDiscPoint(rng, radius, x, y);
    return u * x + v * y + n * std::sqrt(fastMax(0.0, 1 - r2));
}

}  // namespace

Vec3 sampleCosineHemisphere(const Vec3& n, const Vec3& u, const Vec3& v, Rng& rng) {
    return projectDiscPoint(n, u, v, 1.0, rng);  // sampleProjectedCone's radius for cosHalf 0
}

Vec3 sampleUniformCone(const Cone& c, Rng& rng) {
    double cosTheta = 1 - rng.uniform() * (1 - c.cosHalf);
    return fromCone(c.axis, cosTheta, 2 * kPi * rng.uniform());
}

Vec3 sampleProjectedCone(const Cone& c, const Vec3& n, Rng& rng) {
    double an = std::clamp(dot(c.axis, n), -1.0, 1.0);
    if (an > 1 - 1e-12) {
        // Centred on the normal: sin^2 uniform in [0, 1 - max(cosHalf,0)^2], i.e. a point
        // uniform in the disc of that radius, projected up onto the hemisphere.
        const double cmin = std::fmax(c.cosHalf, 0.0), radius = std::sqrt(1 - cmin * cmin);
        Vec3 u, v;
        coneFrame(n, u, v);
        return projectDiscPoint(n, u, v, radius, rng);
    }
    // Largest w.n in the cone bounds the rejection ratio of a uniform-cone proposal.
    double alpha = std::acos(an), half = std::acos(std::clamp(c.cosHalf, -1.0, 1.0));
    double maxCos = alpha <= half ? 1.0 : std::cos(alpha - half);
    // Acceptance: cosine hemisphere g/pi, uniform cone g/(Omega maxCos); take the larger.
    bool useHemisphere = kPi <= c.solidAngle() * maxCos;
    for (int i = 0; i < 1000000; ++i) {
        if (useHemisphere) {
            double cos2 = rng.uniform();
            Vec3 w = fromCone(n, std::sqrt(1 - cos2), 2 * kPi * rng.uniform());
            if (dot(w, c.axis) >= c.cosHalf) return w;
        } else {
            Vec3 w = sampleUniformCone(c, rng);
            if (rng.uniform() * maxCos < dot(w, n)) return w;
        }
    }
    return c.axis;  // unreachable unless the cone is (numerically) below the surface
}

void DirectionTable::init(const Cone& cone, double samplesPerSr) {
    axis_ = cone.axis;
    coneFrame(axis_, u_, v_);
    cosHalf_ = std::clamp(cone.cosHalf, -1.0, 1.0);
    // pmapsrc.c: numTheta / numPhi = 1 / pi, numTheta * numPhi ~ dp * solid angle.
    double du = std::sqrt(std::fmax(samplesPerSr, 0.0) * 2 * (1 - cosHalf_));
    nTheta_ = uint32_t(std::fmax(du + 0.5, 1.0));
    nPhi_ = uint32_t(std::fmax(kPi * du + 0.5, 1.0));
    // Cell indices are 16-bit: cap at -dp ~ 1e8 / sr, far beyond any practical value.
    nTheta_ = std::min(nTheta_, 65535u);
    nPhi_ = std::min(nPhi_, 65535u);
    cellSolidAngle_ = 2 * kPi * (1 - cosHalf_) / (double(nTheta_) * nPhi_);
    if (size_t(nTheta_) * nPhi_ <= kMaxKeptCentres) {
        auto centres = std::make_shared<std::vector<Vec3>>();
        centres->reserve(size_t(nTheta_) * nPhi_);
        for (uint32_t t = 0; t < nTheta_; ++t)
            for (uint32_t p = 0; p < nPhi_; ++p) centres->push_back(cellDirection(t, p, 0.5, 0.5));
        centres_ = std::move(centres);
    }
}

void DirectionTable::add(uint32_t t, uint32_t p, const Color& value) {
    double mean = value.average();
    if (!(mean > 0)) return;
    float prev = cells_.empty() ? 0.0f : cells_.back().cdf;
    cells_.push_back({uint16_t(t),
                      uint16_t(p),
                      prev + float(mean),
                      {float(value.r), float(value.g), float(value.b)}});
    integral_ += value * cellSolidAngle_;
}

Vec3 DirectionTable::cellDirection(uint32_t t, uint32_t p, double ju, double jv) const {
    double cosTheta = 1 - (t + ju) * (1 - cosHalf_) / nTheta_;
    double sinTheta = std::sqrt(std::fmax(0.0, 1 - cosTheta * cosTheta));
    double phi = 2 * kPi * (p + jv) / nPhi_;
    return normalize(u_ * (std::cos(phi) * sinTheta) + v_ * (std::sin(phi) * sinTheta) +
                     axis_ * cosTheta);
}

const DirectionTable::Cell& DirectionTable::pick(double u) const {
    float target = float(u) * cells_.back().cdf;
    auto it = std::upper_bound(cells_.begin(), cells_.end(), target,
                               [](float x, const Cell& c) { return x < c.cdf; });
    return it == cells_.end() ? cells_.back() : *it;
}

}  // namespace rp::light
