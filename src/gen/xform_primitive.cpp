// Transforming one Primitive record as RADIANCE's xform does (see xform_scene.h): each
// surface type's points, directions and radii (ray.html argument lists, xform.c o_* and
// m_* functions), the materials whose arguments hold distances, and the transform
// options appended to types that carry their own transform.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "gen/xform_scene.h"
#include "scene/arg_rules.h"

namespace rp {

namespace {
std::array<double, 3> at3(const std::vector<double>& r, size_t i) {
    return {r[i], r[i + 1], r[i + 2]};
}
void set3(std::vector<double>& r, size_t i, const std::array<double, 3>& v) {
    r[i] = v[0], r[i + 1] = v[1], r[i + 2] = v[2];
}

std::string numberArg(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}
}  // namespace

void checkXformArgs(const Primitive& p) {
    auto fail = [&](const std::string& what) {
        return InputError(
            p.loc, "bad " + std::string(primTypeName(p.type)) + " '" + p.name + "': " + what);
    };
    auto exactly = [&](size_t strings, size_t reals) {
        if (p.sargs.size() != strings)
            throw fail("expected " + std::to_string(strings) + " string arguments, got " +
                       std::to_string(p.sargs.size()));
        if (p.rargs.size() != reals)
            throw fail("expected " + std::to_string(reals) + " real arguments, got " +
                       std::to_string(p.rargs.size()));
    };
    switch (p.type) {
        case PrimType::Source:
        case PrimType::Sphere:
        case PrimType::Bubble:
        case PrimType::Glow:
            return exactly(0, 4);
        case PrimType::Polygon:
            if (!p.sargs.empty()) throw fail("expected 0 string arguments");
            if (p.rargs.size() % 3)
                throw fail("expected a multiple of 3 real arguments, got " +
                           std::to_string(p.rargs.size()));
            return;
        case PrimType::Cone:
        case PrimType::Cup:
        case PrimType::Ring:
        case PrimType::Interface:
            return exactly(0, 8);
        case PrimType::Cylinder:
        case PrimType::Tube:
        case PrimType::Spotlight:
            return exactly(0, 7);
        case PrimType::Dielectric:
            return exactly(0, 5);
        case PrimType::Mist:
            if (p.rargs.size() > 7) throw fail("expected at most 7 real arguments");
            return;
        case PrimType::Colortext:
        case PrimType::Brighttext:
        case PrimType::Mixtext:
            if (p.rargs.size() < 9) throw fail("expected at least 9 real arguments");
            return;
        default:
            return;
    }
}

void transformPrimitive(Primitive& p, const Transform& xf, const std::vector<std::string>& xfArgs,
                        bool invert) {
    checkXformArgs(p);
    auto& r = p.rargs;
    auto point = [&](size_t i) { set3(r, i, xf.point(at3(r, i))); };
    auto direction = [&](size_t i) { set3(r, i, xf.direction(at3(r, i))); };
    auto swapType = [&](PrimType a, PrimType b) {
        if (invert) p.type = p.type == a ? b : a;
    };
    switch (p.type) {
        case PrimType::Source:
            direction(0);  // the angular size does not change
            break;
        case PrimType::Sphere:
        case PrimType::Bubble:
            point(0);
            r[3] *= xf.scale;
            swapType(PrimType::Sphere, PrimType::Bubble);
            break;
        case PrimType::Polygon:
            for (size_t i = 0; i < r.size(); i += 3) point(i);
            // A mirror turns the vertex order, hence the normal; reversing the order keeps
            // the surface facing the same (transformed) side. -I reverses it on purpose.
            if (xf.mirrors() != invert)
                for (size_t i = 0, j = r.size() - 3; i < j; i += 3, j -= 3)
                    std::swap_ranges(r.begin() + static_cast<long>(i),
                                     r.begin() + static_cast<long>(i) + 3,
                                     r.begin() + static_cast<long>(j));
            break;
        case PrimType::Cone:
        case PrimType::Cup:
            point(0), point(3);
            r[6] *= xf.scale, r[7] *= xf.scale;
            swapType(PrimType::Cone, PrimType::Cup);
            break;
        case PrimType::Cylinder:
        case PrimType::Tube:
            point(0), point(3);
            r[6] *= xf.scale;
            swapType(PrimType::Cylinder, PrimType::Tube);
            break;
        case PrimType::Ring:
            point(0), direction(3);
            if (invert) r[3] = -r[3], r[4] = -r[4], r[5] = -r[5];
            r[6] *= xf.scale, r[7] *= xf.scale;
            break;
        case PrimType::Glow:
            r[3] *= xf.scale;  // the maximum radius is a distance
            break;
        case PrimType::Spotlight:
            direction(4);  // xform.c m_spot(): the aim vector turns (and scales) with the scene
            break;
        case PrimType::Mist:
            // Extinction is per unit length: a scene scaled by s needs coefficients / s.
            if (r.size() > 2) r[0] /= xf.scale, r[1] /= xf.scale, r[2] /= xf.scale;
            break;
        case PrimType::Dielectric:
        case PrimType::Interface:
            // Transmission is given per unit distance: over s units it is t^s, so the
            // transformed scene keeps the same attenuation with t^(1/s).
            for (size_t i = 0; i < 3; ++i) r[i] = std::pow(r[i], 1.0 / xf.scale);
            if (p.type == PrimType::Interface)
                for (size_t i = 4; i < 7; ++i) r[i] = std::pow(r[i], 1.0 / xf.scale);
            break;
        case PrimType::Colortext:
        case PrimType::Brighttext:
        case PrimType::Mixtext:
            point(0), direction(3), direction(6);  // anchor, right and down vectors
            break;
        default:
            if (argRule(p.type).xformAt != XformAt::None && !xfArgs.empty()) {
                // xform.c addxform(): the options are appended as written. "-i 1" first closes
                // any "-i n" group the existing transform ends with, so the new options are not
                // repeated with it.
                if (xfArgs[0] != "-i") p.sargs.insert(p.sargs.end(), {"-i", "1"});
                p.sargs.insert(p.sargs.end(), xfArgs.begin(), xfArgs.end());
            }
            break;
    }
}

std::vector<std::string> transformArgs(const Transform& xf) {
    std::vector<std::string> args;
    if (xf.isIdentity()) return args;
    double s = xf.scale;
    bool mirror = xf.mirrors();
    // R = M / s with the first column negated when mirrored (-mx applied first).
    double R[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R[i][j] = xf.m[i][j] / s * (mirror && j == 0 ? -1 : 1);
    // R = Rz(c) Ry(b) Rx(a): "-rx a -ry b -rz c" applies a first.
    double a, b, c;
    double sb = std::clamp(-R[2][0], -1.0, 1.0);
    b = std::asin(sb);
    if (std::fabs(sb) < 1.0 - 1e-12) {
        a = std::atan2(R[2][1], R[2][2]);
        c = std::atan2(R[1][0], R[0][0]);
    } else {  // gimbal lock: fold the z rotation into x
        c = 0;
        a = std::atan2(-R[1][2], R[1][1]);
    }
    auto degrees = [](double rad) { return rad * 180.0 / std::numbers::pi; };
    if (mirror) args.push_back("-mx");
    if (s != 1.0) args.insert(args.end(), {"-s", numberArg(s)});
    if (a != 0) args.insert(args.end(), {"-rx", numberArg(degrees(a))});
    if (b != 0) args.insert(args.end(), {"-ry", numberArg(degrees(b))});
    if (c != 0) args.insert(args.end(), {"-rz", numberArg(degrees(c))});
    if (xf.m[0][3] != 0 || xf.m[1][3] != 0 || xf.m[2][3] != 0)
        args.insert(args.end(),
                    {"-t", numberArg(xf.m[0][3]), numberArg(xf.m[1][3]), numberArg(xf.m[2][3])});
    return args;
}

void transformPrimitive(Primitive& p, const Transform& xf) {
    transformPrimitive(p, xf, transformArgs(xf), false);
}

}  // namespace rp
