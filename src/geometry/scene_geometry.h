// SceneGeometry: the traceable geometry of one Scene and its queries (closest hit,
// occlusion, bounds, RADIANCE's scene cube, distant sources by direction): the scene's
// own shapes and every placement of its instanced octrees and meshes (each object
// built once). Built once; all queries are const and thread-safe. Materials and lights
// live elsewhere.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/accel/embree_accel.h"
#include "geometry/coincident.h"
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
    // Throws InputError for bad surface arguments (with the primitive's loc); warns about
    // and skips degenerate shapes. Instances and meshes need their objects attached
    // (attachObjects, which loadScene does).
    explicit SceneGeometry(const Scene& scene);
    ~SceneGeometry();
    SceneGeometry(SceneGeometry&&) noexcept;
    SceneGeometry& operator=(SceneGeometry&&) noexcept;

    // Nearest surface with t in (0, ray.tmax), ignoring surfaces whose modifier is in
    // `skip` (they are passed through, e.g. antimatter). Origins on a surface must be
    // offset first (spawnRay).
    std::optional<Hit> closestHit(const Ray& ray, const ModifierSet* skip = nullptr) const;

    // Whether anything (modifier not in `skip`) lies on the ray with t in (0, tmax).
    bool occluded(const Vec3& origin, const Vec3& dir, double tmax,
                  const ModifierSet* skip = nullptr) const;

    // Bounds of every traced surface (sources have none): tight for the scene's own, the
    // placed cube's corners for instances and meshes, as RADIANCE's oconv bounds them.
    const Bounds3& bounds() const { return bounds_; }
    SceneCube sceneCube() const;

    const std::vector<DistantSource>& sources() const { return shapes_->sources; }
    // Indices into sources() whose disk contains unit direction dir, in input order.
    std::vector<int32_t> sourcesInDirection(const Vec3& dir) const;

    // The scene's own shapes (where light sources are: none inside instances).
    const ShapeSet& shapes() const { return *shapes_; }
    size_t triangleCount() const { return shapes_->triangles.size(); }
    size_t placementCount() const { return placements_.size(); }

    // Per triangle, what moving a hit point inside it needs (scene_geometry.cpp
    // insetIntoTriangle): the in-plane unit inward normal of each edge and the smallest
    // height of a vertex over its opposite edge. Computed once for polygons because the
    // normalisations were most of the cost of completing a polygon hit (80 bytes per
    // triangle); for mesh triangles at each hit, since meshes are large.
    struct TriangleInset {
        Vec3 inward[3];
        double minRoom;  // NaN if any height is NaN (degenerate): never inset
    };

private:
    // One placed copy of an object and how the surfaces inside report themselves
    // (RADIANCE o_instance.c, o_mesh.c). With where.fixed every surface inside reports
    // `prim` and where.fixedModifier: an instance with a modifier of its own (or one
    // inside such an instance), or a mesh with one.
    struct Placement {
        AccelPlacement where;  // object (Scene::objects index), transforms, modifier rule
        int32_t prim = -1;     // fixed: the primitive reported; mesh: the mesh primitive
        // RADIANCE ray.rox: the object space function files see; none for world space.
        std::optional<TransformPair> patternSpace;
    };
    struct ObjectGeometry;
    Hit completeHit(const Ray& ray, const AccelHit& a) const;
    Hit completePlacedHit(const Ray& ray, const AccelHit& a) const;
    void place(const Scene& scene, int32_t begin, int32_t end, const Transform& outer,
               const Placement* fixedBy, int depth);

    std::unique_ptr<ShapeSet> shapes_;     // heap: the accelerator points into it
    std::vector<TriangleInset> insets_;    // indexed like shapes_->triangles
    CoincidentPolygons coincident_;        // the scene's own doubled surfaces
    std::vector<ObjectGeometry> objects_;  // indexed like Scene::objects
    std::vector<Placement> placements_;
    Bounds3 bounds_;
    std::unique_ptr<EmbreeAccel> accel_;  // last: built from everything above
};

// RADIANCE compat (oconv.c): bounds grown by OMARGIN = 10*FTINY on every side, side =
// largest extent, cube centred on the bounds.
SceneCube sceneCubeFor(const Bounds3& bounds);

}  // namespace rp
