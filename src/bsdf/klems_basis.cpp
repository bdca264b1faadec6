// LBNL's Klems angle bases (klems_basis.h).
#include "bsdf/klems_basis.h"

#include <algorithm>
#include <cmath>

namespace rp::bsdf {

namespace {

double sq(double x) { return x * x; }

constexpr double kDeg = kPi / 180;

KlemsBasis makeBasis(const char* name, std::vector<KlemsLatitude> lat) {
    KlemsBasis b{name, 0, std::move(lat)};
    for (const KlemsLatitude& l : b.lat) b.nangles += l.nphis;
    return b;
}

}  // namespace

const std::vector<KlemsBasis>& standardKlemsBases() {
    static const std::vector<KlemsBasis> bases{
        makeBasis("LBNL/Klems Full", {{0, 1},
                                      {5, 8},
                                      {15, 16},
                                      {25, 20},
                                      {35, 24},
                                      {45, 24},
                                      {55, 24},
                                      {65, 16},
                                      {75, 12},
                                      {90, 0}}),
        makeBasis(
            "LBNL/Klems Half",
            {{0, 1}, {6.5, 8}, {19.5, 12}, {32.5, 16}, {46.5, 20}, {61.5, 12}, {76.5, 4}, {90, 0}}),
        makeBasis("LBNL/Klems Quarter", {{0, 1}, {9, 8}, {27, 12}, {46, 12}, {66, 8}, {90, 0}}),
    };
    return bases;
}

Vec3 klemsPatchVector(const KlemsBasis& b, int ndx, double rx, double ry) {
    std::size_t li = 0;
    while (ndx >= b.lat[li].nphis) ndx -= b.lat[li++].nphis;
    const double c2 = (1 - rx) * sq(std::cos(kDeg * b.lat[li].thetaMin)) +
                      rx * sq(std::cos(kDeg * b.lat[li + 1].thetaMin));
    const double cz = std::sqrt(c2), sz = std::sqrt(std::max(0.0, 1 - c2));
    const double azi = 2 * kPi * (ndx + ry - .5) / b.lat[li].nphis;
    return {std::cos(azi) * sz, std::sin(azi) * sz, cz};
}

}  // namespace rp::bsdf
