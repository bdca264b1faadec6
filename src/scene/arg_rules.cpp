// The argument table from ray.html (RADIANCE 6.0 reference manual, section 2.1) and the
// load-time value checks of RADIANCE's o_sphere/o_cone/o_face (see arg_rules.h).
#include "scene/arg_rules.h"

#include <array>
#include <cmath>

#include "scene/xform.h"
#include "util/warnings.h"

namespace rp {

namespace {
constexpr double kFtiny = 1e-6;  // RADIANCE's FTINY (fvect.h, double RREAL)
constexpr int kAny = -1;

ArgCount exactly(int n) { return {n, n}; }
ArgCount atLeast(int n) { return {n, kAny}; }
ArgCount range(int a, int b) { return {a, b}; }
ArgCount oneOf(int a, int b, int c = -1, int d = -1) {
    ArgCount r{0, kAny};
    r.oneOf[0] = a, r.oneOf[1] = b, r.oneOf[2] = c, r.oneOf[3] = d;
    return r;
}
ArgCount none() { return exactly(0); }

ArgRule plain(ArgCount s, ArgCount r) { return {s, none(), r}; }
ArgRule fixedXf(int at, ArgCount r) { return {atLeast(at), none(), r, XformAt::Fixed, at}; }
// Data types: `minStrings` strings at least; coordinate functions then the transform
// follow the function file at index `coordsAt - 1`.
ArgRule dataXf(int minStrings, int coordsAt, ArgCount r) {
    return {atLeast(minStrings), none(), r, XformAt::Search, coordsAt};
}

using T = PrimType;
constexpr size_t kCount = static_cast<size_t>(PrimType::Alias) + 1;

std::array<ArgRule, kCount> makeTable() {
    std::array<ArgRule, kCount> t{};
    auto set = [&](T type, ArgRule r) { t[static_cast<size_t>(type)] = r; };
    // Surfaces.
    set(T::Source, plain(none(), exactly(4)));
    set(T::Sphere, plain(none(), exactly(4)));
    set(T::Bubble, plain(none(), exactly(4)));
    ArgCount polygon = atLeast(9);  // 3n reals, n >= 3
    polygon.multiple = 3;
    set(T::Polygon, plain(none(), polygon));
    set(T::Cone, plain(none(), exactly(8)));
    set(T::Cup, plain(none(), exactly(8)));
    set(T::Cylinder, plain(none(), exactly(7)));
    set(T::Tube, plain(none(), exactly(7)));
    set(T::Ring, plain(none(), exactly(8)));
    set(T::Instance, fixedXf(1, none()));  // "1+ octree transform"
    set(T::Mesh, fixedXf(1, none()));
    // Light-emitting materials.
    set(T::Light, plain(none(), exactly(3)));
    set(T::Illum, plain(range(0, 1), exactly(3)));  // optional alternate material
    set(T::Glow, plain(none(), exactly(4)));
    set(T::Spotlight, plain(none(), exactly(7)));
    // Reflecting and refracting materials.
    set(T::Mirror, plain(range(0, 1), exactly(3)));
    set(T::Prism1, fixedXf(5, atLeast(0)));
    set(T::Prism2, fixedXf(9, atLeast(0)));
    set(T::Plastic, plain(none(), exactly(5)));
    set(T::Metal, plain(none(), exactly(5)));
    set(T::Trans, plain(none(), exactly(7)));
    set(T::Plastic2, fixedXf(4, exactly(6)));
    set(T::Metal2, fixedXf(4, exactly(6)));
    set(T::Trans2, fixedXf(4, exactly(8)));
    set(T::Ashik2, fixedXf(4, exactly(8)));
    set(T::Mist, plain(atLeast(0), oneOf(0, 3, 6, 7)));
    set(T::Dielectric, plain(none(), exactly(5)));
    set(T::Interface, plain(none(), exactly(8)));
    set(T::Glass, plain(none(), oneOf(3, 4)));
    set(T::Plasfunc, fixedXf(2, atLeast(4)));
    set(T::Metfunc, fixedXf(2, atLeast(4)));
    set(T::Transfunc, fixedXf(2, atLeast(6)));
    set(T::BRTDfunc, fixedXf(10, atLeast(9)));
    set(T::Plasdata, dataXf(3, 3, atLeast(4)));  // func datafile funcfile x1..xn transform
    set(T::Metdata, dataXf(3, 3, atLeast(4)));
    set(T::Transdata, dataXf(3, 3, atLeast(6)));
    set(T::BSDF, fixedXf(6, oneOf(0, 3, 6, 9)));  // thick BSDFfile ux uy uz funcfile
    set(T::ABSDF, fixedXf(5, oneOf(0, 3, 6, 9)));
    // WGMDfunc (RADIANCE 6): rs_mod rs rs_ur rs_vr ts_mod ts ts_ur ts_vr td_mod ux uy uz
    // funcfile transform
    set(T::WGMDfunc, fixedXf(13, atLeast(9)));
    set(T::Antimatter, plain(atLeast(1), none()));  // N mod1 .. modN
    // Textures.
    set(T::Texfunc, fixedXf(4, atLeast(0)));
    set(T::Texdata, dataXf(7, 7, atLeast(0)));  // 3 funcs, 3 data files, vfname, coords
    // Patterns.
    set(T::Colorfunc, fixedXf(4, atLeast(0)));
    set(T::Brightfunc, fixedXf(2, atLeast(0)));
    set(T::Colordata, dataXf(7, 7, atLeast(0)));
    set(T::Brightdata, dataXf(3, 3, atLeast(0)));
    set(T::Colorpict, fixedXf(7, atLeast(0)));            // 3 funcs, pictfile, funcfile, u, v
    set(T::Colortext, plain(atLeast(2), range(15, 16)));  // [spacing]
    set(T::Brighttext, plain(atLeast(2), range(11, 12)));
    set(T::Spectrum, plain(none(), atLeast(5)));  // nmA nmB s1 s2 s3 ..
    set(T::Specfile, plain(exactly(1), none()));
    set(T::Specfunc, fixedXf(2, atLeast(2)));
    set(T::Specdata, dataXf(3, 3, atLeast(0)));
    set(T::Specpict, fixedXf(5, atLeast(0)));  // func specfile funcfile u v
    // Mixtures.
    set(T::Mixfunc, fixedXf(4, atLeast(0)));
    set(T::Mixdata, dataXf(5, 5, atLeast(0)));
    set(T::Mixpict, fixedXf(7, atLeast(0)));
    set(T::Mixtext, plain(atLeast(4), range(9, 10)));
    set(T::Alias, plain(none(), none()));
    return t;
}

const std::array<ArgRule, kCount> kRules = makeTable();

std::string header(const Primitive& p) {
    return std::string(primTypeName(p.type)) + " '" + p.name + "': ";
}

void checkCount(const Primitive& p, const ArgCount& c, size_t n, const char* kind) {
    if (!c.allows(n))
        throw InputError(p.loc,
                         header(p) + "expected " + c.describe(kind) + ", got " + std::to_string(n));
}

// Sphere and bubble: RADIANCE o_sphere() flips a negative radius into the other type.
void checkSphere(Primitive& p) {
    double& r = p.rargs[3];
    if (r < -kFtiny) {
        warn(p.loc, header(p) + "negative radius, made a " +
                        std::string(p.type == PrimType::Sphere ? "bubble" : "sphere"));
        p.type = p.type == PrimType::Sphere ? PrimType::Bubble : PrimType::Sphere;
        r = -r;
    } else if (r <= kFtiny) {
        throw InputError(p.loc, header(p) + "zero radius");
    }
}

double axisLength(const double* a, const double* b) {
    return std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                     (b[2] - a[2]) * (b[2] - a[2]));
}

// Cones, cups, cylinders, tubes and rings: RADIANCE getcone() (common/cone.c).
void checkCone(Primitive& p) {
    double* a = p.rargs.data();
    bool cyl = p.type == PrimType::Cylinder || p.type == PrimType::Tube;
    bool ring = p.type == PrimType::Ring;
    if (cyl) {
        if (a[6] < -kFtiny) {
            warn(p.loc, header(p) + "negative radius, made a " +
                            std::string(p.type == PrimType::Cylinder ? "tube" : "cylinder"));
            p.type = p.type == PrimType::Cylinder ? PrimType::Tube : PrimType::Cylinder;
            a[6] = -a[6];
        } else if (a[6] <= kFtiny) {
            throw InputError(p.loc, header(p) + "illegal radii (zero radius)");
        }
    } else {
        int s0 = a[6] < -kFtiny ? -1 : a[6] > kFtiny ? 1 : 0;
        int s1 = a[7] < -kFtiny ? -1 : a[7] > kFtiny ? 1 : 0;
        if (s0 + s1 == 0)  // both zero, or of opposite sign
            throw InputError(p.loc, header(p) + "illegal radii");
        if (s0 < 0 || s1 < 0) {
            if (ring) throw InputError(p.loc, header(p) + "negative radii");
            warn(p.loc, header(p) + "negative radii, made a " +
                            std::string(p.type == PrimType::Cone ? "cup" : "cone"));
            p.type = p.type == PrimType::Cone ? PrimType::Cup : PrimType::Cone;
        }
        a[6] *= s0;
        a[7] *= s1;
        if (ring && std::fabs(a[7] - a[6]) <= kFtiny)
            throw InputError(p.loc, header(p) + "illegal radii (inner equals outer)");
    }
    double len = ring ? std::sqrt(a[3] * a[3] + a[4] * a[4] + a[5] * a[5]) : axisLength(a, a + 3);
    if (len == 0.0) throw InputError(p.loc, header(p) + "zero orientation");
}

// RADIANCE compat: o_face() warns about and drops a polygon without area rather than
// stopping the load. Degenerate = fewer than 3 distinct vertices, or zero area.
bool polygonHasArea(const std::vector<double>& v) {
    size_t n = v.size() / 3;
    size_t distinct = 0;
    for (size_t i = 0; i < n; ++i) {
        bool seen = false;
        for (size_t j = 0; j < i && !seen; ++j)
            seen = v[3 * i] == v[3 * j] && v[3 * i + 1] == v[3 * j + 1] &&
                   v[3 * i + 2] == v[3 * j + 2];
        if (!seen) ++distinct;
    }
    if (distinct < 3) return false;
    // Newell's method: twice the vector area, valid for non-convex polygons and seams.
    double nx = 0, ny = 0, nz = 0;
    for (size_t i = 0; i < n; ++i) {
        const double* a = &v[3 * i];
        const double* b = &v[3 * ((i + 1) % n)];
        nx += (a[1] - b[1]) * (a[2] + b[2]);
        ny += (a[2] - b[2]) * (a[0] + b[0]);
        nz += (a[0] - b[0]) * (a[1] + b[1]);
    }
    double area2 = std::sqrt(nx * nx + ny * ny + nz * nz);
    double extent = 0;  // compare against the polygon's own size, not an absolute zero
    for (size_t i = 0; i < n; ++i) extent = std::max(extent, axisLength(&v[0], &v[3 * i]));
    return area2 > 1e-12 * extent * extent && area2 > 0;
}
}  // namespace

bool ArgCount::allows(size_t n) const {
    if (oneOf[0] >= 0) {
        for (int v : oneOf)
            if (v >= 0 && static_cast<size_t>(v) == n) return true;
        return false;
    }
    if (n < static_cast<size_t>(min)) return false;
    if (max >= 0 && n > static_cast<size_t>(max)) return false;
    return n % multiple == 0;
}

std::string ArgCount::describe(const char* kind) const {
    std::string k = std::string(" ") + kind + " argument";
    if (oneOf[0] >= 0) {
        std::string s;
        int count = 0;
        for (int v : oneOf)
            if (v >= 0) ++count;
        for (int i = 0; i < count; ++i) {
            if (i) s += (i == count - 1) ? " or " : ", ";
            s += std::to_string(oneOf[i]);
        }
        return s + k + "s";
    }
    if (multiple > 1)
        return "a multiple of " + std::to_string(multiple) + k + "s (at least " +
               std::to_string(min) + ")";
    if (max == min) return std::to_string(min) + k + (min == 1 ? "" : "s");
    if (max < 0) return "at least " + std::to_string(min) + k + (min == 1 ? "" : "s");
    if (max == min + 1) return std::to_string(min) + " or " + std::to_string(max) + k + "s";
    return std::to_string(min) + " to " + std::to_string(max) + k + "s";
}

const ArgRule& argRule(PrimType t) { return kRules[static_cast<size_t>(t)]; }

size_t transformStart(const Primitive& p) {
    const ArgRule& r = argRule(p.type);
    size_t at = static_cast<size_t>(r.xformIndex);
    switch (r.xformAt) {
        case XformAt::None:
            return p.sargs.size();
        case XformAt::Fixed:
            return std::min(at, p.sargs.size());
        case XformAt::Search:
            // The coordinate-function count comes from the data file's dimensions, which
            // is not read here; a coordinate expression is never spelt exactly like a
            // transform option, so the first such word starts the transform.
            for (size_t i = at; i < p.sargs.size(); ++i)
                if (isTransformOption(p.sargs[i])) return i;
            return p.sargs.size();
    }
    return p.sargs.size();
}

bool checkArgs(Primitive& p) {
    const ArgRule& r = argRule(p.type);
    checkCount(p, r.strings, p.sargs.size(), "string");
    checkCount(p, r.integers, p.iargs.size(), "integer");
    checkCount(p, r.reals, p.rargs.size(), "real");
    if (r.xformAt != XformAt::None) {
        try {
            parseTransform(p.sargs, transformStart(p), p.loc);
        } catch (const InputError& e) {
            throw InputError(p.loc, header(p) + e.message());
        }
    }
    switch (p.type) {
        case PrimType::Sphere:
        case PrimType::Bubble:
            checkSphere(p);
            break;
        case PrimType::Cone:
        case PrimType::Cup:
        case PrimType::Cylinder:
        case PrimType::Tube:
        case PrimType::Ring:
            checkCone(p);
            break;
        case PrimType::Polygon:
            if (!polygonHasArea(p.rargs)) {
                warn(p.loc, header(p) + "degenerate polygon (zero area), skipped");
                return false;
            }
            break;
        case PrimType::Source:
            if (p.rargs[0] == 0 && p.rargs[1] == 0 && p.rargs[2] == 0)
                throw InputError(p.loc, header(p) + "zero direction");
            break;
        default:
            break;
    }
    return true;
}

}  // namespace rp
