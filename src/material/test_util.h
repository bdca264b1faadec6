// Helpers shared by the material/ unit tests: building Primitive records, random
// directions, and running many photons through scatterPhoton. Test-only.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "material/material.h"

namespace rp::material::test {

inline Primitive prim(PrimType t, std::vector<double> r, std::vector<std::string> s = {},
                      int line = 7) {
    Primitive p;
    p.type = t;
    p.name = "m";
    p.rargs = std::move(r);
    p.sargs = std::move(s);
    p.loc = SourceLoc{"test.rad", line};
    return p;
}

// Uniform direction on the unit sphere.
inline Vec3 uniformSphere(Rng& rng) {
    double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
    double s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

// Incident travel direction at angle thetaDeg from the normal +z (arriving from above).
inline Vec3 incident(double thetaDeg, double phiDeg = 30) {
    double t = thetaDeg * kPi / 180, p = phiDeg * kPi / 180;
    return {-std::sin(t) * std::cos(p), -std::sin(t) * std::sin(p), -std::cos(t)};
}

// Sample mean and standard error (per channel) of the scattered flux factor.
struct FluxStats {
    Color mean, stderr_;
    long counts[6] = {0, 0, 0, 0, 0, 0};  // by ScatterKind
};

template <class Fn>
FluxStats photonStats(const MaterialParams& m, long n, uint64_t seed, Fn makePoint) {
    Rng rng(seed, RngDomain::Test, 0);
    Color sum, sum2;
    FluxStats st;
    for (long i = 0; i < n; ++i) {
        SurfacePoint sp = makePoint(rng);
        PhotonScatter s = scatterPhoton(m, sp, rng);
        st.counts[int(s.kind)]++;
        Color f = s.kind == ScatterKind::Absorbed ? Color{} : s.fluxFactor;
        sum += f;
        sum2 += f * f;
    }
    for (int c = 0; c < 3; ++c) {
        double mu = sum[c] / n, var = sum2[c] / n - mu * mu;
        st.mean[c] = mu;
        st.stderr_[c] = std::sqrt(std::max(var, 0.0) / n);
    }
    return st;
}

// 4 sigma of the sample mean, plus a floor for exact (zero-variance) cases.
inline void expectMeanNear(const FluxStats& st, const Color& expected, const char* what) {
    for (int c = 0; c < 3; ++c) {
        double tol = 4 * st.stderr_[c] + 1e-12;
        EXPECT_NEAR(st.mean[c], expected[c], tol) << what << " channel " << c;
    }
}

}  // namespace rp::material::test
