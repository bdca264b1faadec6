// The backward pass's light-source list (RADIANCE source.c marksources, virtuals.c
// markvirtuals): real emitters with the geometry the direct calculation samples, the
// planar mirrors that relay them, and the virtual sources those mirrors make. Sampling a
// source from a point lives in source_sampling.h; shadow testing in direct.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/light_sources.h"
#include "render/render_options.h"
#include "scene/primitive.h"
#include "util/vec.h"

namespace rp::render {

// A planar polygon as a set of triangles in its own (u, v) frame: what flat-source
// sampling subdivides and what mirror tests check a crossing point against.
struct PlanarRegion {
    Vec3 normal;            // unit, the polygon's front (right-hand rule)
    double offset = 0;      // plane: dot(normal, x) == offset
    Vec3 origin;            // (u, v) origin (first vertex)
    Vec3 uAxis, vAxis;      // unit, in plane; vAxis = normal x uAxis
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // bounding rectangle in (u, v)
    std::vector<std::array<double, 6>> tris;  // (u, v) of each triangle's corners, CCW
    double area = 0;
    Vec3 centroid;          // area centroid (RADIANCE sloc for a polygon)

    Vec3 at(double u, double v) const { return origin + uAxis * u + vAxis * v; }
    // Whether in-plane point (u, v) lies in the polygon (on a triangle, edges included).
    bool contains(double u, double v) const;
    double signedDistance(const Vec3& p) const { return dot(normal, p) - offset; }
};

// Builds the region of ShapeSet polygon `index` from the geometry's triangulation.
PlanarRegion makePlanarRegion(const ShapeSet& shapes, size_t index);

// A planar `mirror` surface (m_mirror): virtual sources are seen through it.
struct MirrorPlane {
    int32_t prim = -1;
    int32_t modifier = kVoid;
    PlanarRegion region;
    Vec3 reflectPoint(const Vec3& p) const {
        return p - region.normal * (2 * region.signedDistance(p));
    }
    Vec3 reflectDir(const Vec3& d) const { return d - region.normal * (2 * dot(region.normal, d)); }
};

struct DirectSource {
    light::LightSource light;  // the real emitter: prim, material params, shape
    Vec3 centre;               // RADIANCE sloc (distant: unit direction to the source)
    // Local glow (RADIANCE SPROX): light reaches only points within this distance of
    // `centre` (measured from the apparent origin for virtual sources). 0: no limit.
    double proximity = 0;
    int32_t region = -1;       // polygon sources: index into SourceList::regions
    // Virtual sources: indices into SourceList::mirrors in the order a shadow ray from
    // the shaded point meets them; empty for a real source.
    std::vector<int32_t> mirrors;
    // Virtual sources: where the source appears from the mirrors' side (distant: the
    // apparent direction), used to check that a point is on the side that sees it.
    Vec3 apparentCentre;
    // Virtual sources: the side (+1/-1) of the first mirror's plane a point must be on.
    int mirrorSide = 0;

    bool distant() const { return light.distant(); }
    bool isVirtual() const { return !mirrors.empty(); }
};

struct SourceList {
    std::vector<DirectSource> sources;  // real sources in scene order, then virtual ones
    size_t realCount = 0;
    std::vector<PlanarRegion> regions;  // of polygon sources
    std::vector<MirrorPlane> mirrors;   // planar mirrors (only when virtual sources are on)
    // Per prim: index of the real source whose surface it is, -1 if none.
    std::vector<int32_t> sourceOfPrim;
    // Per SceneGeometry::sources() entry: whether it is a direct source.
    std::vector<bool> distantInList;
};

// RADIANCE marksources: light, spotlight, illum, glow with positive radius on surfaces;
// light, illum and spotlight (as light) on distant `source`s. A glow on a `source` is the
// sky (RADIANCE SSKIP): left to the ambient calculation. With `virtualSources` and
// options.relays > 0, each planar polygon whose material is `mirror` relays every source
// in front of it, up to options.relays reflections (virtuals.c); spheres and other
// curved mirrors relay nothing. Pretest: a source relayed by a mirror must lie strictly
// in front of the mirror (on its normal's side: mirrors reflect on the front only) and, if flat, face some part of the mirror; with -dp > 0
// a grid of mirror points (dp per steradian of the mirror seen from the source, 4 to
// 256) must include one that sees the source's centre past opaque surfaces (RADIANCE
// virtuals.c tests with full shadow rays; we have no materials here, so every surface
// that is not plainly opaque, e.g. glass, trans, lights, is passed: conservative).
SourceList buildSourceList(const Scene& scene, const SceneGeometry& geometry,
                           const DirectOptions& options, bool virtualSources);

}  // namespace rp::render
