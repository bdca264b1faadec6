// RADIANCE transform arguments (-t, -rx/-ry/-rz, -s, -mx/-my/-mz, -i) parsed into a
// double-precision 4x4 matrix, as they appear after the function file of patterns,
// textures and materials, and on xform's command line. Nothing here reads scenes.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "util/error.h"
#include "util/vec.h"

namespace rp {

// An affine transform p' = M p (column vectors). scale is the uniform scale factor that
// RADIANCE keeps beside the matrix (XF.sca): distances and radii multiply by it.
struct Transform {
    std::array<std::array<double, 4>, 4> m{
        {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    double scale = 1.0;

    static Transform identity() { return {}; }
    static Transform translate(double x, double y, double z);
    static Transform rotateX(double degrees);
    static Transform rotateY(double degrees);
    static Transform rotateZ(double degrees);
    static Transform uniformScale(double f);
    static Transform mirror(int axis);  // 0 = x, 1 = y, 2 = z

    // (a * b) applies b first, then a.
    Transform operator*(const Transform& b) const;
    // Applies `next` after this one: what each further option on a command line does.
    Transform then(const Transform& next) const { return next * *this; }

    std::array<double, 3> point(const std::array<double, 3>& p) const;
    std::array<double, 3> direction(const std::array<double, 3>& v) const;
    // The same for Vec3 (named apart: brace-initialised arrays would be ambiguous).
    Vec3 mapPoint(const Vec3& p) const {
        auto r = point(std::array<double, 3>{p.x, p.y, p.z});
        return {r[0], r[1], r[2]};
    }
    Vec3 mapDirection(const Vec3& v) const {
        auto r = direction(std::array<double, 3>{v.x, v.y, v.z});
        return {r[0], r[1], r[2]};
    }
    // The inverse (world to object space). RADIANCE transforms are similarities (rotation,
    // mirror, uniform scale, translation), so the linear part inverts as L^T / scale^2.
    Transform inverse() const;
    // True if the transform mirrors (negative determinant): surface orientation flips.
    bool mirrors() const;
    bool isIdentity() const;
};

// A transform and its inverse (RADIANCE FULLXF): object to world and back.
struct TransformPair {
    Transform forward;   // object -> world
    Transform backward;  // world -> object
    static TransformPair of(const Transform& forward) { return {forward, forward.inverse()}; }
};

// True if `arg` is one of the transform options above (exact spelling).
bool isTransformOption(const std::string& arg);

// Parses args[first..] as a complete transform, applying each option to the result of
// the previous ones, as RADIANCE's xf() does. "-i n" repeats the options that follow it
// (up to the next -i or the end) n times. Bad options, missing or non-numeric values,
// a zero scale factor and a negative count are InputErrors at loc.
Transform parseTransform(const std::vector<std::string>& args, size_t first, const SourceLoc& loc);

}  // namespace rp
