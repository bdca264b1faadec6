// mgf2rad: MGF surfaces and materials as RADIANCE primitives (RADIANCE's mgf2rad.c and
// the barycentric smoothing of tmesh.c, rewritten). Output formats are mgf2rad's printf
// formats, so that scenes converted here and by RADIANCE read the same.
#include "gen/mgf2rad.h"

#include <cmath>
#include <cstdlib>

#include "calc/search_path.h"
#include "gen/gen_text.h"
#include "gen/mgf_reader.h"
#include "util/error.h"

namespace rp::gen {

namespace {

constexpr double kWhiteEfficacy = 179;    // RADIANCE's WHTEFFICACY, lm/W
constexpr double kOneSidedThick = 0.005;  // thickness assumed for 1-sided dielectrics
constexpr double kSmoothCos = 0.999995;   // normals closer than this are "flat"

std::string putv(const Vec3& v) { return cformat("%18.12g %18.12g %18.12g\n", v.x, v.y, v.z); }

enum class Flatness { Bent, Flat, ReversedBent, ReversedFlat, Degenerate };

// tmesh.c flat_tri: whether vertex normals bend the triangle, and whether they face away
// from the vertex order's normal.
Flatness flatness(const MgfVertex& a, const MgfVertex& b, const MgfVertex& c) {
    Vec3 n = cross(b.p - a.p, c.p - b.p);
    if (mgfNormalize(n) == 0) return Flatness::Degenerate;
    double d1 = dot(n, a.n), d2 = dot(n, b.n), d3 = dot(n, c.n);
    if (d1 < 0 && d2 < 0 && d3 < 0)
        return d1 > -kSmoothCos || d2 > -kSmoothCos || d3 > -kSmoothCos ? Flatness::ReversedBent
                                                                        : Flatness::ReversedFlat;
    if (d1 < kSmoothCos || d2 < kSmoothCos || d3 < kSmoothCos) return Flatness::Bent;
    return Flatness::Flat;
}

// tmesh.c comp_baryc: barycentric weights as linear functions of the two coordinates
// other than the triangle's major axis.
struct Barycentric {
    int axis = 0;
    double tm[2][3] = {};
};

bool barycentric(Barycentric& bc, Vec3 v1, Vec3 v2, Vec3 v3) {
    Vec3 n = cross(v1 - v2, v3 - v2);
    bc.axis = n.y * n.y > n.x * n.x;
    if (n.z * n.z > n[bc.axis] * n[bc.axis]) bc.axis = 2;
    int a0 = (bc.axis + 1) % 3, a1 = (bc.axis + 2) % 3;
    for (int i = 0; i < 2; ++i) {
        double ab0 = v1[a0] - v2[a0], cb0 = v3[a0] - v2[a0];
        double ab1 = v1[a1] - v2[a1], cb1 = v3[a1] - v2[a1];
        double d = cb0 * cb0 + cb1 * cb1;
        if (d <= 1e-12) return false;
        d = (cb0 * ab0 + cb1 * ab1) / d;
        double va0 = ab0 - cb0 * d, va1 = ab1 - cb1 * d;
        d = va0 * va0 + va1 * va1;
        if (d <= 1e-12) return false;
        d = 1.0 / d;
        bc.tm[i][0] = va0 *= d;
        bc.tm[i][1] = va1 *= d;
        bc.tm[i][2] = -(v2[a0] * va0 + v2[a1] * va1);
        Vec3 t = v1;  // the second weight belongs to the next vertex
        v1 = v2;
        v2 = v3;
        v3 = t;
    }
    return true;
}

class RadWriter final : public MgfHandler {
public:
    explicit RadWriter(const Mgf2radOptions& opt) : opt_(opt), reader_(*this) {}

    MgfReader& reader() { return reader_; }
    std::string take() { return std::move(out_); }

    void comment(const MgfArgs& av) override {
        out_ += "#";
        for (size_t i = 1; i < av.size(); ++i) out_ += " " + av[i];
        out_ += "\n";
    }
    void face(const MgfArgs& av) override;
    void cone(const MgfArgs& av) override;
    void cylinder(const MgfArgs& av) override;
    void sphere(const MgfArgs& av) override;
    void ring(const MgfArgs& av) override;

private:
    const MgfVertex& vertex(const std::string& name) const {
        const MgfVertex* v = reader_.vertex(name);
        if (!v) mgfFail(MgfError::Undefined);
        return *v;
    }
    std::string objectPrefix() const;
    std::string material();
    bool emitter(const std::string& name, MgfMaterial& m);
    bool glass(const std::string& name, MgfMaterial& m);
    bool trans(const std::string& name, MgfMaterial& m);
    void plasticOrMetal(const std::string& name, MgfMaterial& m);
    void sided(const std::string& name, const MgfMaterial& m);
    void smoothTriangle(const std::string& mat, const MgfVertex* a, const MgfVertex* b,
                        const MgfVertex* c, bool reverse);

    Mgf2radOptions opt_;
    MgfReader reader_;
    std::string out_;
    int faces_ = 0, triangles_ = 0, cones_ = 0, cylinders_ = 0, spheres_ = 0, rings_ = 0;
};

// mgf2rad names each surface after (at most) the four innermost object names.
std::string RadWriter::objectPrefix() const {
    const auto& names = reader_.objectNames();
    std::string s;
    for (size_t i = names.size() > 4 ? names.size() - 4 : 0; i < names.size(); ++i) {
        if (s.size() + names[i].size() >= 63) break;  // RADIANCE's 64-byte buffer
        s += names[i] + ".";
    }
    return s;
}

double radius(const std::string& word) { return std::atof(word.c_str()); }

void RadWriter::cone(const MgfArgs& av) {
    if (av.size() != 5) mgfFail(MgfError::ArgCount);
    if (!mgfIsFloat(av[2]) || !mgfIsFloat(av[4])) mgfFail(MgfError::ArgType);
    const MgfVertex& a = vertex(av[1]);
    const MgfVertex& b = vertex(av[3]);
    Vec3 p1 = reader_.xfPoint(a.p), p2 = reader_.xfPoint(b.p);
    double r1 = reader_.xfScale(radius(av[2])), r2 = reader_.xfScale(radius(av[4]));
    // Negative radii turn the cone inside out (a cup); both radii must agree on it.
    bool inv = r1 < 0;
    if (r1 == 0) {
        if (r2 == 0) mgfFail(MgfError::IllegalValue);
        inv = r2 < 0;
    } else if (r2 != 0 && inv != (r2 < 0)) {
        mgfFail(MgfError::IllegalValue);
    }
    if (inv) r1 = -r1, r2 = -r2;
    std::string mat = material();
    out_ += cformat("\n%s %s %sc%d\n0\n0\n8\n", mat.c_str(), inv ? "cup" : "cone",
                    objectPrefix().c_str(), ++cones_);
    out_ += putv(p1) + putv(p2) + cformat("%18.12g %18.12g\n", r1, r2);
}

void RadWriter::cylinder(const MgfArgs& av) {
    if (av.size() != 4) mgfFail(MgfError::ArgCount);
    if (!mgfIsFloat(av[2])) mgfFail(MgfError::ArgType);
    const MgfVertex& a = vertex(av[1]);
    const MgfVertex& b = vertex(av[3]);
    Vec3 p1 = reader_.xfPoint(a.p), p2 = reader_.xfPoint(b.p);
    double r = reader_.xfScale(radius(av[2]));
    bool inv = r < 0;
    if (inv) r = -r;
    std::string mat = material();
    out_ += cformat("\n%s %s %scy%d\n0\n0\n7\n", mat.c_str(), inv ? "tube" : "cylinder",
                    objectPrefix().c_str(), ++cylinders_);
    out_ += putv(p1) + putv(p2) + cformat("%18.12g\n", r);
}

void RadWriter::sphere(const MgfArgs& av) {
    if (av.size() != 3) mgfFail(MgfError::ArgCount);
    if (!mgfIsFloat(av[2])) mgfFail(MgfError::ArgType);
    Vec3 c = reader_.xfPoint(vertex(av[1]).p);
    double r = reader_.xfScale(radius(av[2]));
    bool inv = r < 0;
    if (inv) r = -r;
    std::string mat = material();
    out_ +=
        cformat("\n%s %s %ss%d\n0\n0\n4 %18.12g %18.12g %18.12g %18.12g\n", mat.c_str(),
                inv ? "bubble" : "sphere", objectPrefix().c_str(), ++spheres_, c.x, c.y, c.z, r);
}

void RadWriter::ring(const MgfArgs& av) {
    if (av.size() != 4) mgfFail(MgfError::ArgCount);
    if (!mgfIsFloat(av[2]) || !mgfIsFloat(av[3])) mgfFail(MgfError::ArgType);
    const MgfVertex& v = vertex(av[1]);
    if (dot(v.n, v.n) <= 1e-12) mgfFail(MgfError::IllegalValue);  // a ring needs a normal
    Vec3 c = reader_.xfPoint(v.p), n = reader_.rotVector(v.n);
    double r1 = reader_.xfScale(radius(av[2])), r2 = reader_.xfScale(radius(av[3]));
    if (r1 < 0 || r2 <= r1) mgfFail(MgfError::IllegalValue);
    std::string mat = material();
    out_ += cformat("\n%s ring %sr%d\n0\n0\n8\n", mat.c_str(), objectPrefix().c_str(), ++rings_);
    out_ += putv(c) + putv(n) + cformat("%18.12g %18.12g\n", r1, r2);
}

void RadWriter::face(const MgfArgs& av) {
    size_t ac = av.size();
    if (ac < 4) mgfFail(MgfError::ArgCount);
    std::string mat = material();
    bool reverse = reader_.reversed();
    if (ac <= 5) {
        // Triangles and quads whose vertices all have normals may be smoothed.
        const MgfVertex* v[4] = {};
        bool allNormals = true;
        for (size_t i = 1; i < ac && allNormals; ++i) {
            v[i - 1] = &vertex(av[i]);
            allNormals = dot(v[i - 1]->n, v[i - 1]->n) > 1e-12;
        }
        Flatness f = allNormals ? flatness(*v[0], *v[1], *v[2]) : Flatness::Flat;
        if (f == Flatness::Degenerate) return;  // RADIANCE compat: dropped silently
        if (f == Flatness::ReversedBent || f == Flatness::ReversedFlat) reverse = !reverse;
        if (f == Flatness::Bent || f == Flatness::ReversedBent) {
            smoothTriangle(mat, v[0], v[1], v[2], reverse);
            if (ac == 5) smoothTriangle(mat, v[2], v[3], v[0], reverse);
            return;
        }
    }
    out_ += cformat("\n%s polygon %sf%d\n0\n0\n%d\n", mat.c_str(), objectPrefix().c_str(), ++faces_,
                    int(3 * (ac - 1)));
    for (size_t i = 1; i < ac; ++i)
        out_ += putv(reader_.xfPoint(vertex(av[reverse ? ac - i : i]).p));
}

void RadWriter::smoothTriangle(const std::string& mat, const MgfVertex* a, const MgfVertex* b,
                               const MgfVertex* c, bool reverse) {
    if (reverse) std::swap(a, c);
    Vec3 v1 = reader_.xfPoint(a->p), v2 = reader_.xfPoint(b->p), v3 = reader_.xfPoint(c->p);
    Barycentric bc;
    if (!barycentric(bc, v1, v2, v3)) return;  // degenerate
    // The normal interpolated over the triangle, for tmesh.cal's T-nor texture.
    out_ += cformat("\n%s texfunc T-nor\n4 dx dy dz tmesh.cal\n0\n", mat.c_str());
    Vec3 n[3] = {reader_.rotVector(a->n), reader_.rotVector(b->n), reader_.rotVector(c->n)};
    out_ += cformat("%d\t%d\n", 1 + 3 * 3, bc.axis);
    for (int i = 0; i < 3; ++i) {
        double ca = n[0][i] - n[2][i], cb = n[1][i] - n[2][i];
        out_ += cformat("%14.8f %14.8f %14.8f\n", bc.tm[0][0] * ca + bc.tm[1][0] * cb,
                        bc.tm[0][1] * ca + bc.tm[1][1] * cb,
                        bc.tm[0][2] * ca + bc.tm[1][2] * cb + n[2][i]);
    }
    out_ += cformat("\nT-nor polygon %st%d\n0\n0\n9\n", objectPrefix().c_str(), ++triangles_);
    out_ += putv(v1) + putv(v2) + putv(v3);
}

// ---- materials (mgf2rad's material(): the first RADIANCE type that fits) ----

// Printed on first use after each change; "mat" is the unnamed material.
std::string RadWriter::material() {
    std::string name = reader_.materialName().empty() ? "mat" : reader_.materialName();
    MgfMaterial& m = reader_.material();
    if (!m.clock) return name;
    m.clock = 0;
    if (emitter(name, m)) return name;
    float total = m.rd + m.td + m.rs + m.ts;
    if (total < 0 || total > 1) mgfFail(MgfError::BadMaterial);
    if (glass(name, m) || trans(name, m)) return name;
    plasticOrMetal(name, m);
    return name;
}

bool RadWriter::emitter(const std::string& name, MgfMaterial& m) {
    if (!(m.ed > .1)) return false;
    // MGF emittance is in lm/m^2; RADIANCE radiance in W/sr/m^2 (179 lm/W white).
    auto rgb = mgfColorToRgb(m.edColor, opt_.emitterMultiplier * m.ed / (kPi * kWhiteEfficacy));
    if (opt_.glowDistance < 1e10)
        out_ += cformat("\nvoid glow %s\n0\n0\n4 %f %f %f %f\n", name.c_str(), rgb[0], rgb[1],
                        rgb[2], opt_.glowDistance);
    else
        out_ +=
            cformat("\nvoid light %s\n0\n0\n3 %f %f %f\n", name.c_str(), rgb[0], rgb[1], rgb[2]);
    return true;
}

bool RadWriter::glass(const std::string& name, MgfMaterial& m) {
    if (!(m.nr > 1.1 && m.ts > .25 && m.rs <= .125 && m.td <= .01 && m.rd <= .01 &&
          m.rsRough <= .01 && m.tsRough <= .01))
        return false;
    auto rgb = mgfColorToRgb(m.tsColor, m.ts + m.rs);
    if (m.oneSided) {
        // A one-sided interface: a dielectric whose absorption gives this transmission
        // through the assumed thickness.
        for (float& c : rgb) c = float(std::pow(c, 1. / kOneSidedThick));
        out_ += cformat("\nvoid dielectric %s\n0\n0\n5 %g %g %g %f 0\n", name.c_str(), rgb[0],
                        rgb[1], rgb[2], m.nr);
    } else {
        out_ += cformat("\nvoid glass %s\n0\n0\n4 %f %f %f %f\n", name.c_str(), rgb[0], rgb[1],
                        rgb[2], m.nr);
    }
    return true;
}

void addColor(std::array<float, 3>& a, const std::array<float, 3>& b) {
    for (int i = 0; i < 3; ++i) a[i] += b[i];
}

bool RadWriter::trans(const std::string& name, MgfMaterial& m) {
    if (!(m.td > .01 || m.ts > .01)) return false;
    // Float arithmetic where RADIANCE's is float (its material fields), so digits agree.
    double d = float(m.rd + m.td + m.ts);
    auto rgb = mgfColorToRgb(m.rdColor, m.rd / d);
    addColor(rgb, mgfColorToRgb(m.tdColor, m.td / d));
    addColor(rgb, mgfColorToRgb(m.tsColor, m.ts / d));
    double roughness = 0;  // RADIANCE leaves it unset when rs + ts is tiny
    if (m.rs + m.ts > .0001)
        roughness = float((m.rs * m.rsRough + m.ts * m.tsRough) / (m.rs + m.ts));
    double transmitted = float((m.td + m.ts) / (m.rd + m.td + m.ts));
    d = transmitted < .999 ? m.rd / (1. - m.rs) / (1. - transmitted) : double(float(m.td + m.ts));
    for (float& c : rgb) c = float(c * d);
    out_ += cformat("\nvoid trans %s\n0\n0\n7 %f %f %f\n\t%f %f %f %f\n", name.c_str(), rgb[0],
                    rgb[1], rgb[2], m.rs, roughness, transmitted, m.ts / (m.ts + m.td));
    sided(name, m);
    return true;
}

void RadWriter::plasticOrMetal(const std::string& name, MgfMaterial& m) {
    if (m.rs < .08 && (m.rs < .1 * m.rd || m.rsColor.isGrey())) {
        auto rgb = mgfColorToRgb(m.rdColor, m.rd / (1. - m.rs));
        out_ += cformat("\nvoid plastic %s\n0\n0\n5 %f %f %f %f %f\n", name.c_str(), rgb[0], rgb[1],
                        rgb[2], m.rs, m.rsRough);
    } else {
        auto rgb = mgfColorToRgb(m.rdColor, m.rd);
        addColor(rgb, mgfColorToRgb(m.rsColor, m.rs));
        out_ += cformat("\nvoid metal %s\n0\n0\n5 %f %f %f %f %f\n", name.c_str(), rgb[0], rgb[1],
                        rgb[2], m.rs / (m.rd + m.rs), m.rsRough);
    }
    sided(name, m);
}

// A one-sided material: void seen from the back.
void RadWriter::sided(const std::string& name, const MgfMaterial& m) {
    if (m.oneSided)
        out_ += cformat("\nvoid mixfunc %s\n4 %s void if(Rdot,1,0) .\n0\n0\n", name.c_str(),
                        name.c_str());
}

// One converter for a whole command: RADIANCE keeps contexts and counters across files.
struct Conversion {
    explicit Conversion(const Mgf2radOptions& opt) : writer(opt) {}
    RadWriter writer;
    std::string out;
    void file(std::string_view text, const std::string& name, bool fromFile) {
        if (fromFile)
            writer.reader().loadFile(name);
        else
            writer.reader().loadText(text, name);
        out += writer.take();
    }
};

}  // namespace

std::string mgfToRad(std::string_view mgf, const std::string& name, const Mgf2radOptions& opt,
                     std::vector<std::string>* warnings, unsigned* unknownEntities) {
    Conversion c(opt);
    c.file(mgf, name, false);
    if (warnings)
        for (const auto& w : c.writer.reader().warnings()) warnings->push_back(w);
    if (unknownEntities) *unknownEntities = c.writer.reader().unknownCount();
    return c.out;
}

std::string mgf2rad(const std::vector<std::string>& args, const std::string& input,
                    std::vector<std::string>& warnings, const std::string& from) {
    Mgf2radOptions opt;
    std::string prog = args.empty() ? "mgf2rad" : args[0];
    std::string header = "## " + prog;
    OptionTable table = genOptionTable();
    table.messages.unknown = [](const std::string&) {
        return "usage: mgf2rad [-g dist][-e mult] [file.mgf] ..";
    };
    auto number = [&](const char* name, const char* what, double& v) {
        table.add(customOption(name, [&header, &v, what](OptionReader& r) {
            v = parseReal(r.word(), what);
            header += " " + r.option() + " " + r.args()[r.next() - 1];
        }));
    };
    number("-g", "glow distance", opt.glowDistance);
    number("-e", "multiplier", opt.emitterMultiplier);
    table.add(wordOption("-m", [] {
        throw notSupportedYet(SourceLoc{}, "mgf2rad -m (a separate materials file)");
    }));
    std::vector<std::string> words = args;
    size_t i = table.parse(words, 1).next;
    if (i < args.size() && args[i] == "-version") throw InputError(table.messages.unknown(args[i]));
    Conversion c(opt);
    c.out = "## Translated from MGF Version 2.0\n" + header + "\n";
    MgfReader& reader = c.writer.reader();
    auto unknownLine = [&](const std::string& what) {
        if (reader.unknownCount())
            c.out += cformat("## %s: %u unknown entities\n", what.c_str(), reader.unknownCount());
        reader.resetUnknownCount();
    };
    if (i == args.size()) {
        c.file(input, "<stdin>", false);
        unknownLine(prog);
    }
    for (; i < args.size(); ++i) {
        c.out += "## " + prog + " " + args[i] + " ##############################\n";
        c.file({}, calc::inDirectory(from, args[i]), true);
        unknownLine(prog + " " + args[i]);
    }
    for (const auto& w : reader.warnings()) warnings.push_back(w);
    return c.out;
}

}  // namespace rp::gen
