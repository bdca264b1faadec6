// genbox(1): a RADIANCE box with one corner at the origin, optionally with bevelled
// (-b) or rounded (-r) edges, rounding tessellated into flat facets (-n), and inward
// normals (-i). Command parsing, geometry and RADIANCE's text layout, byte for byte;
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
    int segments = 1;                   // -n nsegs as given (see genboxRoundingSegments)
};

// Parse genbox's command line; args[0] is the program name. Throws InputError for a
// wrong argument count, non-numeric or non-positive sizes, unknown options, -r together
// with -b, a bevel or radius not smaller than half the smallest size, or -n below 1.
// RADIANCE's -s (smoothed facets) and -o (OBJ output) are refused as not supported yet.
GenboxOptions parseGenboxArgs(const std::vector<std::string>& args);

// Facets per quarter circle of a rounded edge, 0 when the rounding stays cylinders and
// spheres. RADIANCE compat (genbox.c): -n N rounds up to a power of two, N <= 2 keeps
// cylinders and spheres, and -i with -r tessellates with 32 unless -n says otherwise.
// -n without -r changes nothing.
int genboxRoundingSegments(const GenboxOptions& opt);

// The surfaces in RADIANCE genbox's order and naming (side names spell the corner codes
// in RADIANCE's 64-letter alphabet; bit i = far side on axis i, bit i+3 = pulled in):
//   square box: polygons name.1540 name.4620 name.2310 name.3267 name.5137 name.6457;
//   -b: six shrunken faces, twelve bevel strips, eight corner triangles;
//   -r: six shrunken faces, twelve cylinders name.st ..., eight spheres name.s ... name.z;
//   -r tessellated (genboxRoundingSegments > 0): RADIANCE's mesh output, every face
//   numbered name.1 ... in reverse order of construction (triangles of the last corner
//   first, the shrunken faces last), each corner octant split recursively into four,
//   faces of area <= 1e-12 dropped.
// RADIANCE compat: -i mirrors the box through its centre instead of reversing vertex
// order (same names, same surfaces, opposite orientation).
std::vector<GenSurface> genboxSurfaces(const GenboxOptions& opt);

// One surface as genbox prints it (leading blank line, %18.12g numbers, tab-separated;
// with meshLayout "\t%18.12g %18.12g %18.12g" per vertex, as RADIANCE's mesh writer).
std::string formatGenboxSurface(const std::string& material, const GenSurface& s,
                                bool meshLayout = false);

// The whole output: header line "# genbox ..." then every surface.
std::string genbox(const std::vector<std::string>& args);

}  // namespace rp::gen
