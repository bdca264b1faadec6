// Coincident polygons: surfaces that a ray can meet at the same distance. CAD exports
// write a surface shared by two zones twice (Honeybee: a floor and the ceiling below it,
// in one plane with opposite normals and each zone's material). RADIANCE decides such
// ties by a fixed rule (raytrace.c rayreject, for hits within FTINY of each other); our
// float BVH would pick one by traversal order, that is by position. This module finds
// the polygons of the scene's own records that have coincident partners, once, and
// re-decides hits on them by RADIANCE's rule. Placed objects (instances, meshes) are not
// covered.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "geometry/shapes.h"
#include "scene/primitive.h"

namespace rp {

struct TriangleRange {
    uint32_t first = 0, last = 0;  // [first, last) in ShapeSet::triangles
};

class CoincidentPolygons {
public:
    CoincidentPolygons() = default;
    // Pairs of polygons in one plane (every vertex of each within FTINY of the other's
    // plane) whose extents overlap in it.
    CoincidentPolygons(const Scene& scene, const ShapeSet& shapes);

    bool empty() const { return partners_.empty(); }
    size_t pairCount() const { return partners_.size() / 2; }

    // A ray (origin `o`, unit direction `d`) hit polygon `polygon` (its triangle
    // `triangle`) at `t`: among it and its partners that the ray meets within FTINY of t
    // (their modifiers not in `skip`), RADIANCE's choice replaces it: a surface with a
    // material over one without, an opaque material over a transparent one, else the
    // later modifier definition, else the later surface (rtrace -oms on such pairs).
    void resolve(const ShapeSet& shapes, const Vec3& o, const Vec3& d, const ModifierSet* skip,
                 uint32_t& polygon, uint32_t& triangle, double& t) const;

private:
    // Per polygon: first and one-past-last index into partners_ (equal: none).
    std::vector<uint32_t> begin_, end_;
    std::vector<uint32_t> partners_;
    std::vector<TriangleRange> triangles_;  // per polygon: they are contiguous
    // RADIANCE's order between coincident surfaces, larger wins: 2 opaque material (or
    // mixture, antimatter), 1 transparent material, 0 none.
    std::vector<uint8_t> materialClass_;
};

}  // namespace rp
