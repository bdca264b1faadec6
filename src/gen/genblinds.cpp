// genblinds(1): slat geometry. One slat is built at the origin (a flat rectangle, or a
// circular arc of radius |rcurv| cut into facets of equal chord), then copied up the z
// axis. The arithmetic follows RADIANCE's genblinds.c expression by expression (same
// operations in the same order), so every printed digit agrees with RADIANCE's output.
#include "gen/genblinds.h"

#include <cmath>

#include "util/error.h"

namespace rp::gen {

namespace {

constexpr double kPiRad = 3.14159265358979323846;  // RADIANCE's PI
constexpr double kDegree = kPiRad / 180.;
constexpr double kMaxFacetTurnDeg = 3.;  // RADIANCE's DELTA

// A flat strip of the given width (y) and depth d tilted by a radians about the y axis,
// first corner at the origin: RADIANCE's makeflat().
std::vector<Vec3> tiltedStrip(double width, double d, double a) {
    double h = d * std::sin(a);
    d *= std::cos(a);
    return {{0.0, 0.0, 0.0}, {0.0, width, 0.0}, {d, width, h}, {d, 0.0, h}};
}

// The facets of one curved slat, first edge at the origin. The arc spans theta =
// 2 asin(depth / 2R); its chord is tilted by the blind angle.
std::vector<std::vector<Vec3>> curvedSlat(const GenblindsOptions& opt) {
    double r = std::fabs(opt.curvature);
    double theta = 2. * std::asin(opt.depth / (2. * r));
    int facets = int(theta / (kDegree * kMaxFacetTurnDeg) + 0.99999);
    double facetDeg = (180. / kPiRad) * theta / facets;
    double chord = 2. * r * std::sin(kDegree * (facetDeg / 2.));
    double beta = (kPiRad - theta) / 2.;
    double gamma = beta - (kDegree * opt.angleDeg);
    bool down = opt.curvature > 0;  // "-r": the arc bulges downwards
    // First point of the arc, relative to the circle's centre; the slat is shifted so it
    // sits at the origin.
    Vec3 first = down ? Vec3(r * std::cos(gamma + theta), 0., -(r * std::sin(gamma + theta)))
                      : Vec3(-(r * std::cos(gamma)), 0., r * std::sin(gamma));
    std::vector<std::vector<Vec3>> out;
    for (int k = 0; k < facets; ++k) {
        double turn = k * kDegree * facetDeg;
        double half = kDegree * ((180. - facetDeg) / 2.);
        double tilt = down ? (kPiRad - (gamma + theta) + turn) - half : half - (gamma + turn);
        Vec3 at = down ? Vec3(r * std::cos(gamma + theta - turn) - first.x, 0.,
                              (-r) * std::sin(gamma + theta - turn) - first.z)
                       : Vec3((-r) * std::cos(gamma + turn) - first.x, 0.,
                              r * std::sin(gamma + turn) - first.z);
        std::vector<Vec3> facet = tiltedStrip(opt.width, chord, tilt);
        for (Vec3& p : facet) p = {p.x + at.x, p.y + at.y, p.z + at.z};
        out.push_back(std::move(facet));
    }
    return out;
}

double positive(const std::string& word, const char* what) {
    double v = parseReal(word, what);
    if (v <= 0) throw InputError(std::string(what) + " must be positive, got " + word);
    return v;
}

}  // namespace

GenblindsOptions parseGenblindsArgs(const std::vector<std::string>& args) {
    if (args.size() != 8 && args.size() != 10)
        throw InputError("usage: genblinds mat name depth width height nslats angle [-r|+r rcurv]");
    GenblindsOptions opt;
    opt.material = args[1];
    opt.name = args[2];
    opt.depth = positive(args[3], "depth");
    opt.width = positive(args[4], "width");
    opt.height = positive(args[5], "height");
    opt.slats = parseInt(args[6], "nslats");
    if (opt.slats < 1) throw InputError("nslats must be at least 1, got " + args[6]);
    opt.angleDeg = parseReal(args[7], "angle");
    // The one option: -r (or +r, the other way round) and the curvature radius.
    OptionTable table = genOptionTable();
    table.plusWords = true;
    table.messages.unknown = [](const std::string& w) {
        return "unknown option '" + w + "' (expected -r or +r)";
    };
    for (const double sign : {1.0, -1.0})
        table.add(realOption(sign > 0 ? "-r" : "+r", "curvature radius", [&opt, sign](double r) {
            opt.curvature = sign * r;
            if (r != 0 && 2 * std::fabs(r) < opt.depth)
                throw InputError(cformat("curvature radius %g is less than half the depth (%g)",
                                         std::fabs(r), opt.depth));
        }));
    std::vector<std::string> words = args;
    table.parseAll(words, 8);
    return opt;
}

std::vector<GenSurface> genblindsSurfaces(const GenblindsOptions& opt) {
    std::vector<std::vector<Vec3>> slat;
    if (opt.curvature != 0.)
        slat = curvedSlat(opt);
    else
        slat.push_back(tiltedStrip(opt.width, opt.depth, opt.angleDeg * kDegree));
    std::vector<GenSurface> out;
    for (int n = 1; n <= opt.slats; ++n) {
        double lift = opt.height * (n - .5) / opt.slats;
        for (size_t k = 0; k < slat.size(); ++k) {
            GenSurface s;
            s.name = opt.name + "." + std::to_string(n) + "." + std::to_string(k);
            for (const Vec3& p : slat[k]) s.points.push_back({p.x, p.y, p.z + lift});
            out.push_back(std::move(s));
        }
    }
    return out;
}

std::string genblinds(const std::vector<std::string>& args) {
    GenblindsOptions opt = parseGenblindsArgs(args);
    std::string out = commandHeader(args);
    for (const GenSurface& s : genblindsSurfaces(opt)) {
        out += cformat("\n%s polygon %s\n0\n0\n12\n", opt.material.c_str(), s.name.c_str());
        for (const Vec3& p : s.points) out += vertexLine(p);
    }
    return out;
}

}  // namespace rp::gen
