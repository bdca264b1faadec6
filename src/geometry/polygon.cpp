// RADIANCE polygon: argument checks, plane, frame and triangulation (see polygon.h).
#include "geometry/polygon.h"

#include <cmath>
#include <string>

#include "geometry/ray.h"
#include "util/warnings.h"

namespace rp {

bool makePolygon(const Primitive& prim, int32_t primIndex, PolygonShape& shape,
                 std::vector<Vec3>& vertices, std::vector<TriIndices>& triangles) {
    const std::vector<double>& r = prim.rargs;
    if (r.size() % 3 != 0 || r.size() < 9)
        throw InputError(prim.loc, "polygon '" + prim.name +
                                       "': expected a multiple of 3 real arguments (at least "
                                       "9), got " + std::to_string(r.size()));
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
    // RADIANCE compat: face.c warns about non-planar vertices (tolerance relative to size).
    for (const Vec3& v : loop)
        if (std::fabs(dot(shape.normal, v) - shape.offset) > 1e-6 * size) {
            warn(prim.loc, "polygon '" + prim.name + "': non-planar vertex");
            break;
        }
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
