// genworm(1): a "worm" along the curve (x(t), y(t), z(t)) with radius r(t), t = 0..1 in
// nseg steps: nseg+1 spheres joined by nseg cones or cylinders. Command parsing, geometry
// and RADIANCE's text layout; the tool main is tools/genworm.cpp, expression handling is
// gen_func.h.
#pragma once

#include <string>
#include <vector>

#include "gen/gen_func.h"
#include "util/vec.h"

namespace rp::gen {

struct GenwormOptions {
    std::string material;
    std::string name;
    std::string xExpr, yExpr, zExpr, rExpr;  // x(t) y(t) z(t) r(t)
    int segments = 0;                        // nseg > 0
    std::vector<CalcSource> sources;         // -e / -f in order
};

// Parses genworm's command line; args[0] is the program name. Throws InputError for a
// wrong argument count, a non-integer or non-positive nseg, or an unknown option.
GenwormOptions parseGenwormArgs(const std::vector<std::string>& args);

// One surface in output order: after sphere name.s0, each step i gives a joint
// name.c<i> (a cylinder when the radii agree within 1e-6, else a cone) then sphere
// name.s<i>. A cone is the one tangent to both spheres: its end points move along the
// axis by r*(r0-r1)/d and its radii shrink by sqrt(1-((r0-r1)/d)^2), d = |p1-p0|.
// No joint is written between coincident centres (d = 0).
struct WormPart {
    enum class Kind { Sphere, Cylinder, Cone };
    Kind kind = Kind::Sphere;
    std::string name;
    Vec3 p0, p1;            // sphere: p0 = centre
    double r0 = 0, r1 = 0;  // sphere and cylinder: r0
};

// The parts in output order. Throws InputError for expression errors and negative radii.
std::vector<WormPart> genwormParts(const GenwormOptions& opt, GenFunctions& funcs);

// One part as genworm prints it ("\n" first; space-separated %18.12g numbers).
std::string formatWormPart(const std::string& material, const WormPart& p);

// The whole output: "# genworm ..." header then every part. `searchPath` is where -f
// files are found; `warnings` receives the math-error warning, if any.
std::string genworm(const std::vector<std::string>& args,
                    const std::vector<std::string>& searchPath, std::vector<std::string>& warnings);

}  // namespace rp::gen
