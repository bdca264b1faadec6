// RADIANCE `polygon`: the exact plane (Newell normal, double precision) kept for hit
// refinement, plus its triangulation for the accelerator. Triangulation itself is in
// triangulate.h; Embree buffers are built in accel/.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/triangulate.h"
#include "scene/primitive.h"
#include "util/vec.h"

namespace rp {

// One polygon's plane and local frame. Triangles of the accelerator point back here.
struct PolygonShape {
    Vec3 normal;      // unit, right-hand rule over the vertex loop (front side)
    double offset;    // plane: dot(normal, x) == offset (mean over the vertices)
    Vec3 origin;      // first vertex: origin of the in-plane frame
    Vec3 vertexMean;  // mean of the outline's vertices (RADIANCE's source centre)
    Vec3 uAxis;       // unit, in plane, along the first non-degenerate edge (PlanarRegion)
    double scale;     // largest |coordinate| of any vertex (float rounding scale)
    int32_t prim;     // index into Scene::prims
    int32_t modifier;
};

// Builds polygon `primIndex` (its rargs are x y z triples). Appends its vertices to
// `vertices` and its triangles (global vertex indices) to `triangles`. Returns false and
// warns (with the primitive's loc) for zero area; throws InputError for a bad argument
// count. Warns, like RADIANCE, when a vertex lies off the mean plane.
bool makePolygon(const Primitive& prim, int32_t primIndex, PolygonShape& shape,
                 std::vector<Vec3>& vertices, std::vector<TriIndices>& triangles);

}  // namespace rp
