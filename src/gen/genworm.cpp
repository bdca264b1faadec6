// genworm(1): spheres joined by cones or cylinders along a curve (see genworm.h).
// Matches RADIANCE genworm.c's naming (name.s<i>, name.c<i>), its tangent-cone
// construction and its %18.12g layout.
#include "gen/genworm.h"

#include <cmath>

#include "gen/gen_text.h"
#include "util/error.h"

namespace rp::gen {

namespace {

// RADIANCE's FTINY: radii this close make a cylinder instead of a cone.
constexpr double kFtiny = 1e-6;

const char* kUsage = "usage: genworm mat name 'x(t)' 'y(t)' 'z(t)' 'r(t)' nseg [-e expr][-f file]";

}  // namespace

GenwormOptions parseGenwormArgs(const std::vector<std::string>& args) {
    if (args.size() < 8) throw InputError(kUsage);
    GenwormOptions opt;
    opt.material = args[1];
    opt.name = args[2];
    opt.xExpr = args[3];
    opt.yExpr = args[4];
    opt.zExpr = args[5];
    opt.rExpr = args[6];
    opt.segments = parseInt(args[7], "nseg");
    if (opt.segments <= 0)
        throw InputError("nseg must be positive, got " + std::to_string(opt.segments));
    OptionTable table = genOptionTable();
    addCalcOptions(table, opt.sources);
    std::vector<std::string> words = args;
    table.parseAll(words, 8);
    return opt;
}

std::vector<WormPart> genwormParts(const GenwormOptions& opt, GenFunctions& funcs) {
    GenFunctionId xf = funcs.define("x(t)", "t", opt.xExpr);
    GenFunctionId yf = funcs.define("y(t)", "t", opt.yExpr);
    GenFunctionId zf = funcs.define("z(t)", "t", opt.zExpr);
    GenFunctionId rf = funcs.define("r(t)", "t", opt.rExpr);
    funcs.build();

    std::vector<WormPart> parts;
    Vec3 lastp;
    double lastr = 0;
    for (int i = 0; i <= opt.segments; ++i) {
        double t = double(i) / opt.segments;
        Vec3 p(funcs.call(xf, t), funcs.call(yf, t), funcs.call(zf, t));
        double r = funcs.call(rf, t);
        if (r < 0)
            throw InputError(cformat("r(t) is negative (%g) at t = %g: radii must be >= 0", r, t));
        // A joint between coincident centres would be degenerate (NaN for a cone in
        // genworm.c); the larger sphere covers it, so it is left out and its number skipped.
        if (i > 0 && lengthSquared(p - lastp) > 0) {
            WormPart joint;
            joint.name = opt.name + ".c" + std::to_string(i);
            if (std::fabs(lastr - r) <= kFtiny) {
                joint.kind = WormPart::Kind::Cylinder;
                joint.p0 = lastp;
                joint.p1 = p;
                joint.r0 = r;
            } else {
                // The cone touching both spheres: with a = (r0-r1)/d, the tangent circle
                // of a sphere of radius r sits r*a/d * (p1-p0) from its centre and has
                // radius r*sqrt(1-a^2). f below is (r0-r1)/d^2, as in genworm.c.
                joint.kind = WormPart::Kind::Cone;
                Vec3 axis = p - lastp;
                double f = (lastr - r) / lengthSquared(axis);
                joint.p0 = lastp + axis * (f * lastr);
                joint.p1 = p + axis * (f * r);
                double c = 1.0 - (lastr - r) * f;
                c = c <= 0 ? 0 : std::sqrt(c);
                joint.r0 = c * lastr;
                joint.r1 = c * r;
            }
            parts.push_back(joint);
        }
        WormPart ball;
        ball.kind = WormPart::Kind::Sphere;
        ball.name = opt.name + ".s" + std::to_string(i);
        ball.p0 = p;
        ball.r0 = r;
        parts.push_back(ball);
        lastp = p;
        lastr = r;
    }
    return parts;
}

std::string formatWormPart(const std::string& material, const WormPart& p) {
    const char* m = material.c_str();
    const char* n = p.name.c_str();
    switch (p.kind) {
        case WormPart::Kind::Sphere:
            return cformat("\n%s sphere %s\n0\n0\n4 %18.12g %18.12g %18.12g %18.12g\n", m, n,
                           p.p0.x, p.p0.y, p.p0.z, p.r0);
        case WormPart::Kind::Cylinder:
            return cformat(
                "\n%s cylinder %s\n0\n0\n7\n%18.12g %18.12g %18.12g\n"
                "%18.12g %18.12g %18.12g\n%18.12g\n",
                m, n, p.p0.x, p.p0.y, p.p0.z, p.p1.x, p.p1.y, p.p1.z, p.r0);
        case WormPart::Kind::Cone:
            return cformat(
                "\n%s cone %s\n0\n0\n8\n%18.12g %18.12g %18.12g\n"
                "%18.12g %18.12g %18.12g\n%18.12g %18.12g\n",
                m, n, p.p0.x, p.p0.y, p.p0.z, p.p1.x, p.p1.y, p.p1.z, p.r0, p.r1);
    }
    return {};
}

std::string genworm(const std::vector<std::string>& args,
                    const std::vector<std::string>& searchPath,
                    std::vector<std::string>& warnings) {
    GenwormOptions opt = parseGenwormArgs(args);
    GenFunctions funcs(opt.sources, searchPath);
    std::vector<WormPart> parts = genwormParts(opt, funcs);
    std::string out = commandHeader(args);
    for (const WormPart& p : parts) out += formatWormPart(opt.material, p);
    if (std::string w = funcs.mathWarning(); !w.empty()) warnings.push_back(w);
    return out;
}

}  // namespace rp::gen
