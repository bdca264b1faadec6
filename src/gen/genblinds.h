// genblinds(1): RADIANCE's venetian blinds, nslats flat or curved slats stacked up the
// z axis, as polygons in RADIANCE's order, naming and number layout. Command parsing and
// geometry; the tool main is tools/genblinds.cpp.
#pragma once

#include <string>
#include <vector>

#include "gen/gen_text.h"

namespace rp::gen {

struct GenblindsOptions {
    std::string material;
    std::string name;
    double depth = 0;     // slat depth along x
    double width = 0;     // slat width along y
    double height = 0;    // height of the whole blind along z
    int slats = 0;        // nslats, spread evenly over the height
    double angleDeg = 0;  // tilt; positive lifts the +x edge
    // RADIANCE's rcurv: "-r R" gives +R, "+r R" gives -R; 0 = flat slats.
    double curvature = 0;
};

// genblinds mat name depth width height nslats angle [-r|+r rcurv]; args[0] is the
// program name. Throws InputError for a wrong word count, an option other than -r/+r,
// non-numeric words, non-positive depth, width, height or nslats, and a curvature radius
// below half the depth (RADIANCE would take asin of a number above 1 and print no slats).
GenblindsOptions parseGenblindsArgs(const std::vector<std::string>& args);

// Slat n (1..nslats) becomes polygons name.n.0 ... name.n.(m-1): one for flat slats,
// for curved ones as many as keep each facet's turn below 3 degrees.
std::vector<GenSurface> genblindsSurfaces(const GenblindsOptions& opt);

// The whole output: "# genblinds ..." then every polygon (tab-separated %18.12g).
std::string genblinds(const std::vector<std::string>& args);

}  // namespace rp::gen
