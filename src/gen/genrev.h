// genrev(1): a surface of revolution about the z axis from z(t) and r(t), t = 0..1 in
// nseg steps, as cones, cups, cylinders, tubes and rings, optionally smoothed (-s) with
// a Phong texfunc per segment. Command parsing, geometry and RADIANCE's text layout; the
// tool main is tools/genrev.cpp, expression handling is gen_func.h.
#pragma once

#include <string>
#include <vector>

#include "gen/gen_func.h"

namespace rp::gen {

struct GenrevOptions {
    std::string material;
    std::string name;
    std::string zExpr;                // z(t)
    std::string rExpr;                // r(t)
    int segments = 0;                 // nseg > 0
    std::vector<CalcSource> sources;  // -e / -f in order
    bool smooth = false;              // -s
};

// Parses genrev's command line; args[0] is the program name. Throws InputError for a
// wrong argument count, a non-integer or non-positive nseg, or an unknown option.
GenrevOptions parseGenrevArgs(const std::vector<std::string>& args);

// One segment between t = (i-1)/nseg and i/nseg, as genrev.c classifies it: z rising
// gives outward normals (cone, cylinder), z falling inward ones (cup, tube); constant z
// gives a ring facing +z when r shrinks and -z when it grows. Segments where neither z
// nor r changes (by more than 1e-9) are left out but keep their number.
struct RevSegment {
    enum class Kind { Cone, Cup, Cylinder, Tube, Ring };
    Kind kind = Kind::Cone;
    int index = 0;           // i: the name is "name.i"
    double z0 = 0, z1 = 0;   // heights at the segment's start and end (ring: z1)
    double r0 = 0, r1 = 0;   // radii at the start and end
    double ringNormalZ = 0;  // ring only: +1 or -1
    // -s: the Phong texfunc's 4 real arguments as genrev.c writes them: for each of the
    // normal's z and r components either a linear fit (slope, offset) in z (or r), or a
    // constant ("0 +-1", written as integers).
    bool zLinear = false, rLinear = false;
    double phong[4] = {0, 0, 0, 0};
};

// The segments in output order. Throws InputError for expression errors and for a
// negative radius (RADIANCE forbids them but does not check).
std::vector<RevSegment> genrevSegments(const GenrevOptions& opt, GenFunctions& funcs);

// One segment as genrev prints it ("\n" first; tab + %18.12g columns); `smooth` adds the
// "mat texfunc Phong" record and makes Phong the segment's modifier.
std::string formatRevSegment(const GenrevOptions& opt, const RevSegment& s);

// The whole output: "# genrev ..." header then every segment. `searchPath` is where -f
// files are found; `warnings` receives the math-error warning, if any.
std::string genrev(const std::vector<std::string>& args, const std::vector<std::string>& searchPath,
                   std::vector<std::string>& warnings);

}  // namespace rp::gen
