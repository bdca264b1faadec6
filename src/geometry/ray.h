// Ray and hit records shared by every geometry query, the per-query set of modifiers to
// pass through, and the spawnRay offset rule that keeps secondary rays off the surface
// they leave. Intersection code lives with the shapes (sphere.h, ...) and in accel/.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "scene/xform.h"
#include "util/fast_minmax.h"
#include "util/vec.h"

namespace rp {

// A ray o + t*dir, t in (0, tmax). dir need not be unit, but then t is in units of
// |dir|; the renderer always passes unit directions so that t is a distance.
// Both vectors start on 16-byte boundaries. Why: compilers copy and load a Vec3 as an
// (x, y) pair plus z; with dir at offset 24 a ray copied in 16-byte pieces was then read
// back as (dir.x, dir.y) straddling two of those stores, which the store buffer cannot
// forward (a stall at the start of every photon path).
struct Ray {
    alignas(16) Vec3 origin;
    alignas(16) Vec3 dir;
    double tmax = HUGE_VAL;
};

// Where a ray met a surface.
struct Hit {
    double t = 0;  // ray parameter (distance for a unit direction)
    Vec3 point;    // o + t*dir, recomputed in double against the exact surface
    // Unit geometric normal with the primitive's own orientation as RADIANCE defines it
    // (polygon: right-hand rule; sphere/cone/cylinder: outward; bubble/cup/tube: inward;
    // ring: its direction vector). It is NOT flipped toward the ray: see `front`.
    Vec3 normal;
    bool front = true;  // dot(dir, normal) < 0: the ray arrived on the front side
    // The surface as shading sees it (RADIANCE ray.ro): index into Scene::prims of the
    // surface, or inside an instance with a modifier of its own that instance, or for a
    // mesh the mesh primitive; and the modifier that applies (kVoid = -1).
    int32_t prim = -1;
    int32_t modifier = -1;
    // RADIANCE's local coordinates (ray.uv, Lu and Lv): a mesh's interpolated (u, v)
    // where its three vertices have them, 0 everywhere else.
    double u = 0, v = 0;
    // A mesh's interpolated vertex normal minus the geometric normal (RADIANCE ray.pert,
    // to which textures add); zero elsewhere.
    Vec3 perturbation;
    // Inside an instance or mesh: the object space its function files see (RADIANCE
    // ray.rox), held by the SceneGeometry that made the hit; null for world space.
    const TransformPair* objectSpace = nullptr;
    // Distance by which a ray leaving this point must start off the surface so that it
    // can neither re-hit it through rounding nor tunnel through a neighbouring surface
    // farther than this (see spawnRay).
    double offset = 0;
};

// Modifiers whose surfaces a query passes through (antimatter, sensors, ports). Small
// sets are the rule, so a linear scan beats hashing.
class ModifierSet {
public:
    ModifierSet() = default;
    ModifierSet(std::initializer_list<int32_t> mods) : mods_(mods) {}
    void add(int32_t modifier) {
        if (!contains(modifier)) mods_.push_back(modifier);
    }
    bool contains(int32_t modifier) const {
        for (int32_t m : mods_)
            if (m == modifier) return true;
        return false;
    }
    bool empty() const { return mods_.empty(); }

private:
    std::vector<int32_t> mods_;
};

// Offset rule. Embree traverses and tests triangles in single precision, so the origin
// of a secondary ray, the triangle vertices and Embree's plane test each carry a rounding
// error of about one float ulp of the coordinates involved: 2^-24 * max|coordinate|.
// Moving the origin 32 such ulps along the normal (2^-19 relative, i.e. 1.9 mm at 1 km,
// 1.9 nm at 1 mm) puts it unambiguously on the intended side of a planar surface, yet
// keeps millimetre gaps near the origin open. Quadrics are intersected entirely in
// double from the double ray kept beside Embree's, so they only need a double-precision
// margin (2^-40 relative). `scale` is the largest |coordinate| of the hit point and of
// the surface it lies on (a large polygon hit near the origin still has large vertices).
constexpr double kFloatOffsetRel = 1.0 / (1 << 19);
constexpr double kDoubleOffsetRel = 1.0 / (double(1LL << 40));

// Forced inline: GCC kept it out of line in hit completion, a call (and its AVX state
// transitions) per photon bounce.
[[gnu::always_inline]] inline double maxAbs(const Vec3& p) {
    // fastMax: fabs gives no -0, so the same bits as std::fmax without its libm call.
    return fastMax(std::fabs(p.x), fastMax(std::fabs(p.y), std::fabs(p.z)));
}

// A ray leaving hit.point in direction dir, with its origin moved hit.offset to the
// side of the surface that dir points into (so reflection and transmission both work).
inline Ray spawnRay(const Hit& hit, const Vec3& dir, double tmax = HUGE_VAL) {
    double side = dot(dir, hit.normal) >= 0 ? hit.offset : -hit.offset;
    return Ray{hit.point + hit.normal * side, dir, tmax};
}

// A shadow-ray segment from hit.point to target: origin offset toward the target and
// tmax shortened by the target's own offset so that the target surface itself does not
// count as an occluder. Fills out (unit direction) and returns out.tmax.
inline double spawnSegment(const Hit& hit, const Vec3& target, double targetOffset, Ray& out) {
    Vec3 d = target - hit.point;
    double side = dot(d, hit.normal) >= 0 ? hit.offset : -hit.offset;
    out.origin = hit.point + hit.normal * side;
    Vec3 to = target - out.origin;
    double dist = length(to);
    out.dir = dist > 0 ? to / dist : d;
    out.tmax = std::fmax(0.0, dist - targetOffset);
    return out.tmax;
}

}  // namespace rp
