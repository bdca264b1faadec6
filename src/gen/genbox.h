// genbox(1): a RADIANCE box with one corner at the origin, optionally with bevelled
// (-b) or rounded (-r) edges, inward normals (-i), and (our extension) rounded edges
// tessellated into flat facets (-n). Command parsing, geometry and RADIANCE's text layout;
// the tool main is tools/genbox.cpp.
#pragma once

#include <string>
#include <vector>

#include "gen/gen_text.h"
#include "util/vec.h"

namespace rp::gen {

enum class BoxEdges { Square, Bevel, Round };

struct GenboxOptions {
    std::string material;
    std::string name;
    Vec3 size;                          // xsiz ysiz zsiz, all > 0
    bool inward = false;                // -i
    BoxEdges edges = BoxEdges::Square;  // -b bev / -r rad
    double edgeSize = 0;                // the bevel indentation or the rounding radius
    int segments = 0;                   // -n: facets per rounded edge (0 = cylinders/spheres)
};

// Parse genbox's command line; args[0] is the program name. Throws InputError for a
// wrong argument count, non-numeric or non-positive sizes, unknown options, a bevel or
// radius not smaller than half the smallest size, or -n without -r.
GenboxOptions parseGenboxArgs(const std::vector<std::string>& args);

// The surfaces in RADIANCE genbox's order and naming:
//   square box: polygons name.1540 name.4620 name.2310 name.3267 name.5137 name.6457
//   (the digits are the corner codes; bit i = far side on axis i);
//   -b: six shrunken faces, twelve bevel strips, eight corner triangles;
//   -r: six shrunken faces, twelve cylinders name.hi.., eight spheres name.h..name.o;
//   -r with -n N: the cylinders and spheres become N strips name.hi.1..N and N*N corner
//   patches name.h.1.. (our extension; with N = 1 the shape is the bevelled box).
// RADIANCE compat: -i reverses polygons only; cylinders and spheres stay outward.
std::vector<GenSurface> genboxSurfaces(const GenboxOptions& opt);

// One surface as genbox prints it (leading blank line, tab-separated %18.12g numbers).
std::string formatGenboxSurface(const std::string& material, const GenSurface& s);

// The whole output: header line "# genbox ..." then every surface.
std::string genbox(const std::vector<std::string>& args);

}  // namespace rp::gen
