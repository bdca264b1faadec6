// LBNL's Klems angle bases (RADIANCE bsdf_m.c abase_list, fo_getvec): a basis is a list
// of latitude bands, each cut into equal azimuth patches. The BSDF reader (klems.cpp)
// and rfluxmtx's sender and receiver bases (src/flux) both use these.
#pragma once

#include <string>
#include <vector>

#include "util/vec.h"

namespace rp::bsdf {

struct KlemsLatitude {
    double thetaMin = 0;  // degrees
    int nphis = 0;        // 0 ends the list (its thetaMin is 90)
};

struct KlemsBasis {
    std::string name;
    int nangles = 0;
    std::vector<KlemsLatitude> lat;  // with the closing {90, 0}
};

// "LBNL/Klems Full", "LBNL/Klems Half" and "LBNL/Klems Quarter", in that order.
const std::vector<KlemsBasis>& standardKlemsBases();

// Patch `ndx` of the +Z hemisphere at fractional position (rx, ry) inside it: cos^2 of
// the polar angle uniform over the band and the azimuth over the patch (uniform in
// projected solid angle), patch 0 of a band centred on azimuth 0 (bsdf_m.c fo_getvec).
Vec3 klemsPatchVector(const KlemsBasis& b, int ndx, double rx, double ry);

}  // namespace rp::bsdf
