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
constexpr const char* kLetters = "0123456789._ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

// RADIANCE's normalize() (fvect.c): near unit length it scales by a first-order
// approximation of 1/|v| instead of a division; matching it keeps the corner vertices
// identical to RADIANCE's to the last printed digit. Returns the old length.
double radianceNormalize(Vec3& v) {
    double d = dot(v, v);
    if (d == 0.0) return 0.0;
    double len;
    if (d <= 1.0 + 1e-6 && d >= 1.0 - 1e-6) {
        len = 0.5 + 0.5 * d;
        d = 2.0 - len;
    } else {
        len = std::sqrt(d);
        d = 1.0 / len;
    }
    v *= d;
    return len;
}

struct BoxBuilder {
    const GenboxOptions& opt;
    int segments;  // facets per quarter circle when the rounding is tessellated, else 0
    std::vector<GenSurface> out;

    double inset() const { return opt.edges == BoxEdges::Square ? 0.0 : opt.edgeSize; }

    // RADIANCE compat (genbox.c): -i mirrors the box through its centre (every corner
    // code takes the opposite corner's coordinates) rather than reversing vertex order;
    // the surfaces keep their names and each polygon's first vertex moves.
    bool farSide(int code, int axis) const { return (((code >> axis) & 1) != 0) != opt.inward; }

    Vec3 corner(int code) const {
        Vec3 v;
        double b = inset();
        for (int i = 0; i < 3; ++i) {
            bool far = farSide(code, i);
            bool in = (code >> (i + 3)) & 1;
            v[i] = in ? (far ? opt.size[i] - b : b) : (far ? opt.size[i] : 0.0);
        }
        return v;
    }

    void polygon(std::initializer_list<int> codes) {
        GenSurface s;
        s.name = opt.name + ".";
        for (int c : codes) s.name += kLetters[c];
        for (int c : codes) s.points.push_back(corner(c));
        out.push_back(std::move(s));
    }

    void cylinder(int c0, int c1) {
        GenSurface s;
        s.kind = GenSurface::Kind::Cylinder;
        s.name = opt.name + "." + kLetters[c0] + kLetters[c1];
        s.points = {corner(c0), corner(c1)};
        s.radius = opt.edgeSize;
        out.push_back(std::move(s));
    }

    void sphere(int c) {
        GenSurface s;
        s.kind = GenSurface::Kind::Sphere;
        s.name = opt.name + "." + kLetters[c];
        s.points = {corner(c)};
        s.radius = opt.edgeSize;
        out.push_back(std::move(s));
    }

    // A mesh facet; named later, when RADIANCE's numbering is known.
    void facet(std::vector<Vec3> pts) {
        out.push_back({GenSurface::Kind::Polygon, "", std::move(pts), 0});
    }

    // Rounded edge c0-c1 as `segments` flat strips. The quarter circle starts on the
    // first of two offset axes and turns towards the second, RADIANCE's choice per edge
    // direction (x edge: z then y; y edge: x then z; z edge: y then x); each offset points
    // to the side of the box the edge lies on.
    void edgeStrips(int c0, int c1) {
        Vec3 p0 = corner(c0), p1 = corner(c1);
        int axis = (c0 ^ c1) & 1 ? 0 : ((c0 ^ c1) & 2 ? 1 : 2);
        static constexpr int kOffsetAxes[3][2] = {{2, 1}, {0, 2}, {1, 0}};
        Vec3 off[2];
        for (int k = 0; k < 2; ++k) {
            int a = kOffsetAxes[axis][k];
            off[k][a] = opt.edgeSize * (p1[a] < 0.5 * opt.size[a] ? -1.0 : 1.0);
        }
        double step = 0.5 * kPi / segments;
        Vec3 prev0 = p0 + off[0], prev1 = p1 + off[0];
        for (int i = 1; i <= segments; ++i) {
            double c = std::cos(step * i), s = std::sin(step * i);
            Vec3 o;
            for (int j = 0; j < 3; ++j) o[j] = c * off[0][j] + s * off[1][j];
            Vec3 next0 = p0 + o, next1 = p1 + o;
            facet({prev0, prev1, next1, next0});
            prev0 = next0;
            prev1 = next1;
        }
    }

    // Octant of the sphere around `centre` spanned by unit directions d0 d1 d2, split
    // `level` times into four (midpoints of the edges pushed back onto the sphere).
    void cornerTriangles(const Vec3& centre, const Vec3& d0, const Vec3& d1, const Vec3& d2,
                         int level) {
        if (level == 0) {
            double r = opt.edgeSize;
            facet({centre + d0 * r, centre + d1 * r, centre + d2 * r});
            return;
        }
        Vec3 m01 = d0 + d1, m12 = d1 + d2, m20 = d2 + d0;
        radianceNormalize(m01);
        radianceNormalize(m12);
        radianceNormalize(m20);
        cornerTriangles(centre, d0, m01, m20, level - 1);
        cornerTriangles(centre, d1, m12, m01, level - 1);
        cornerTriangles(centre, d2, m20, m12, level - 1);
        cornerTriangles(centre, m01, m12, m20, level - 1);
    }

    void cornerPatches(int c) {
        Vec3 d[3];
        for (int i = 0; i < 3; ++i) d[i][i] = farSide(c, i) ? 1.0 : -1.0;
        // Corners with an even number of far sides swap the first two directions, so
        // every octant winds outward (before -i mirrors the box).
        int parity = (c & 1) + ((c >> 1) & 1) + ((c >> 2) & 1);
        if (parity % 2 == 0) std::swap(d[0], d[1]);
        int level = 0;
        while ((1 << level) < segments) ++level;
        cornerTriangles(corner(c), d[0], d[1], d[2], level);
    }

    // RADIANCE writes a tessellated box through its mesh library (objutil.c): faces
    // come out last first, numbered name.1, name.2, ..., and faces of area at most
    // 1e-12 (FTINY squared) are dropped.
    void finishMesh() {
        std::reverse(out.begin(), out.end());
        std::vector<GenSurface> kept;
        for (GenSurface& s : out) {
            Vec3 sum, v1 = s.points[1] - s.points[0];
            for (size_t i = 2; i < s.points.size(); ++i) {
                Vec3 v2 = s.points[i] - s.points[0];
                sum += cross(v1, v2);
                v1 = v2;
            }
            if (0.5 * radianceNormalize(sum) <= 1e-12) continue;
            s.name = opt.name + "." + std::to_string(kept.size() + 1);
            kept.push_back(std::move(s));
        }
        out = std::move(kept);
    }

    void build() {
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
        if (opt.edges == BoxEdges::Bevel) {
            static constexpr int kBevels[12][4] = {
                {031, 051, 050, 030}, {060, 062, 032, 030}, {050, 054, 064, 060},
                {034, 036, 066, 064}, {037, 057, 056, 036}, {052, 062, 066, 056},
                {052, 053, 033, 032}, {057, 067, 063, 053}, {061, 031, 033, 063},
                {065, 067, 037, 035}, {055, 051, 061, 065}, {034, 054, 055, 035}};
            static constexpr int kCorners[8][3] = {
                {030, 050, 060}, {051, 031, 061}, {032, 062, 052}, {064, 054, 034},
                {036, 056, 066}, {065, 035, 055}, {053, 063, 033}, {037, 067, 057}};
            for (const auto& q : kBevels) polygon({q[0], q[1], q[2], q[3]});
            for (const auto& t : kCorners) polygon({t[0], t[1], t[2]});
        } else if (segments == 0) {
            for (const auto& e : kEdges) cylinder(e[0], e[1]);
            for (int c = 070; c <= 077; ++c) sphere(c);
        } else {
            for (const auto& e : kEdges) edgeStrips(e[0], e[1]);
            for (int c = 070; c <= 077; ++c) cornerPatches(c);
            finishMesh();
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
    bool sawEdge = false;
    auto edge = [&](const std::string& name, BoxEdges kind) {
        return realOption(name, kind == BoxEdges::Round ? "radius" : "bevel",
                          [&, name, kind](double v) {
                              if (sawEdge)
                                  throw InputError("-r and -b may be given only once, not both");
                              sawEdge = true;
                              if (v < 0) throw InputError(name + " value must not be negative");
                              opt.edgeSize = v;
                              if (v > 0) opt.edges = kind;
                          });
    };
    auto notYet = [](const std::string& name, const std::string& what) {
        return wordOption(name, [name, what] {
            throw InputError("option " + name + " (" + what + ") is not supported yet");
        });
    };
    OptionTable table = genOptionTable();
    table.add(wordOption("-i", [&] { opt.inward = true; }));
    table.add(edge("-r", BoxEdges::Round));
    table.add(edge("-b", BoxEdges::Bevel));
    table.add(intOption("-n", "segment count", [&](int n) {
        if (n < 1) throw InputError("-n needs at least 1 segment");
        opt.segments = n;
    }));
    table.add(notYet("-s", "smoothed facets"));
    table.add(notYet("-o", "OBJ output"));
    std::vector<std::string> words = args;
    table.parseAll(words, 6);
    double smallest = std::min({opt.size.x, opt.size.y, opt.size.z});
    if (opt.edges != BoxEdges::Square && 2 * opt.edgeSize >= smallest)
        throw InputError(cformat("%s %g must be less than half the smallest size (%g)",
                                 opt.edges == BoxEdges::Round ? "radius" : "bevel", opt.edgeSize,
                                 smallest));
    return opt;
}

int genboxRoundingSegments(const GenboxOptions& opt) {
    if (opt.edges != BoxEdges::Round) return 0;
    int requested = opt.segments;
    if (opt.inward && requested == 1) requested = 32;
    int segments = 2;
    while (segments < requested) segments *= 2;
    return segments > 2 ? segments : 0;
}

std::vector<GenSurface> genboxSurfaces(const GenboxOptions& opt) {
    BoxBuilder b{opt, genboxRoundingSegments(opt), {}};
    b.build();
    return std::move(b.out);
}

std::string formatGenboxSurface(const std::string& material, const GenSurface& s, bool meshLayout) {
    std::string out;
    switch (s.kind) {
        case GenSurface::Kind::Polygon:
            out = cformat("\n%s polygon %s\n0\n0\n%d\n", material.c_str(), s.name.c_str(),
                          int(3 * s.points.size()));
            for (const Vec3& p : s.points)
                out += meshLayout ? cformat("\t%18.12g %18.12g %18.12g\n", p.x, p.y, p.z)
                                  : vertexLine(p);
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
    bool mesh = genboxRoundingSegments(opt) > 0;
    for (const GenSurface& s : genboxSurfaces(opt))
        out += formatGenboxSurface(opt.material, s, mesh);
    return out;
}

}  // namespace rp::gen
