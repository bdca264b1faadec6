// See obj_file.h.
#include "scene/obj_file.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <tuple>

#include "util/error.h"
#include "util/warnings.h"

namespace rp {
namespace {

using Vec = std::array<double, 3>;

struct Corner {
    int v = -1, vt = -1, vn = -1;  // 0-based, -1 = not given
};

// RADIANCE's polygon splitter (common/triangulate.c, after J. Ratcliff): repeatedly
// cuts off the ear at the current vertex, skipping collinear corners.
struct Pt {
    double x, y;
};

double polyArea(const std::vector<Pt>& p) {
    double a = 0.0;
    for (size_t q = 0, r = p.size() - 1; q < p.size(); r = q++)
        a += p[r].x * p[q].y - p[q].x * p[r].y;
    return a * 0.5;
}

bool insideTriangle(Pt a, Pt b, Pt c, Pt p) {
    double ax = c.x - b.x, ay = c.y - b.y;
    double bx = a.x - c.x, by = a.y - c.y;
    double cx = b.x - a.x, cy = b.y - a.y;
    double apx = p.x - a.x, apy = p.y - a.y;
    double bpx = p.x - b.x, bpy = p.y - b.y;
    double cpx = p.x - c.x, cpy = p.y - c.y;
    return (ax * bpy - ay * bpx >= 0.0) & (bx * cpy - by * cpx >= 0.0) &
           (cx * apy - cy * apx >= 0.0);
}

// 1: an ear, 0: not an ear, -1: the three corners are collinear.
int snip(const std::vector<Pt>& p, int u, int v, int w, int n, const std::vector<int>& V) {
    constexpr double kEps = 1e-10;
    Pt a = p[V[u]], b = p[V[v]], c = p[V[w]];
    double cr = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (cr < kEps) return cr > -kEps ? -1 : 0;
    for (int k = 0; k < n; ++k) {
        if (k == u || k == v || k == w) continue;
        Pt q = p[V[k]];
        // Corners repeated along a seam do not block an ear.
        if ((q.x == a.x && q.y == a.y) || (q.x == b.x && q.y == b.y) || (q.x == c.x && q.y == c.y))
            continue;
        if (insideTriangle(a, b, c, q)) return 0;
    }
    return 1;
}

// Appends corner-index triples (counter-clockwise in the plane); false if it gave up.
bool splitPolygon(const std::vector<Pt>& p, std::vector<std::array<int, 3>>& out) {
    int nv = static_cast<int>(p.size());
    std::vector<int> V(nv);
    bool ccw = polyArea(p) > 0.0;
    for (int k = 0; k < nv; ++k) V[k] = ccw ? k : nv - 1 - k;
    int count = 2 * nv;
    int v = nv - 1;
    while (nv > 2) {
        if (count-- <= 0) return false;
        int u = v;
        if (u >= nv) u = 0;
        v = u + 1;
        if (v >= nv) v = 0;
        int w = v + 1;
        if (w >= nv) w = 0;
        int r = snip(p, u, v, w, nv, V);
        if (r > 0) out.push_back({V[u], V[v], V[w]});
        if (r) {
            V.erase(V.begin() + v);
            nv--;
            count = 2 * nv;
        }
    }
    return true;
}

class Parser {
public:
    Parser(const std::string& file) : file_(file) {}

    void statement(const std::vector<std::string_view>& av, int line) {
        line_ = line;
        out.statements++;
        std::string_view cmd = av[0];
        if (cmd[0] == '#') return;
        if (cmd == "v") {
            vs_.push_back(vec3(av, "bad vertex"));
        } else if (cmd == "vn") {
            Vec n = vec3(av, "bad normal");
            if (!normalize(n)) fail("zero normal");
            vns_.push_back(n);
        } else if (cmd == "vt") {
            // RADIANCE needs u and v; a lone u (1-D texture) gets v = 0 here.
            if (av.size() < 2) fail("bad texture coordinate");
            std::array<double, 2> t{number(av[1], "bad texture coordinate"), 0.0};
            if (av.size() > 2) t[1] = number(av[2], "bad texture coordinate");
            vts_.push_back(t);
        } else if (cmd == "f") {
            face(av);
        } else if (cmd == "usemtl") {
            material_ = av.size() > 1 ? std::string(av[1]) : std::string();
        } else if (cmd == "g") {
            group_ = av.size() > 1 ? std::string(av[1]) : std::string();
        } else if (cmd == "o" || cmd == "usemap") {
            // object names and texture maps: nothing to do
        } else {
            out.unrecognised++;
        }
    }

    ObjMesh out;

private:
    [[noreturn]] void fail(const std::string& msg) const {
        throw InputError(SourceLoc{file_, line_}, msg);
    }

    double number(std::string_view s, const char* what) const {
        std::string t(s);
        char* end = nullptr;
        double d = std::strtod(t.c_str(), &end);
        if (t.empty() || *end != '\0' || !std::isfinite(d))
            fail(std::string(what) + " '" + t + "'");
        return d;
    }

    Vec vec3(const std::vector<std::string_view>& av, const char* what) const {
        if (av.size() < 4) fail(what);
        return {number(av[1], what), number(av[2], what), number(av[3], what)};
    }

    // RADIANCE's normalize() (a first-order step for near-unit vectors).
    static bool normalize(Vec& v) {
        double d = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (d == 0.0) return false;
        if (d <= 1.0 + 1e-6 && d >= 1.0 - 1e-6)
            d = 2.0 - (0.5 + 0.5 * d);
        else
            d = 1.0 / std::sqrt(d);
        for (double& c : v) c *= d;
        return true;
    }

    // One part of a v/vt/vn reference: "" is none, else a non-zero integer counted
    // from 1, or back from the latest when negative.
    int index(std::string_view part, size_t count, const char* what, bool required) const {
        if (part.empty()) {
            if (required) fail(std::string("missing ") + what + " index");
            return -1;
        }
        std::string t(part);
        char* end = nullptr;
        long i = std::strtol(t.c_str(), &end, 10);
        if (*end != '\0') fail(std::string("bad ") + what + " index '" + t + "'");
        long n = static_cast<long>(count);
        long k = i > 0 ? i - 1 : n + i;
        if (i == 0 || k < 0 || k >= n)
            fail(std::string(what) + " index " + t + " out of range (" + std::to_string(n) +
                 " defined)");
        return static_cast<int>(k);
    }

    Corner corner(std::string_view s) const {
        Corner c;
        size_t a = s.find('/');
        c.v = index(s.substr(0, a), vs_.size(), "vertex", true);
        if (a == std::string_view::npos) return c;
        std::string_view rest = s.substr(a + 1);
        size_t b = rest.find('/');
        c.vt = index(rest.substr(0, b), vts_.size(), "texture vertex", false);
        if (b != std::string_view::npos)
            c.vn = index(rest.substr(b + 1), vns_.size(), "normal", false);
        return c;
    }

    void face(const std::vector<std::string_view>& av) {
        if (av.size() < 4) fail("face with fewer than 3 vertices");
        std::vector<Corner> cs;
        for (size_t i = 1; i < av.size(); ++i) cs.push_back(corner(av[i]));
        if (cs.size() == 3) {
            triangle(cs[0], cs[1], cs[2]);
            return;
        }
        // The dominant axis of the last corner triple (searching backwards) whose
        // turn is not degenerate; a face without one is dropped, as in RADIANCE.
        int ax = -1;
        for (int i = static_cast<int>(cs.size()) - 3; i >= 0; --i) {
            const Vec &p1 = vs_[cs[i].v], &p2 = vs_[cs[i + 1].v], &p3 = vs_[cs[i + 2].v];
            Vec e1{p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]};
            Vec e2{p3[0] - p2[0], p3[1] - p2[1], p3[2] - p2[2]};
            Vec n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0]};
            int imax = 2;
            for (int k = 2; k--;)
                if (n[k] * n[k] > n[imax] * n[imax]) imax = k;
            if (n[imax] * n[imax] > 1e-24) {
                ax = imax;
                break;
            }
        }
        if (ax < 0) return;
        int x = (ax + 1) % 3, y = (x + 1) % 3;
        std::vector<Pt> poly;
        for (const Corner& c : cs) poly.push_back({vs_[c.v][x], vs_[c.v][y]});
        bool reversed = polyArea(poly) < 0.0;
        std::vector<std::array<int, 3>> tris;
        bool ok = splitPolygon(poly, tris);
        for (const auto& t : tris) {
            if (reversed)
                triangle(cs[t[2]], cs[t[1]], cs[t[0]]);
            else
                triangle(cs[t[0]], cs[t[1]], cs[t[2]]);
        }
        if (!ok)
            warn(SourceLoc{file_, line_},
                 "self-intersecting face with " + std::to_string(cs.size()) + " vertices");
    }

    void triangle(const Corner& a, const Corner& b, const Corner& c) {
        MeshTriangleInput t;
        const Corner* cs[3] = {&a, &b, &c};
        t.hasUV = a.vt >= 0 && b.vt >= 0 && c.vt >= 0;
        t.hasNormals = a.vn >= 0 && b.vn >= 0 && c.vn >= 0;
        for (int k = 0; k < 3; ++k) {
            t.v[k] = vs_[cs[k]->v];
            if (t.hasUV) t.uv[k] = vts_[cs[k]->vt];
            if (t.hasNormals) t.n[k] = vns_[cs[k]->vn];
        }
        t.loc = SourceLoc{file_, line_};
        out.triangles.push_back(t);
        out.materialNames.push_back(material_ == "void" ? material_
                                    : material_.empty() ? group_
                                                        : material_);
    }

    std::string file_;
    int line_ = 0;
    std::vector<Vec> vs_, vns_;
    std::vector<std::array<double, 2>> vts_;
    std::string material_, group_;
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

ObjMesh parseObj(std::string_view text, const std::string& file) {
    Parser p(file);
    size_t pos = 0;
    int line = 0;
    std::vector<std::string_view> av;
    std::string joined;
    while (pos < text.size()) {
        // One statement: a line, joined with the next while it ends in a backslash.
        int first = ++line;
        joined.clear();
        for (;;) {
            size_t nl = text.find('\n', pos);
            std::string_view l = text.substr(pos, nl == std::string_view::npos ? nl : nl - pos);
            pos = nl == std::string_view::npos ? text.size() : nl + 1;
            size_t end = l.size();
            while (end > 0 && isSpace(l[end - 1])) --end;
            if (end > 0 && l[end - 1] == '\\' && pos < text.size()) {
                joined.append(l.substr(0, end - 1));
                joined.push_back(' ');
                ++line;
                continue;
            }
            joined.append(l);
            break;
        }
        av.clear();
        std::string_view s = joined;
        for (size_t i = 0; i < s.size();) {
            while (i < s.size() && isSpace(s[i])) ++i;
            if (i >= s.size()) break;
            size_t j = i;
            while (j < s.size() && !isSpace(s[j])) ++j;
            if (s[i] == '#' && !av.empty()) break;  // a comment after a statement
            av.push_back(s.substr(i, j - i));
            i = j;
        }
        if (!av.empty()) p.statement(av, first);
    }
    if (p.out.unrecognised > 0)
        warn(SourceLoc{file, 0}, std::to_string(p.out.unrecognised) + " of " +
                                     std::to_string(p.out.statements) + " statements unrecognized");
    return std::move(p.out);
}

void assignObjMaterials(ObjMesh& obj, const Scene& materials) {
    std::map<std::string, int32_t> latest;
    for (size_t i = 0; i < materials.prims.size(); ++i)
        if (isModifier(materials.prims[i].type))
            latest[materials.prims[i].name] = static_cast<int32_t>(i);
    for (size_t t = 0; t < obj.triangles.size(); ++t) {
        const std::string& name = obj.materialNames[t];
        int32_t m = kVoid;
        if (!materials.prims.empty() && !name.empty() && name != "void") {
            auto it = latest.find(name);
            if (it == latest.end())
                throw InputError(obj.triangles[t].loc, "undefined modifier \"" + name + "\"");
            m = it->second;
        }
        obj.triangles[t].material = m;
    }
}

MeshData objToMeshData(const ObjMesh& obj, const Scene& materials) {
    MeshData m;
    m.materials = materials;
    using Key =
        std::tuple<std::array<double, 3>, int, std::array<double, 3>, std::array<double, 2>>;
    std::map<Key, uint32_t> index;
    bool anyN = false, anyUV = false;
    for (const auto& t : obj.triangles) {
        anyN |= t.hasNormals;
        anyUV |= t.hasUV;
    }
    std::vector<int32_t> mats;
    for (const auto& t : obj.triangles) {
        for (int k = 0; k < 3; ++k) {
            int fl = (t.hasNormals ? MeshData::kHasNormal : 0) | (t.hasUV ? MeshData::kHasUV : 0);
            Key key{t.v[k], fl, t.hasNormals ? t.n[k] : std::array<double, 3>{},
                    t.hasUV ? t.uv[k] : std::array<double, 2>{}};
            auto [it, added] = index.emplace(key, static_cast<uint32_t>(m.vertexCount()));
            if (added) {
                for (double c : t.v[k]) m.positions.push_back(static_cast<float>(c));
                if (anyN)
                    m.normals.push_back({static_cast<float>(std::get<2>(key)[0]),
                                         static_cast<float>(std::get<2>(key)[1]),
                                         static_cast<float>(std::get<2>(key)[2])});
                if (anyUV)
                    m.uvs.push_back({static_cast<float>(std::get<3>(key)[0]),
                                     static_cast<float>(std::get<3>(key)[1])});
                if (anyN || anyUV) m.vertexFlags.push_back(static_cast<uint8_t>(fl));
            }
            m.triangles.push_back(it->second);
        }
        mats.push_back(t.material);
    }
    m.positions.push_back(0.0f);  // the pad float Embree's 16-byte loads need
    bool same = true;
    for (int32_t x : mats) same &= x == mats.front();
    if (same && !mats.empty())
        m.soleMaterial = mats.front();
    else
        m.triangleMaterial = std::move(mats);
    return m;
}

}  // namespace rp
