// Every traceable shape of a Scene, grouped by family in flat arrays: what the
// accelerator (accel/) is built from and what hit records are completed from. Shapes
// describe; accel/ builds. Distant sources are kept here too but never traced.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/cone.h"
#include "geometry/polygon.h"
#include "geometry/ring.h"
#include "geometry/source.h"
#include "geometry/sphere.h"
#include "scene/primitive.h"

namespace rp {

// Shape families, also the accelerator's geometry ids. Mesh triangles occur only in
// placed objects (geometry/placement.h).
enum class ShapeKind : uint8_t { Polygon = 0, Sphere = 1, Cone = 2, Ring = 3, Mesh = 4 };

struct ShapeSet {
    std::vector<PolygonShape> polygons;
    std::vector<Vec3> vertices;             // all polygon vertices, double precision
    std::vector<TriIndices> triangles;      // indices into vertices
    std::vector<uint32_t> trianglePolygon;  // triangle -> index into polygons (flat)
    std::vector<SphereShape> spheres;
    std::vector<ConeShape> cones;
    std::vector<RingShape> rings;
    std::vector<DistantSource> sources;
    Bounds3 bounds;  // of every traced shape (sources excluded)
};

// Builds the shapes of the surface primitives among scene.prims[begin, end): the scene's
// own records or one placed octree's. Modifiers are ignored, and so are instances and
// meshes (they are placements); bad arguments throw InputError; degenerate shapes are
// skipped with a warning naming their loc. Distant sources count only in the scene's
// own records (RADIANCE: no light sources inside instances).
ShapeSet buildShapes(const Scene& scene, int32_t begin, int32_t end);
// The scene's own records.
inline ShapeSet buildShapes(const Scene& scene) { return buildShapes(scene, 0, scene.ownCount()); }

}  // namespace rp
