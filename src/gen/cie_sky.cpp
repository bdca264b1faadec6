// CIE sky luminance formulas as skybright.cal evaluates them, and gensky's normalisation
// polynomial fits. Clear sky: CIE 1973 (Kittler); overcast: Moon & Spencer 1942;
// intermediate: the CIE intermediate formula RADIANCE's skybright.cal uses.
#include "gen/cie_sky.h"

#include <algorithm>
#include <cmath>

namespace rp::gen {

double clearSkyF2(double alt) {
    double sz = std::sin(alt);
    return 0.274 * (0.91 + 10.0 * std::exp(-3.0 * (kPi / 2.0 - alt)) + 0.45 * sz * sz);
}

double intermediateSkyF2(double alt) {
    return (2.739 + .9891 * std::sin(.3119 + 2.6 * alt)) *
           std::exp(-(kPi / 2.0 - alt) * (.4441 + 1.48 * alt));
}

double skyNormalisationFit(double alt, bool intermediate) {
    static constexpr double kFit[2][5] = {
        {2.766521, 0.547665, -0.369832, 0.009237, 0.059229},  // clear
        {3.5556, -2.7152, -1.3081, 1.0660, 0.60227},          // intermediate
    };
    const double* c = kFit[intermediate ? 1 : 0];
    double x = (alt - kPi / 4.0) / (kPi / 4.0);
    double v = c[4];
    for (int i = 3; i >= 0; --i) v = v * x + c[i];
    return v;
}

double skyRadiance(SkyType type, double zenith, double f2, const Vec3& sunDir, const Vec3& dir) {
    double cosGamma = std::clamp(dot(dir, sunDir), -1.0, 1.0);
    double gamma = std::acos(cosGamma);
    switch (type) {
        case SkyType::Uniform:
            return zenith;
        case SkyType::Overcast:
            return zenith * (1 + 2 * dir.z) / 3;
        case SkyType::Clear: {
            double gradation = dir.z > .01 ? 1 - std::exp(-.32 / dir.z) : 1.0;
            return zenith * (.91 + 10 * std::exp(-3 * gamma) + .45 * cosGamma * cosGamma) *
                   gradation / f2;
        }
        case SkyType::Intermediate: {
            double eta = std::acos(std::clamp(dir.z, -1.0, 1.0));
            double zt = std::acos(std::clamp(sunDir.z, -1.0, 1.0));
            return zenith *
                   ((1.35 * std::sin(5.631 - 3.59 * eta) + 3.12) * std::sin(4.396 - 2.6 * zt) +
                    6.37 - eta) /
                   2.326 * std::exp(gamma * -.563 * ((2.629 - eta) * (1.562 - zt) + .812)) / f2;
        }
    }
    return 0;
}

double skyHorizontalIrradiance(SkyType type, double zenith, double f2, const Vec3& sunDir,
                               int nTheta, int nPhi) {
    double sum = 0;
    double dTheta = 0.5 * kPi / nTheta, dPhi = 2 * kPi / nPhi;
    for (int i = 0; i < nTheta; ++i) {
        double th = (i + 0.5) * dTheta;
        double st = std::sin(th), ct = std::cos(th);
        for (int j = 0; j < nPhi; ++j) {
            double ph = (j + 0.5) * dPhi;
            Vec3 d(st * std::cos(ph), st * std::sin(ph), ct);
            sum += skyRadiance(type, zenith, f2, sunDir, d) * ct * st;
        }
    }
    return sum * dTheta * dPhi;
}

}  // namespace rp::gen
