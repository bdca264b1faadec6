// SceneGeometry: the traceable geometry of one Scene and its queries (closest hit,
// occlusion, bounds, RADIANCE's scene cube, distant sources by direction). Built once;
// all queries are const and thread-safe. Materials and lights live elsewhere.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/ray.h"
#include "geometry/shapes.h"
#include "scene/primitive.h"

namespace rp {

class EmbreeAccel;
struct AccelHit;

// RADIANCE's octree cube (oconv: thescene.cuorg, cusize): the axis-aligned cube of side
// `size` with minimum corner `origin` that encloses the scene bounds. Photon emission
// from distant sources aims at its disk.
struct SceneCube {
    Vec3 origin;
    double size = 0;  // 0 for a scene with no traceable surface
};

class SceneGeometry {
public:
    // Throws InputError for bad surface arguments (with the primitive's loc) and for
    // instance/mesh (notSupportedYet); warns about and skips degenerate shapes.
    explicit SceneGeometry(const Scene& scene);
    ~SceneGeometry();
    SceneGeometry(SceneGeometry&&) noexcept;
    SceneGeometry& operator=(SceneGeometry&&) noexcept;

    // Nearest surface with t in (0, ray.tmax), ignoring surfaces whose modifier is in
    // `skip` (they are passed through, e.g. antimatter). Origins on a surface must be
    // offset first (spawnRay). Without `surfaceCoords`, Hit::u and Hit::v are left 0 where
    // they cost extra work (sphere: atan2 and acos; polygon: two dot products); the
    // photon tracer never reads them. Everything else is the same bits either way.
    std::optional<Hit> closestHit(const Ray& ray, const ModifierSet* skip = nullptr,
                                  bool surfaceCoords = true) const;

    // Whether anything (modifier not in `skip`) lies on the ray with t in (0, tmax).
    bool occluded(const Vec3& origin, const Vec3& dir, double tmax,
                  const ModifierSet* skip = nullptr) const;

    // Tight bounds of every traced surface (sources have none).
    const Bounds3& bounds() const { return shapes_->bounds; }
    SceneCube sceneCube() const;

    const std::vector<DistantSource>& sources() const { return shapes_->sources; }
    // Indices into sources() whose disk contains unit direction dir, in input order.
    std::vector<int32_t> sourcesInDirection(const Vec3& dir) const;

    const ShapeSet& shapes() const { return *shapes_; }
    size_t triangleCount() const { return shapes_->triangles.size(); }

private:
    Hit completeHit(const Ray& ray, const AccelHit& a, bool surfaceCoords) const;

    // Per triangle, what moving a hit point inside it needs (scene_geometry.cpp
    // insetIntoTriangle): the in-plane unit inward normal of each edge and the smallest
    // height of a vertex over its opposite edge. Computed once because the normalisations
    // were most of the cost of completing a polygon hit (80 bytes per triangle).
    struct TriangleInset {
        Vec3 inward[3];
        double minRoom;  // NaN if any height is NaN (degenerate): never inset
    };

    std::unique_ptr<ShapeSet> shapes_;  // heap: the accelerator points into it
    std::unique_ptr<EmbreeAccel> accel_;
    std::vector<TriangleInset> insets_;  // indexed like shapes_->triangles
};

// RADIANCE compat (oconv.c): bounds grown by OMARGIN = 10*FTINY on every side, side =
// largest extent, cube centred on the bounds.
SceneCube sceneCubeFor(const Bounds3& bounds);

}  // namespace rp
