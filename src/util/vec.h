// Double-precision 3-vectors for geometry and shading. Single precision lives only
// inside the accelerator and in stored photon records.
#pragma once

#include <cmath>
#include <vector>

namespace rp {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3& operator+=(const Vec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Vec3& operator-=(const Vec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Vec3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vec3& o) const = default;
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double lengthSquared(const Vec3& v) { return dot(v, v); }
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
// Unit vector; a zero vector stays zero (callers that care check the length first).
inline Vec3 normalize(const Vec3& v) {
    double l = length(v);
    return l > 0 ? v / l : v;
}
inline Vec3 vmin(const Vec3& a, const Vec3& b) {
    return {std::fmin(a.x, b.x), std::fmin(a.y, b.y), std::fmin(a.z, b.z)};
}
inline Vec3 vmax(const Vec3& a, const Vec3& b) {
    return {std::fmax(a.x, b.x), std::fmax(a.y, b.y), std::fmax(a.z, b.z)};
}

// Axis-aligned box in double precision; empty when min > max.
struct Bounds3 {
    Vec3 min{HUGE_VAL, HUGE_VAL, HUGE_VAL};
    Vec3 max{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const Vec3& p) {
        min = vmin(min, p);
        max = vmax(max, p);
    }
    void extend(const Bounds3& b) {
        min = vmin(min, b.min);
        max = vmax(max, b.max);
    }
    Vec3 extent() const { return max - min; }
};

constexpr double kPi = 3.14159265358979323846;

// Newell's method: the area-weighted normal of a (possibly non-planar, concave) vertex
// loop, right-hand rule; its length is twice the projected area. Summed relative to the
// first vertex, which keeps full precision for polygons far from the origin.
inline Vec3 newellNormal(const std::vector<Vec3>& loop) {
    Vec3 n;
    const size_t count = loop.size();
    for (size_t i = 0; i < count; ++i) {
        Vec3 a = loop[i] - loop[0];
        Vec3 b = loop[(i + 1) % count] - loop[0];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

// Unit e1, e2 completing unit `axis` to a right-handed orthonormal frame, fixed for each
// axis so that angles about it are reproducible (Duff et al. 2017, "Building an
// orthonormal basis, revisited"): one division, no square root and no branch
// (|sign + axis.z| >= 1, so no cancellation).
inline void orthonormalFrame(const Vec3& axis, Vec3& e1, Vec3& e2) {
    double sign = std::copysign(1.0, axis.z);
    double a = -1.0 / (sign + axis.z);
    double b = axis.x * axis.y * a;
    e1 = {1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
    e2 = {b, sign + axis.y * axis.y * a, -axis.y};
}

}  // namespace rp
