// genprism(1): parsing, the extruded-polygon geometry (plain and rounded) and RADIANCE's
// output layout. For rounding, u[i] is the unit vector from vertex i back to vertex i-1
// and a[i] = tan(half the turn at vertex i), signed by the turn direction relative to the
// extrusion; corners are then offset by radius * (a[i] u[i] + perp(u[i])).
#include "gen/genprism.h"

#include <cctype>
#include <cmath>
#include <fstream>

#include "util/error.h"

namespace rp::gen {

namespace {

constexpr double kTiny = 1e-6;  // RADIANCE FTINY

std::vector<std::array<double, 2>> readVertices(std::istream& in) {
    std::vector<std::array<double, 2>> v;
    double x, y;
    while (in >> x >> y) v.push_back({x, y});
    return v;
}

struct PrismBuilder {
    const GenprismOptions& opt;
    size_t n;
    std::vector<std::array<double, 2>> u;
    std::vector<double> a;
    std::vector<GenSurface> out;

    Vec3 at(size_t i, double z) const { return {opt.vertices[i][0], opt.vertices[i][1], z}; }
    // Rounded corner offset radius * (a u + perp u) in the base plane.
    Vec3 cornerOffset(size_t i) const {
        double r = opt.radius;
        return {r * (a[i] * u[i][0] - u[i][1]), r * (a[i] * u[i][1] + u[i][0]), 0};
    }

    void computeRounding() {
        u.resize(n);
        a.resize(n);
        size_t prev = n - 1;
        for (size_t i = 0; i < n; ++i) {
            double dx = opt.vertices[prev][0] - opt.vertices[i][0];
            double dy = opt.vertices[prev][1] - opt.vertices[i][1];
            double l = std::sqrt(dx * dx + dy * dy);
            if (l <= kTiny) throw InputError("degenerate side in prism");
            u[i] = {dx / l, dy / l};
            prev = i;
        }
        for (size_t i = 0; i < n; ++i) {
            const auto& v0 = u[i];
            const auto& v1 = u[(i + 1) % n];
            double c = v0[0] * v1[0] + v0[1] * v1[1];
            if (1 + c <= kTiny) throw InputError("overlapping sides in prism");
            if (1 - c <= 0) {
                a[i] = 0;
            } else {
                a[i] = std::sqrt((1 - c) / (1 + c));
                if ((v1[0] * v0[1] - v1[1] * v0[0] > 0) != (opt.extrude.z > 0)) a[i] = -a[i];
            }
        }
    }

    void polygon(std::string name, std::vector<Vec3> pts) {
        out.push_back({GenSurface::Kind::Polygon, std::move(name), std::move(pts), 0});
    }
    void cylinder(std::string name, Vec3 p0, Vec3 p1) {
        out.push_back({GenSurface::Kind::Cylinder, std::move(name), {p0, p1}, opt.radius});
    }
    void sphere(std::string name, Vec3 c) {
        out.push_back({GenSurface::Kind::Sphere, std::move(name), {c}, opt.radius});
    }

    void plainEnds() {
        std::vector<Vec3> bottom, top;
        for (size_t i = 0; i < n; ++i) bottom.push_back(at(i, 0));
        for (size_t i = n; i--;) top.push_back(at(i, 0) + opt.extrude);
        polygon(opt.name + ".b", bottom);
        polygon(opt.name + ".t", top);
    }

    // One rounded end: the inset polygon, then per vertex a corner sphere (convex turns
    // only) and the cylinder along the edge arriving at that vertex.
    void roundedEnd(bool top) {
        double r = opt.radius;
        Vec3 shift = top ? opt.extrude : Vec3(0, 0, 0);
        double zFace = top ? opt.extrude.z : 0.0;
        double zEdge = top ? opt.extrude.z - r : r;
        std::vector<Vec3> face;
        if (!top)
            for (size_t i = 0; i < n; ++i) face.push_back(at(i, 0) + cornerOffset(i));
        else
            for (size_t i = n; i--;) {
                Vec3 p = at(i, 0) + shift + cornerOffset(i);
                face.push_back({p.x, p.y, zFace});
            }
        polygon(opt.name + (top ? ".t" : ".b"), face);
        auto edgePoint = [&](size_t i) {
            Vec3 p = at(i, 0) + shift + cornerOffset(i);
            return Vec3(p.x, p.y, zEdge);
        };
        Vec3 c0 = edgePoint(n - 1);
        std::string tag = top ? "t" : "b";
        for (size_t i = 0; i < n; ++i) {
            Vec3 c1 = edgePoint(i);
            if (a[i] > 0) sphere(opt.name + "." + tag + "c" + std::to_string(i + 1), c1);
            cylinder(opt.name + "." + tag + "e" + std::to_string(i + 1), c0, c1);
            c0 = c1;
        }
    }

    void side(size_t n0, size_t n1) {
        polygon(opt.name + "." + std::to_string(n0 + 1),
                {at(n0, 0), at(n0, 0) + opt.extrude, at(n1, 0) + opt.extrude, at(n1, 0)});
    }

    // A side of a rounded prism, pulled in by the radius and tilted for slanted extrusion.
    void roundedSide(size_t n0, size_t n1) {
        double r = opt.radius;
        const Vec3& l = opt.extrude;
        double s = (l.y * u[n1][0] - l.x * u[n1][1]) / length(l);
        Vec3 t;
        if (s < -kTiny || s > kTiny) {
            double c = std::sqrt(1. - s * s);
            t = {(c - 1.) * u[n1][1], (1. - c) * u[n1][0], s};
        }
        Vec3 along0(-a[n0] * u[n1][0], -a[n0] * u[n1][1], 0);
        Vec3 along1(a[n1] * u[n1][0], a[n1] * u[n1][1], 0);
        Vec3 lowOff(t.x, t.y, t.z + 1.), highOff(t.x, t.y, t.z - 1.);
        polygon(opt.name + "." + std::to_string(n0 + 1),
                {at(n0, 0) + (along0 + lowOff) * r, at(n0, 0) + l + (along0 + highOff) * r,
                 at(n1, 0) + l + (along1 + highOff) * r, at(n1, 0) + (along1 + lowOff) * r});
        if (a[n1] < 0) return;
        Vec3 base = at(n1, 0) + cornerOffset(n1);
        cylinder(opt.name + ".e" + std::to_string(n0 + 1), Vec3(base.x, base.y, r),
                 Vec3(base.x + l.x, base.y + l.y, l.z - r));
    }

    void build() {
        bool rounding = opt.radius > kTiny;
        if (rounding) computeRounding();
        if (opt.ends) {
            if (rounding) {
                roundedEnd(false);
                roundedEnd(true);
            } else {
                plainEnds();
            }
        }
        size_t last = opt.complete ? n - 1 : n;
        for (size_t i = 0; i < last; ++i) {
            if (rounding)
                roundedSide(i, (i + 1) % n);
            else
                side(i, (i + 1) % n);
        }
    }
};

}  // namespace

GenprismOptions parseGenprismArgs(const std::vector<std::string>& args, std::istream& in) {
    const char* usage =
        "usage: genprism mat name { - | vfile | N x1 y1 .. xN yN } [-l lx ly lz] [-r radius] "
        "[-c] [-e]";
    if (args.size() < 4) throw InputError(usage);
    GenprismOptions opt;
    opt.material = args[1];
    opt.name = args[2];
    size_t an = 4;
    if (args[3] == "-") {
        opt.vertices = readVertices(in);
    } else if (std::isdigit(static_cast<unsigned char>(args[3][0]))) {
        int count = parseInt(args[3], "vertex count");
        if (args.size() < 4 + 2 * size_t(count))
            throw InputError("expected " + std::to_string(count) + " vertices (" +
                             std::to_string(2 * count) + " coordinates), got " +
                             std::to_string(args.size() - 4) + " words");
        for (int k = 0; k < count; ++k)
            opt.vertices.push_back({parseReal(args[4 + 2 * k], "x coordinate"),
                                    parseReal(args[5 + 2 * k], "y coordinate")});
        an = 4 + 2 * size_t(count);
    } else {
        std::ifstream f(args[3]);
        if (!f) throw InputError(SourceLoc{args[3], 0}, "cannot open vertex file");
        opt.vertices = readVertices(f);
    }
    if (opt.vertices.size() < 3) throw InputError("not enough vertices (need at least 3)");
    OptionTable table = genOptionTable();
    table.add(customOption("-l", [&opt](OptionReader& r) {
        for (int k = 0; k < 3; ++k)
            opt.extrude[k] = parseReal(r.word(), "extrusion vector component");
        if (length(opt.extrude) <= kTiny) throw InputError("zero extrusion vector");
    }));
    table.add(realOption("-r", "radius", [&opt](double v) {
        if (v < 0) throw InputError("-r radius must not be negative");
        opt.radius = v;
    }));
    table.add(wordOption("-e", [&opt] { opt.ends = !opt.ends; }));
    table.add(wordOption("-c", [&opt] { opt.complete = !opt.complete; }));
    std::vector<std::string> words = args;
    table.parseAll(words, an);
    if (opt.radius > kTiny && opt.radius > std::fabs(opt.extrude.z))
        throw InputError("rounding greater than height");
    return opt;
}

std::vector<GenSurface> genprismSurfaces(const GenprismOptions& opt) {
    PrismBuilder b{opt, opt.vertices.size(), {}, {}, {}};
    b.build();
    return std::move(b.out);
}

std::string formatGenprismSurface(const std::string& material, const GenSurface& s) {
    const char* m = material.c_str();
    const char* nm = s.name.c_str();
    std::string out;
    switch (s.kind) {
        case GenSurface::Kind::Polygon:
            out = cformat("\n%s polygon %s\n0\n0\n%d\n", m, nm, int(3 * s.points.size()));
            for (const Vec3& p : s.points) out += vertexLine(p);
            break;
        case GenSurface::Kind::Cylinder:
            out = cformat("\n%s cylinder %s\n0\n0\n7\n", m, nm);
            out += vertexLine(s.points[0]) + vertexLine(s.points[1]);
            out += cformat("\t%18.12g\n", s.radius);
            break;
        case GenSurface::Kind::Sphere: {
            const Vec3& c = s.points[0];
            out = cformat("\n%s sphere %s\n0\n0\n4 %18.12g %18.12g %18.12g %18.12g\n", m, nm, c.x,
                          c.y, c.z, s.radius);
            break;
        }
    }
    return out;
}

std::string genprism(const std::vector<std::string>& args, std::istream& in) {
    GenprismOptions opt = parseGenprismArgs(args, in);
    std::string out = commandHeader(args);
    for (const GenSurface& s : genprismSurfaces(opt)) out += formatGenprismSurface(opt.material, s);
    return out;
}

}  // namespace rp::gen
