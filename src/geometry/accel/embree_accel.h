// The Embree 3 accelerator: the only code that sees rtc* calls or types. Built once from
// a ShapeSet (polygons' triangles as an Embree triangle mesh; spheres, cones and rings as
// Embree user geometry with exact double-precision intersectors, or tested one by one
// with those intersectors when there are only a few of them), then queried from
// any number of threads. Hit records are completed by SceneGeometry, not here.
#pragma once

#include <cstdint>
#include <memory>

#include "geometry/ray.h"
#include "geometry/shapes.h"

namespace rp {

struct AccelHit {
    ShapeKind kind = ShapeKind::Polygon;
    uint32_t index = 0;  // into the ShapeSet array of `kind` (polygons, spheres, ...)
    uint32_t triangle = 0;  // for polygons: the triangle Embree reported
    double t = 0;        // double precision: against the polygon's exact plane, or the
                         // analytic quadric with the unrounded ray
};

class EmbreeAccel {
public:
    // Keeps a reference to `shapes`, which must outlive the accelerator. Throws
    // std::runtime_error if Embree reports an error (device error callback).
    explicit EmbreeAccel(const ShapeSet& shapes);
    ~EmbreeAccel();
    EmbreeAccel(const EmbreeAccel&) = delete;
    EmbreeAccel& operator=(const EmbreeAccel&) = delete;

    // Nearest surface with t in (0, ray.tmax) whose modifier is not in `skip`.
    bool intersect(const Ray& ray, const ModifierSet* skip, AccelHit& hit) const;
    // Any such surface. Triangles are tested in single precision here (no refinement):
    // callers keep their shadow-ray ends an offset away from surfaces (spawnSegment).
    bool occluded(const Ray& ray, const ModifierSet* skip) const;

    size_t triangleCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp
