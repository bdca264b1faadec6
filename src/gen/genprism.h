// genprism(1): a polygon in the z = 0 plane extruded along a vector, with optional end
// caps (-e toggles them off), an open last side (-c) and rounded edges (-r, spheres and
// cylinders). Parsing, geometry and RADIANCE's text layout; tool main tools/genprism.cpp.
#pragma once

#include <array>
#include <istream>
#include <string>
#include <vector>

#include "gen/gen_text.h"
#include "util/vec.h"

namespace rp::gen {

struct GenprismOptions {
    std::string material;
    std::string name;
    std::vector<std::array<double, 2>> vertices;  // (x, y) in the z = 0 plane
    Vec3 extrude{0, 0, 1};                        // -l lx ly lz
    bool ends = true;                             // -e toggles
    bool complete = false;  // -c toggles: the polygon is already closed, no last side
    double radius = 0;      // -r: corner rounding radius
};

// Parse genprism's command line (args[0] = program name). Vertices come from the command
// line ("N x1 y1 .. xN yN"), from standard input ("-", read from `in`) or from a file.
// Throws InputError for fewer than 3 vertices, missing coordinates, a zero extrusion
// vector, a radius larger than the height, and degenerate or overlapping sides (-r).
GenprismOptions parseGenprismArgs(const std::vector<std::string>& args, std::istream& in);

// Surfaces in RADIANCE's order: name.b (bottom, vertices as given), name.t (top,
// reversed and shifted by the extrusion), then sides name.1 .. name.N, side i joining
// vertex i to i+1. With -r: the ends gain spheres name.bc<i>/name.tc<i> and cylinders
// name.be<i>/name.te<i>, the sides cylinders name.e<i>.
std::vector<GenSurface> genprismSurfaces(const GenprismOptions& opt);

// One surface in genprism's layout (spheres on one line, unlike genbox).
std::string formatGenprismSurface(const std::string& material, const GenSurface& s);

std::string genprism(const std::vector<std::string>& args, std::istream& in);

}  // namespace rp::gen
