// RADIANCE polygon: argument checks, plane, frame and triangulation (see polygon.h).
#include "geometry/polygon.h"

#include <cmath>
#include <string>

#include "geometry/ray.h"
#include "util/warnings.h"

namespace rp {

namespace {

// RADIANCE compat (face.c getface, VERTEPS 1e-5): each vertex's distance along the normal
// is compared with the mean of those before it, relatively (absolutely when the first
// is within 1e-5 of the origin's plane), so that 7e-6 off a plane 3 m from the origin is
// planar, as RADIANCE has it. A closing vertex repeating the first is not counted.
bool nonPlanar(const std::vector<Vec3>& loop, const Vec3& normal) {
    size_t n = loop.size();
    if (n > 3 && lengthSquared(loop[0] - loop[n - 1]) <= 1e-12) --n;
    if (n <= 3) return false;
    constexpr double kVertEps = 1e-5;
    double sum = dot(normal, loop[0]);
    const bool smallOffset = std::fabs(sum) <= kVertEps;
    bool bad = false;
    for (size_t i = 1; i < n; ++i) {
        const double d = dot(normal, loop[i]);
        bad = bad || (smallOffset ? std::fabs(d - sum / double(i)) > kVertEps
                                  : std::fabs(1.0 - d * double(i) / sum) > kVertEps);
        sum += d;
    }
    return bad;
}

}  // namespace

bool makePolygon(const Primitive& prim, int32_t primIndex, PolygonShape& shape,
                 std::vector<Vec3>& vertices, std::vector<TriIndices>& triangles) {
    const std::vector<double>& r = prim.rargs;
    if (r.size() % 3 != 0 || r.size() < 9)
        throw InputError(prim.loc, "polygon '" + prim.name +
                                       "': expected a multiple of 3 real arguments (at least "
                                       "9), got " +
                                       std::to_string(r.size()));
    std::vector<Vec3> loop(r.size() / 3);
    for (size_t i = 0; i < loop.size(); ++i) loop[i] = {r[3 * i], r[3 * i + 1], r[3 * i + 2]};

    Vec3 area2 = newellNormal(loop);
    double len = length(area2);
    double scale = 0, size = 0;
    for (const Vec3& v : loop) {
        scale = std::fmax(scale, maxAbs(v));
        size = std::fmax(size, maxAbs(v - loop[0]));
    }
    // RADIANCE compat: face.c rejects polygons of zero area with a warning.
    if (!(len > 0) || len <= 1e-12 * size * size) {
        warn(prim.loc, "polygon '" + prim.name + "': zero area, ignored");
        return false;
    }
    shape.normal = area2 / len;
    shape.offset = 0;
    for (const Vec3& v : loop) shape.offset += dot(shape.normal, v);
    shape.offset /= double(loop.size());
    if (nonPlanar(loop, shape.normal))
        warn(prim.loc, "polygon '" + prim.name + "': non-planar vertex");
    shape.origin = loop[0];
    shape.vertexMean = {};
    for (const Vec3& v : loop) shape.vertexMean += v;
    shape.vertexMean = shape.vertexMean / double(loop.size());
    shape.uAxis = {};
    for (size_t i = 1; i < loop.size(); ++i) {
        Vec3 e = loop[i] - loop[0];
        e -= shape.normal * dot(shape.normal, e);
        if (lengthSquared(e) > 1e-24 * size * size) {
            shape.uAxis = normalize(e);
            break;
        }
    }
    shape.scale = scale;
    shape.prim = primIndex;
    shape.modifier = prim.modifier;

    Triangulation tri = triangulatePolygon(loop, shape.normal);
    uint32_t base = uint32_t(vertices.size());
    vertices.insert(vertices.end(), tri.vertices.begin(), tri.vertices.end());
    for (const TriIndices& t : tri.triangles)
        triangles.push_back({base + t[0], base + t[1], base + t[2]});
    return !tri.triangles.empty();
}

}  // namespace rp
