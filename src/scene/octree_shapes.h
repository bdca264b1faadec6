// How each object of a scene meets RADIANCE's octree, as RADIANCE's oconv decides it
// (ot/bbox.c, o_face.c, sphere.c, o_cone.c, o_instance.c): its bounding box, and whether
// it misses, cuts or (instances and meshes only) encloses a cube. Polygons, spheres and
// bubbles, cones, cups, cylinders, tubes and rings, instances (through their octree's
// cube and transform) and meshes (their mesh cube and transform) take part; every other
// record misses every cube. Internal to the octree builder (octree_build.h).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "scene/primitive.h"
#include "scene/radiance_geom.h"

namespace rp::octree {

using radgeom::Vec;

// An axis-aligned cube: origin corner and side (RADIANCE's CUBE).
struct Cube {
    Vec org{};
    double size = 0;
};

// octree.h O_MISS, O_HIT, O_IN.
enum Overlap : int { kMiss = 0, kHit = 1, kInside = 2 };

class Shapes {
public:
    // The cube of the octree or mesh file an instance or mesh record places.
    using PlacedCube = std::function<Cube(const Primitive&)>;

    // Prepares records [0, count) of `scene` (which must outlive this and not change) as
    // getface(), getcone() and getinstance() prepare them, warning where RADIANCE warns.
    Shapes(const Scene& scene, size_t count, const PlacedCube& placedCube);

    // add2bbox(): grows [lo, hi] to hold object `obj`.
    void addBounds(int32_t obj, Vec& lo, Vec& hi) const;
    // The object's test against cube cu (ofun[type].funp).
    int overlap(int32_t obj, const Cube& cu) const;
    // Instances and meshes: the volumes that may enclose a cube (otypes.h T_V).
    bool isVolume(int32_t obj) const;

    // The smallest cube the cone test subdivides to (oconv's mincusize).
    void setMinCubeSize(double s) { minCube_ = s; }

private:
    // One object, as getface()/getcone()/o_sphere() see it. `a` points at the record's real
    // arguments. Face: nv vertices, dir the unit normal, d0 the plane offset, d1 the area,
    // ax the normal's dominant axis. Sphere: d0 the radius. Cone and ring: the ends at
    // a + p0 and a + p1 with radii d0 and d1, dir the unit axis. Placed: nv indexes
    // placements_.
    struct Shape {
        enum class Kind : uint8_t { None, Face, Sphere, Cone, Ring, Placed };
        Kind kind = Kind::None;
        uint8_t ax = 0, p0 = 0, p1 = 0;
        int32_t nv = 0;
        const double* a = nullptr;
        Vec dir{};
        double d0 = 0, d1 = 0;
    };

    // An instance or mesh: the cube of what it places and the transform placing it.
    struct Placement {
        Cube cube;
        radgeom::FullXf xf;
    };

    void prepareFace(int32_t obj, Shape& s);
    void prepareCone(int32_t obj, Shape& s);
    int faceOverlap(const Shape& f, const Cube& cu) const;
    int sphereOverlap(const Shape& s, const Cube& cu) const;
    int coneOverlap(const Shape& c, const Cube& cu) const;
    int placedOverlap(const Placement& p, const Cube& cu) const;

    const Scene& scene_;
    std::vector<Shape> shapes_;
    std::vector<Placement> placements_;
    double minCube_ = 0;
};

}  // namespace rp::octree
