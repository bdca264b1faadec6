// The backward pass's light-source list (RADIANCE source.c marksources, virtuals.c
// markvirtuals): real emitters with the geometry the direct calculation samples, the
// planar mirrors and prisms that relay them, and the virtual sources those make. Sampling a
// source from a point lives in source_sampling.h; shadow testing in direct.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/light_sources.h"
#include "material/material.h"
#include "render/render_options.h"
#include "scene/primitive.h"
#include "util/vec.h"

namespace rp::render {

// A planar polygon as a set of triangles in its own (u, v) frame: what flat-source
// sampling subdivides and what mirror tests check a crossing point against.
struct PlanarRegion {
    Vec3 normal;                              // unit, the polygon's front (right-hand rule)
    double offset = 0;                        // plane: dot(normal, x) == offset
    Vec3 origin;                              // (u, v) origin (first vertex)
    Vec3 uAxis, vAxis;                        // unit, in plane; vAxis = normal x uAxis
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;    // bounding rectangle in (u, v)
    std::vector<std::array<double, 6>> tris;  // (u, v) of each triangle's corners, CCW
    double area = 0;
    Vec3 centroid;  // area centroid
    Vec3 centre;    // RADIANCE's source centre (fsetsrc sloc): the mean of the
                    // outline's vertices, or the centroid if that lies outside

    Vec3 at(double u, double v) const { return origin + uAxis * u + vAxis * v; }
    // Whether in-plane point (u, v) lies in the polygon (on a triangle, edges included).
    bool contains(double u, double v) const;
    double signedDistance(const Vec3& p) const { return dot(normal, p) - offset; }
};

// Builds the region of ShapeSet polygon `index` from the geometry's triangulation.
PlanarRegion makePlanarRegion(const ShapeSet& shapes, size_t index);

// A planar surface that relays light sources as virtual sources (virtuals.c): a `mirror`
// reflects them (m_mirror.c); a `prism1`/`prism2` redirects them in one or two
// directions given by its functions (m_direct.c).
struct RelayPlane {
    enum class Kind : uint8_t { Mirror, Prism } kind = Kind::Mirror;
    int32_t prim = -1;
    int32_t modifier = kVoid;
    int projections = 1;  // prism2: 2 (one virtual source per redirection)
    PlanarRegion region;
    bool isPrism() const { return kind == Kind::Prism; }
    Vec3 reflectPoint(const Vec3& p) const {
        return p - region.normal * (2 * region.signedDistance(p));
    }
    Vec3 reflectDir(const Vec3& d) const { return d - region.normal * (2 * dot(region.normal, d)); }
};

// One relay on a virtual source's path: the affine map x -> x + (n.x - offset) shear that
// takes what lies behind the relay (the source itself or its image in later relays) to
// the image seen through it; directions map by the linear part d -> d + (n.d) shear.
// A mirror's shear is -2 n (a reflection); a prism's is m_direct.c's dir_proj: for the
// direction `old` from the source to the relay's centre and the redirected direction
// `new` there, new/(n.new) - old/(n.old), less 2 n when `new` crosses back.
struct RelayStep {
    int32_t relay = -1;  // index into SourceList::relays
    int projection = 0;  // prism2: which redirection (0 or 1)
    Vec3 shear;
    // The relayed source's (apparent) centre, distant: its direction. A prism's DxA DyA
    // DzA aim here (m_direct.c: the source the virtual one was made from).
    Vec3 target;
    bool targetDistant = false;

    Vec3 project(const PlanarRegion& r, const Vec3& p) const {
        return p + shear * r.signedDistance(p);
    }
    Vec3 projectDir(const PlanarRegion& r, const Vec3& d) const {
        return d + shear * dot(r.normal, d);
    }
    // Determinant of the linear part: 1 + n.shear, which is +1 or -1 (crossing back).
    double det(const PlanarRegion& r) const { return 1 + dot(r.normal, shear); }
    Vec3 unproject(const PlanarRegion& r, const Vec3& p) const {
        return p - shear * (r.signedDistance(p) / det(r));
    }
    // Unit direction from `p` toward `target`.
    Vec3 toTarget(const Vec3& p) const { return targetDistant ? target : normalize(target - p); }
};

struct DirectSource {
    light::LightSource light;  // the real emitter: prim, material params, shape
    Vec3 centre;               // RADIANCE sloc (distant: unit direction to the source)
    // Local glow (RADIANCE SPROX): light reaches only points within this distance of
    // `centre` (measured from the apparent origin for virtual sources). 0: no limit.
    double proximity = 0;
    int32_t region = -1;  // polygon sources: index into SourceList::regions
    // Virtual sources: the relays in the order a shadow ray from the shaded point meets
    // them; empty for a real source.
    std::vector<RelayStep> relays;
    // Virtual sources: where the source appears from the relays' side (distant: the
    // apparent direction), used to check that a point is on the side that sees it.
    Vec3 apparentCentre;
    // Virtual sources: the side (+1/-1) of the first relay's plane a point must be on;
    // 0 for any side (prisms: the path through the prism decides).
    int mirrorSide = 0;

    bool distant() const { return light.distant(); }
    bool isVirtual() const { return !relays.empty(); }
};

// A prism1/prism2 redirection evaluated by the renderer (its .cal functions): redirection
// `projection` of the prism surface at `hit`, met by a ray travelling in `dir`, with
// DxA DyA DzA the unit direction `toSource` (zero: a ray not aimed at a source).
using RedirectFunction = std::function<material::Redirection(const Hit& hit, const Vec3& dir,
                                                             int projection, const Vec3& toSource)>;

struct SourceList {
    std::vector<DirectSource> sources;  // real sources in scene order, then virtual ones
    size_t realCount = 0;
    std::vector<PlanarRegion> regions;  // of polygon sources
    std::vector<RelayPlane> relays;     // planar mirrors and prisms (virtual sources on)
    // Per prim: index of the real source whose surface it is, -1 if none.
    std::vector<int32_t> sourceOfPrim;
    // Per SceneGeometry::sources() entry: whether it is a direct source.
    std::vector<bool> distantInList;
};

// RADIANCE marksources: light, spotlight, illum, glow with positive radius on surfaces;
// light, illum and spotlight (as light) on distant `source`s. A glow on a `source` is the
// sky (RADIANCE SSKIP): left to the ambient calculation. With `virtualSources` and
// options.relays > 0, each planar polygon whose material is `mirror` relays every source
// in front of it, and each whose material is `prism1`/`prism2` (given `redirect`) every
// source on either side once per redirection, up to options.relays relays (virtuals.c);
// spheres and other curved mirrors relay nothing. Pretest: a source relayed by a mirror
// must lie strictly in front of the mirror (on its normal's side: mirrors reflect on the
// front only), by a prism off its plane; a flat source must face some part of the relay;
// a prism's redirection at its centre must have a coefficient above FTINY and leave the
// plane (m_direct.c dir_proj); with -dp > 0
// a grid of mirror points (dp per steradian of the mirror seen from the source, 4 to
// 256) must include one that sees the source's centre past opaque surfaces (RADIANCE
// virtuals.c tests with full shadow rays; we have no materials here, so every surface
// that is not plainly opaque, e.g. glass, trans, lights, is passed: conservative).
SourceList buildSourceList(const Scene& scene, const SceneGeometry& geometry,
                           const DirectOptions& options, bool virtualSources,
                           const RedirectFunction& redirect = {});

}  // namespace rp::render
