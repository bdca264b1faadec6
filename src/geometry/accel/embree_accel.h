// The Embree 3 accelerator: the only code that sees rtc* calls or types. Built once from
// the scene's own ShapeSet (polygons' triangles as an Embree triangle mesh; spheres,
// cones and rings as Embree user geometry with exact double-precision intersectors, or
// tested one by one with those intersectors when there are only a few of them) and the
// placed objects: each octree's shapes or mesh built once as an Embree scene of its own,
// placed by Embree instances, one per placement. Queried from any number of threads.
// Hit records are completed by SceneGeometry, not here.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/ray.h"
#include "geometry/shapes.h"
#include "scene/mesh_data.h"
#include "scene/xform.h"

namespace rp {

// An object that placements refer to, in its own coordinates: exactly one of the two.
struct AccelObject {
    const ShapeSet* shapes = nullptr;  // an octree's surfaces
    const MeshData* mesh = nullptr;    // a mesh's triangles (shared with Embree, not copied)
};

// One placed copy of an object, and the modifier its surfaces report (for the per-query
// skip sets here, for hit records in SceneGeometry): fixedModifier when `fixed`, else the
// shape's own (octree) or meshMaterialBase + the triangle's material (mesh; kVoid where
// it has none).
struct AccelPlacement {
    uint32_t object = 0;  // index into the objects given
    TransformPair xf;     // object <-> world
    bool fixed = false;
    int32_t fixedModifier = kVoid;
    int32_t meshMaterialBase = 0;

    int32_t modifierOf(int32_t own) const { return fixed ? fixedModifier : own; }
    int32_t meshModifier(const MeshData& m, size_t triangle) const {
        if (fixed) return fixedModifier;
        const int32_t mat = m.materialOf(triangle);
        return mat == kVoid ? kVoid : meshMaterialBase + mat;
    }
};

struct AccelHit {
    ShapeKind kind = ShapeKind::Polygon;
    uint32_t index = 0;      // into the ShapeSet array of `kind` (polygons, spheres, ...), or
                             // the mesh triangle
    uint32_t triangle = 0;   // for polygons: the triangle Embree reported
    int32_t placement = -1;  // the placement hit, -1 for the scene's own shapes
    double t = 0;            // double precision: against the polygon's exact plane (or the
                             // mesh triangle's), or the analytic quadric with the unrounded
                             // ray; the same in object space, whose rays are not normalised
};

class EmbreeAccel {
public:
    // Keeps references to `shapes` and the objects, which must outlive the accelerator.
    // Throws std::runtime_error if Embree reports an error (device error callback).
    EmbreeAccel(const ShapeSet& shapes, std::vector<AccelObject> objects = {},
                std::vector<AccelPlacement> placements = {});
    ~EmbreeAccel();
    EmbreeAccel(const EmbreeAccel&) = delete;
    EmbreeAccel& operator=(const EmbreeAccel&) = delete;

    // Nearest surface with t in (0, ray.tmax) whose modifier is not in `skip`.
    bool intersect(const Ray& ray, const ModifierSet* skip, AccelHit& hit) const;
    // Any such surface. Triangles are tested in single precision here (no refinement):
    // callers keep their shadow-ray ends an offset away from surfaces (spawnSegment).
    bool occluded(const Ray& ray, const ModifierSet* skip) const;

    size_t triangleCount() const;  // the scene's own polygon triangles

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp
