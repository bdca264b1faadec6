// RADIANCE transform options -> 4x4 matrix (see xform.h). Option meanings from the
// xform(1) manual page; order of application and the -i grouping follow RADIANCE's xf().
#include "scene/xform.h"

#include <cmath>
#include <numbers>

#include "scene/lexer.h"

namespace rp {

namespace {
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Rotation by `degrees` in the plane (a, b), counter-clockwise looking down the third axis.
Transform planeRotation(int a, int b, double degrees) {
    Transform t;
    double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    t.m[a][a] = c;
    t.m[a][b] = -s;
    t.m[b][a] = s;
    t.m[b][b] = c;
    return t;
}
}  // namespace

Transform Transform::translate(double x, double y, double z) {
    Transform t;
    t.m[0][3] = x;
    t.m[1][3] = y;
    t.m[2][3] = z;
    return t;
}

Transform Transform::rotateX(double degrees) { return planeRotation(1, 2, degrees); }
Transform Transform::rotateY(double degrees) { return planeRotation(2, 0, degrees); }
Transform Transform::rotateZ(double degrees) { return planeRotation(0, 1, degrees); }

Transform Transform::uniformScale(double f) {
    Transform t;
    for (int i = 0; i < 3; ++i) t.m[i][i] = f;
    t.scale = std::fabs(f);  // RADIANCE compat: XF.sca keeps the magnitude only
    return t;
}

Transform Transform::mirror(int axis) {
    Transform t;
    t.m[axis][axis] = -1;
    return t;
}

Transform Transform::operator*(const Transform& b) const {
    Transform r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    r.scale = scale * b.scale;
    return r;
}

std::array<double, 3> Transform::point(const std::array<double, 3>& p) const {
    std::array<double, 3> r;
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    return r;
}

std::array<double, 3> Transform::direction(const std::array<double, 3>& v) const {
    std::array<double, 3> r;
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return r;
}

bool Transform::mirrors() const {
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return det < 0;
}

bool Transform::isIdentity() const { return m == Transform().m && scale == 1.0; }

bool isTransformOption(const std::string& a) {
    return a == "-t" || a == "-rx" || a == "-ry" || a == "-rz" || a == "-s" || a == "-mx" ||
           a == "-my" || a == "-mz" || a == "-i";
}

Transform parseTransform(const std::vector<std::string>& args, size_t first, const SourceLoc& loc) {
    Transform result;  // groups already closed by a later -i
    Transform group;   // options since the last -i
    long repeat = 1;   // how often `group` applies
    auto closeGroup = [&] {
        for (long k = 0; k < repeat; ++k) result = result.then(group);
        group = Transform();
    };
    auto number = [&](size_t& i, const std::string& opt) {
        if (i + 1 >= args.size())
            throw InputError(loc, "transform option " + opt + ": missing value");
        double v;
        if (!parseReal(args[i + 1], v))
            throw InputError(loc, "transform option " + opt + ": expected a real number, got '" +
                                      args[i + 1] + "'");
        ++i;
        return v;
    };
    for (size_t i = first; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-t") {
            double x = number(i, a), y = number(i, a), z = number(i, a);
            group = group.then(Transform::translate(x, y, z));
        } else if (a == "-rx") {
            group = group.then(Transform::rotateX(number(i, a)));
        } else if (a == "-ry") {
            group = group.then(Transform::rotateY(number(i, a)));
        } else if (a == "-rz") {
            group = group.then(Transform::rotateZ(number(i, a)));
        } else if (a == "-s") {
            double f = number(i, a);
            if (f == 0) throw InputError(loc, "transform option -s: zero scale factor");
            group = group.then(Transform::uniformScale(f));
        } else if (a == "-mx" || a == "-my" || a == "-mz") {
            group = group.then(Transform::mirror(a[2] - 'x'));
        } else if (a == "-i") {
            closeGroup();
            if (i + 1 >= args.size() || !parseInteger(args[i + 1], repeat) || repeat < 0)
                throw InputError(loc, "transform option -i: expected a count of 0 or more, got '" +
                                          (i + 1 < args.size() ? args[i + 1] : std::string()) +
                                          "'");
            ++i;
        } else {
            throw InputError(loc, "bad transform argument '" + a + "'");
        }
    }
    closeGroup();
    return result;
}

Transform Transform::inverse() const {
    Transform inv;
    double s2 = scale * scale;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) inv.m[r][c] = m[c][r] / s2;
    for (int r = 0; r < 3; ++r)
        inv.m[r][3] = -(inv.m[r][0] * m[0][3] + inv.m[r][1] * m[1][3] + inv.m[r][2] * m[2][3]);
    inv.m[3] = {0, 0, 0, 1};
    inv.scale = 1.0 / scale;
    return inv;
}

}  // namespace rp
