// The shapes mkillum samples and its direction grids (see illum_sample.h).
#include <cmath>
#include <string>

#include "illum/illum_sample.h"

namespace rp::illum {

namespace {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

std::string what(const InputObject& o) { return o.typeName + " '" + o.name + "'"; }

Vec3 vertex(const InputObject& o, size_t i) {
    return {o.rargs[3 * i], o.rargs[3 * i + 1], o.rargs[3 * i + 2]};
}

}  // namespace

Color Distribution::average() const {
    Color total;
    for (const Color& c : sums) total += c;
    if (sums.empty()) return total;
    total = total / double(sums.size());
    return samples > 1 ? total / double(samples) : total;
}

void flatGrid(int density, int& altitudes, int& azimuths) {
    altitudes = azimuths = 1;
    if (density <= 0) return;  // a diffuse source: one bin
    const int n = int(kPi * density);
    altitudes = int(std::sqrt(n / kPi) + .5);
    azimuths = int(kPi * altitudes + .5);
}

void roundGrid(int density, int& altitudes, int& azimuths) {
    altitudes = azimuths = 1;
    if (density <= 0) return;
    const int n = int(4 * kPi * density);
    altitudes = int(std::sqrt(2 / kPi * n) + .5);
    azimuths = int(kPi / 2 * altitudes + .5);
}

Vec3 flatDirection(double alt, double azi) {
    const double r = std::sqrt(alt);
    const double phi = 2 * kPi * azi;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - alt)};
}

int flatIndex(const Vec3& d, int altitudes, int azimuths) {
    int i = int((1 - d.z * d.z) * altitudes);
    if (i >= altitudes) i = altitudes - 1;  // grazing: the last ring
    if (i < 0) i = 0;
    double turn = std::atan2(d.y, d.x) * (0.5 / kPi);
    if (turn < 0) turn += 1;
    int j = int(turn * azimuths + .5);
    if (j >= azimuths) j = 0;
    return i * azimuths + j;
}

Vec3 roundDirection(double alt, double azi) {
    const double z = 1 - 2 * alt;
    const double r = std::sqrt(std::fmax(0.0, 1 - z * z));
    const double phi = 2 * kPi * azi;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

FlatFrame frameAbout(const Vec3& w) {
    int axis = 2;
    while (axis > 0 && !(std::fabs(w[axis]) < 0.6)) --axis;
    Vec3 e;
    e[axis] = 1;
    FlatFrame f;
    f.w = w;
    f.u = normalize(cross(e, w));
    f.v = cross(w, f.u);
    return f;
}

bool Face::contains(const Vec3& p) const {
    // Even-odd crossings of the ray from p along +x in the plane that drops the normal's
    // largest axis (RADIANCE inface).
    const int xi = (axis + 1) % 3, yi = (axis + 2) % 3;
    const double x = p[xi], y = p[yi];
    bool inside = false;
    for (size_t k = 0, j = vertices.size() - 1; k < vertices.size(); j = k++) {
        const Vec3& a = vertices[j];
        const Vec3& b = vertices[k];
        if ((a[yi] > y) == (b[yi] > y)) continue;
        const double cross = a[xi] + (y - a[yi]) * (b[xi] - a[xi]) / (b[yi] - a[yi]);
        if (cross > x) inside = !inside;
    }
    return inside;
}

Face makeFace(const InputObject& o) {
    const size_t n = o.rargs.size();
    if (n < 9 || n % 3 != 0)
        throw InputError(o.loc, what(o) +
                                    ": expected 3 real arguments per vertex and at least "
                                    "3 vertices, got " +
                                    std::to_string(n) + " reals");
    Face f;
    for (size_t i = 0; i < n / 3; ++i) f.vertices.push_back(vertex(o, i));
    // RADIANCE compat (face.c): a last vertex repeating the first is dropped.
    if (f.vertices.size() > 3 &&
        lengthSquared(f.vertices.back() - f.vertices.front()) <= kFtiny * kFtiny)
        f.vertices.pop_back();
    const Vec3& v0 = f.vertices.front();
    Vec3 sum;
    for (size_t i = 2; i < f.vertices.size(); ++i)
        sum += cross(f.vertices[i - 1] - v0, f.vertices[i] - v0);
    const double len = length(sum);
    if (len == 0) return f;
    f.normal = sum / len;
    f.area = len / 2;
    for (const Vec3& v : f.vertices) f.offset += dot(f.normal, v);
    f.offset /= double(f.vertices.size());
    f.axis = std::fabs(f.normal.y) > std::fabs(f.normal.x) ? 1 : 0;
    if (std::fabs(f.normal.z) > std::fabs(f.normal[f.axis])) f.axis = 2;
    return f;
}

Ring makeRing(const InputObject& o) {
    if (o.rargs.size() != 8)
        throw InputError(
            o.loc, what(o) + ": expected 8 real arguments, got " + std::to_string(o.rargs.size()));
    Ring r;
    r.centre = vertex(o, 0);
    r.normal = vertex(o, 1);
    // RADIANCE cone.c: radii within FTINY of zero are zero; negative ones, or equal
    // ones, make no ring.
    double a = std::fabs(o.rargs[6]) <= kFtiny ? 0 : o.rargs[6];
    double b = std::fabs(o.rargs[7]) <= kFtiny ? 0 : o.rargs[7];
    if (a < 0 || b < 0 || std::fabs(a - b) <= kFtiny)
        throw InputError(o.loc, what(o) + ": illegal radii, cannot make an illum");
    r.inner = std::fmin(a, b);
    r.outer = std::fmax(a, b);
    const double len = length(r.normal);
    if (len == 0) throw InputError(o.loc, what(o) + ": no direction, cannot make an illum");
    r.normal = r.normal / len;
    return r;
}

Sphere makeSphere(const InputObject& o) {
    if (o.rargs.size() != 4)
        throw InputError(
            o.loc, what(o) + ": expected 4 real arguments, got " + std::to_string(o.rargs.size()));
    return {vertex(o, 0), o.rargs[3]};
}

}  // namespace rp::illum
