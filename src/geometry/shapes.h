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

// Shape families, also the accelerator's geometry ids.
enum class ShapeKind : uint8_t { Polygon = 0, Sphere = 1, Cone = 2, Ring = 3 };

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

// Builds the shapes of every surface primitive. Modifiers are ignored; `instance` and
// `mesh` throw notSupportedYet; bad arguments throw InputError; degenerate shapes are
// skipped with a warning naming their loc.
ShapeSet buildShapes(const Scene& scene);

}  // namespace rp
