// genbox(1): parsing, box geometry (square, bevelled, rounded, tessellated rounded) and
// RADIANCE's output layout. Corner codes follow RADIANCE's genbox: bit i (i = 0,1,2 for
// x,y,z) selects the far side on that axis, bit i+3 pulls that coordinate in by the
// bevel/radius; side names print each code through RADIANCE's 64-letter alphabet.
#include "gen/genbox.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace rp::gen {

namespace {

// RADIANCE genbox's letters for corner codes 0..63 in polygon names.
constexpr const char* kLetters =
    "0123456789._ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

struct BoxBuilder {
    const GenboxOptions& opt;
    std::vector<GenSurface> out;

    double inset() const { return opt.edges == BoxEdges::Square ? 0.0 : opt.edgeSize; }

    Vec3 corner(int code) const {
        Vec3 v;
        double b = inset();
        for (int i = 0; i < 3; ++i) {
            bool far = (code >> i) & 1;
            bool in = (code >> (i + 3)) & 1;
            v[i] = in ? (far ? opt.size[i] - b : b) : (far ? opt.size[i] : 0.0);
        }
        return v;
    }

    void polygon(std::vector<int> codes) {
        GenSurface s;
        s.name = opt.name + ".";
        for (int c : codes) s.name += kLetters[c];
        if (opt.inward) std::reverse(codes.begin(), codes.end());
        for (int c : codes) s.points.push_back(corner(c));
        out.push_back(std::move(s));
    }

    void cylinder(int c0, int c1) {
        GenSurface s;
        s.kind = GenSurface::Kind::Cylinder;
        s.name = opt.name + "." + char('0' + c0) + char('0' + c1);
        s.points = {corner(c0), corner(c1)};
        s.radius = opt.edgeSize;
        out.push_back(std::move(s));
    }

    void sphere(int c) {
        GenSurface s;
        s.kind = GenSurface::Kind::Sphere;
        s.name = opt.name + "." + char('0' + c);
        s.points = {corner(c)};
        s.radius = opt.edgeSize;
        out.push_back(std::move(s));
    }

    // A facet of the tessellated rounding: orient it away from the inner box (its
    // rounding centre) and then apply -i.
    void facet(const std::string& name, std::vector<Vec3> pts) {
        Vec3 centroid;
        for (const Vec3& p : pts) centroid += p;
        centroid = centroid / double(pts.size());
        Vec3 inner;
        double b = inset();
        for (int i = 0; i < 3; ++i) inner[i] = std::clamp(centroid[i], b, opt.size[i] - b);
        bool outward = dot(newellNormal(pts), centroid - inner) > 0;
        if (outward == opt.inward) std::reverse(pts.begin(), pts.end());
        out.push_back({GenSurface::Kind::Polygon, name, std::move(pts), 0});
    }

    // Edge between corner codes c0 and c1 (differing on one axis) as n flat strips.
    void edgeStrips(int c0, int c1) {
        int n = opt.segments;
        double r = opt.edgeSize;
        int axis = 0;
        while (!(((c0 ^ c1) >> axis) & 1)) ++axis;
        int u = (axis + 1) % 3, w = (axis + 2) % 3;
        Vec3 a = corner(c0), b = corner(c1);
        double du = ((c0 >> u) & 1) ? 1 : -1, dw = ((c0 >> w) & 1) ? 1 : -1;
        auto offset = [&](int k) {
            double t = 0.5 * kPi * k / n;
            Vec3 d;
            d[u] = du * r * std::cos(t);
            d[w] = dw * r * std::sin(t);
            return d;
        };
        std::string base = opt.name + "." + char('0' + c0) + char('0' + c1) + ".";
        for (int k = 0; k < n; ++k) {
            Vec3 o0 = offset(k), o1 = offset(k + 1);
            facet(base + std::to_string(k + 1), {a + o0, b + o0, b + o1, a + o1});
        }
    }

    // Corner octant as an n x n latitude/longitude grid (triangles at the pole).
    void cornerPatches(int c) {
        int n = opt.segments;
        double r = opt.edgeSize;
        Vec3 centre = corner(c);
        Vec3 d(((c >> 0) & 1) ? 1 : -1, ((c >> 1) & 1) ? 1 : -1, ((c >> 2) & 1) ? 1 : -1);
        auto point = [&](int i, int j) {  // i: polar step from +-z, j: azimuth step
            double th = 0.5 * kPi * i / n, ph = 0.5 * kPi * j / n;
            return centre + Vec3(d.x * r * std::sin(th) * std::cos(ph),
                                 d.y * r * std::sin(th) * std::sin(ph), d.z * r * std::cos(th));
        };
        std::string base = opt.name + "." + char('0' + c) + ".";
        int k = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                std::string nm = base + std::to_string(++k);
                if (i == 0)
                    facet(nm, {point(0, 0), point(1, j), point(1, j + 1)});
                else
                    facet(nm, {point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)});
            }
    }

    void build() {
        bool rounded = opt.edges == BoxEdges::Round;
        if (opt.edges == BoxEdges::Square) {
            polygon({1, 5, 4, 0});
            polygon({4, 6, 2, 0});
            polygon({2, 3, 1, 0});
            polygon({3, 2, 6, 7});
            polygon({5, 1, 3, 7});
            polygon({6, 4, 5, 7});
            return;
        }
        // minor (shrunken) faces
        polygon({051, 055, 054, 050});
        polygon({064, 066, 062, 060});
        polygon({032, 033, 031, 030});
        polygon({053, 052, 056, 057});
        polygon({065, 061, 063, 067});
        polygon({036, 034, 035, 037});
        static constexpr int kEdges[12][2] = {{070, 071}, {070, 074}, {070, 072}, {073, 071},
                                              {073, 072}, {073, 077}, {075, 071}, {075, 074},
                                              {075, 077}, {076, 072}, {076, 074}, {076, 077}};
        if (!rounded) {
            static constexpr int kBevels[12][4] = {
                {031, 051, 050, 030}, {060, 062, 032, 030}, {050, 054, 064, 060},
                {034, 036, 066, 064}, {037, 057, 056, 036}, {052, 062, 066, 056},
                {052, 053, 033, 032}, {057, 067, 063, 053}, {061, 031, 033, 063},
                {065, 067, 037, 035}, {055, 051, 061, 065}, {034, 054, 055, 035}};
            static constexpr int kCorners[8][3] = {{030, 050, 060}, {051, 031, 061},
                                                   {032, 062, 052}, {064, 054, 034},
                                                   {036, 056, 066}, {065, 035, 055},
                                                   {053, 063, 033}, {037, 067, 057}};
            for (const auto& q : kBevels) polygon({q[0], q[1], q[2], q[3]});
            for (const auto& t : kCorners) polygon({t[0], t[1], t[2]});
        } else if (opt.segments == 0) {
            for (const auto& e : kEdges) cylinder(e[0], e[1]);
            for (int c = 070; c <= 077; ++c) sphere(c);
        } else {
            for (const auto& e : kEdges) edgeStrips(e[0], e[1]);
            for (int c = 070; c <= 077; ++c) cornerPatches(c);
        }
    }
};

}  // namespace

GenboxOptions parseGenboxArgs(const std::vector<std::string>& args) {
    if (args.size() < 6)
        throw InputError("usage: genbox mat name xsiz ysiz zsiz [-i] [-r rad | -b bev] [-n nseg]");
    GenboxOptions opt;
    opt.material = args[1];
    opt.name = args[2];
    static const char* kAxis[3] = {"x size", "y size", "z size"};
    for (int i = 0; i < 3; ++i) {
        opt.size[i] = parseReal(args[3 + i], kAxis[i]);
        if (opt.size[i] <= 0)
            throw InputError(std::string(kAxis[i]) + " must be positive, got " + args[3 + i]);
    }
    bool sawEdge = false, sawSegments = false;
    for (size_t i = 6; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-i") {
            opt.inward = true;
        } else if (a == "-r" || a == "-b") {
            if (sawEdge) throw InputError("-r and -b may be given only once, not both");
            sawEdge = true;
            opt.edgeSize = parseReal(optionValue(args, i), a == "-r" ? "radius" : "bevel");
            if (opt.edgeSize < 0) throw InputError(a + " value must not be negative");
            if (opt.edgeSize > 0) opt.edges = a == "-r" ? BoxEdges::Round : BoxEdges::Bevel;
        } else if (a == "-n") {
            sawSegments = true;
            opt.segments = parseInt(optionValue(args, i), "segment count");
            if (opt.segments < 1) throw InputError("-n needs at least 1 segment");
        } else {
            throw InputError("unknown option '" + a + "'");
        }
    }
    double smallest = std::min({opt.size.x, opt.size.y, opt.size.z});
    if (opt.edges != BoxEdges::Square && 2 * opt.edgeSize >= smallest)
        throw InputError(cformat("%s %g must be less than half the smallest size (%g)",
                                 opt.edges == BoxEdges::Round ? "radius" : "bevel",
                                 opt.edgeSize, smallest));
    if (sawSegments && opt.edges != BoxEdges::Round)
        throw InputError("-n applies only to rounded edges (-r rad)");
    return opt;
}

std::vector<GenSurface> genboxSurfaces(const GenboxOptions& opt) {
    BoxBuilder b{opt, {}};
    b.build();
    return std::move(b.out);
}

std::string formatGenboxSurface(const std::string& material, const GenSurface& s) {
    std::string out;
    switch (s.kind) {
        case GenSurface::Kind::Polygon:
            out = cformat("\n%s polygon %s\n0\n0\n%d\n", material.c_str(), s.name.c_str(),
                          int(3 * s.points.size()));
            for (const Vec3& p : s.points) out += vertexLine(p);
            break;
        case GenSurface::Kind::Cylinder:
            out = cformat("\n%s cylinder %s\n0\n0\n7\n", material.c_str(), s.name.c_str());
            out += vertexLine(s.points[0]) + vertexLine(s.points[1]);
            out += cformat("\t%18.12g\n", s.radius);
            break;
        case GenSurface::Kind::Sphere:
            out = cformat("\n%s sphere %s\n0\n0\n4\n", material.c_str(), s.name.c_str());
            out += vertexLine(s.points[0]) + cformat("\t%18.12g\n", s.radius);
            break;
    }
    return out;
}

std::string genbox(const std::vector<std::string>& args) {
    GenboxOptions opt = parseGenboxArgs(args);
    std::string out = commandHeader(args);
    for (const GenSurface& s : genboxSurfaces(opt)) out += formatGenboxSurface(opt.material, s);
    return out;
}

}  // namespace rp::gen
