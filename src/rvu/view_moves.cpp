// rvu's view changes (see view_moves.h).
#include "rvu/view_moves.h"

#include <algorithm>
#include <cmath>

namespace rp::rvu {

namespace {

constexpr double kDegree = kPi / 180;
constexpr double kTiny = 1e-6;  // RADIANCE's FTINY

double focalDistance(const View& v) { return length(v.direction); }
Vec3 unitDirection(const View& v) { return normalize(v.direction); }
Vec3 unitUp(const View& v) { return normalize(v.up); }

// Half-angle zoom of a perspective-like extent in degrees: tan(a/2) shrinks by `f`.
double zoomTangent(double degrees, double f) {
    return std::atan(std::tan(degrees * kDegree / 2) / f) / (kDegree / 2);
}

}  // namespace

Vec3 spinVector(const Vec3& v, const Vec3& axis, double theta) {
    if (theta == 0) return v;
    const double c = std::cos(theta), s = std::sin(theta);
    return v * c + axis * (dot(v, axis) * (1 - c)) + cross(axis, v) * s;
}

Vec3 geodesic(const Vec3& v, const Vec3& target, double theta) {
    const double len = length(v);
    if (theta == 0 || len == 0 || length(target) == 0) return v;
    const Vec3 a = v / len, b = normalize(target);
    const double d = dot(a, b);
    if (d >= 1 - kTiny * kTiny || d <= -1 + kTiny * kTiny) return v;
    const double c = std::cos(theta), sr = std::sin(theta) / std::sqrt(1 - d * d);
    return (a * c + (b - a * d) * sr) * len;
}

void zoomView(View& v, double f) {
    // RADIANCE compat (rv3.c zoomview), per view type.
    switch (v.type) {
        case ViewType::kParallel:
            v.horizontal /= f;
            v.vertical /= f;
            return;
        case ViewType::kAngular:
            v.horizontal = std::min(360.0, v.horizontal / f);
            v.vertical = std::min(360.0, v.vertical / f);
            return;
        case ViewType::kPlanisphere: {
            // Stereographic: the image radius goes as tan(angle/2).
            auto zoom = [f](double deg) {
                double t = std::sin(kDegree / 2 * deg) / (1 + std::cos(kDegree / 2 * deg)) / f;
                t *= t;
                return 2 / kDegree * std::acos((1 - t) / (1 + t));
            };
            v.horizontal = zoom(v.horizontal);
            v.vertical = zoom(v.vertical);
            return;
        }
        case ViewType::kCylindrical:
            v.horizontal = std::min(360.0, v.horizontal / f);
            v.vertical = zoomTangent(v.vertical, f);
            return;
        case ViewType::kPerspective:
            v.horizontal = zoomTangent(v.horizontal, f);
            v.vertical = zoomTangent(v.vertical, f);
            return;
        case ViewType::kHemispherical: {
            auto zoom = [f](double deg) {
                const double s = std::sin(deg * kDegree / 2) / f;
                return s >= 1 - kTiny ? 180.0 : std::asin(s) / (kDegree / 2);
            };
            v.horizontal = zoom(v.horizontal);
            v.vertical = zoom(v.vertical);
            return;
        }
    }
}

View rotateView(const View& view, double angle, double elev, double zoom) {
    // RADIANCE compat (rv2.c getrotate).
    View v = view;
    const Vec3 up = unitUp(view);
    Vec3 dir = spinVector(unitDirection(view), up, angle * kDegree);
    if (elev != 0) dir = geodesic(dir, up, elev * kDegree);
    v.direction = dir * focalDistance(view);
    zoomView(v, zoom);
    return v;
}

View aimView(const View& view, const Vec3& direction, double zoom) {
    View v = view;
    v.direction = direction * focalDistance(view);
    zoomView(v, zoom);
    return v;
}

View moveView(const View& view, double angle, double elev, double mag, const Vec3& center) {
    // RADIANCE compat (rv3.c moveview).
    View v = view;
    const Vec3 up = unitUp(view), oldDir = unitDirection(view);
    Vec3 dir = spinVector(oldDir, up, angle * kDegree);
    if (elev != 0) dir = geodesic(dir, up, -elev * kDegree);
    double d = 0, vdist = focalDistance(view);
    if (v.type == ViewType::kParallel) {
        v.horizontal /= mag;
        v.vertical /= mag;
        d = dot(center - view.point, oldDir);  // parallel views are not moved closer
    } else {
        d = length(view.point - center) / mag;
        if (v.fore > kTiny) v.fore = std::max(0.0, v.fore + d - d * mag);
        if (v.aft > kTiny) {
            v.aft += d - d * mag;
            if (v.aft <= v.fore) v.aft = 0;
        }
        vdist /= mag;
    }
    v.point = center - dir * d;
    v.direction = dir * vdist;
    return v;
}

View advanceView(const View& view, double distance) {
    View v = view;
    v.point = view.point + unitDirection(view) * distance;
    return v;
}

View placeView(const View& view, const Vec3& point, const Vec3& direction) {
    // RADIANCE compat (rv2.c getorigin): a new up vector when the direction is along it.
    View v = view;
    v.point = point;
    v.direction = direction * focalDistance(view);
    const double d = dot(direction, unitUp(view));
    if (d * d >= 1 - 2 * kTiny) {
        int i = 2;
        while (i > 0 && direction[i] * direction[i] >= 0.34) --i;
        v.up = Vec3{};
        v.up[i] = 1;
    }
    return v;
}

}  // namespace rp::rvu
