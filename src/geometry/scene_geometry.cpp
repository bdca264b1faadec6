// SceneGeometry queries and hit completion (see scene_geometry.h).
#include "geometry/scene_geometry.h"

#include <cmath>

#include "geometry/accel/embree_accel.h"
#include "util/fast_minmax.h"

namespace rp {


SceneGeometry::~SceneGeometry() = default;
SceneGeometry::SceneGeometry(SceneGeometry&&) noexcept = default;
SceneGeometry& SceneGeometry::operator=(SceneGeometry&&) noexcept = default;

std::optional<Hit> SceneGeometry::closestHit(const Ray& ray, const ModifierSet* skip,
                                             bool surfaceCoords) const {
    AccelHit a;
    if (!accel_->intersect(ray, skip, a)) return std::nullopt;
    return completeHit(ray, a, surfaceCoords);
}

bool SceneGeometry::occluded(const Vec3& origin, const Vec3& dir, double tmax,
                             const ModifierSet* skip) const {
    return accel_->occluded(Ray{origin, dir, tmax}, skip);
}

namespace {

// Embree's float edge test can accept a hit up to a few float ulps outside the
// triangle. Near a corner that puts the hit point (and then a spawned origin) on the
// far side of the neighbouring wall's plane, and the next ray escapes. So the double
// hit point is moved into the triangle until it is at least `inset` from each edge
// (in the polygon's plane). Triangulation diagonals are interior, so moving away from
// them changes nothing; moving off a boundary edge by the spawn offset is within the
// float accuracy the hit was found with anyway. Triangles too small to hold such a
// point are left alone.
//
// The edge data depend on the triangle only and are computed once (triangleInset); the
// arithmetic is unchanged, so hit points are bit-identical to computing them per hit.
template <class TriangleInset>
TriangleInset triangleInset(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
    const Vec3* v[3] = {&a, &b, &c};
    TriangleInset t;
    t.minRoom = HUGE_VAL;
    for (int i = 0; i < 3; ++i) {
        t.inward[i] = normalize(cross(n, *v[(i + 1) % 3] - *v[i]));  // in plane, CCW about n
        double room = dot(*v[(i + 2) % 3] - *v[i], t.inward[i]);  // height of the third vertex
        t.minRoom = std::isnan(room) || std::isnan(t.minRoom) ? NAN : std::fmin(t.minRoom, room);
    }
    return t;
}

template <class TriangleInset>
void insetIntoTriangle(Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                       const TriangleInset& t, double inset) {
    if (!(t.minRoom > 4 * inset)) return;
    const Vec3* v[3] = {&a, &b, &c};
    // Pushing off one edge can move the point toward another at an acute corner, so
    // repeat; three rounds settle every triangle whose heights exceed 4 insets.
    for (int round = 0; round < 3; ++round) {
        bool moved = false;
        for (int i = 0; i < 3; ++i) {
            double dist = dot(p - *v[i], t.inward[i]);
            if (dist < inset) {
                p += t.inward[i] * (inset - dist);
                moved = true;
            }
        }
        if (!moved) return;
    }
}

}  // namespace

SceneGeometry::SceneGeometry(const Scene& scene)
    : shapes_(std::make_unique<ShapeSet>(buildShapes(scene))),
      accel_(std::make_unique<EmbreeAccel>(*shapes_)) {
    const ShapeSet& s = *shapes_;
    insets_.reserve(s.triangles.size());
    for (size_t i = 0; i < s.triangles.size(); ++i) {
        const TriIndices& tri = s.triangles[i];
        insets_.push_back(triangleInset<TriangleInset>(
            s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]],
            s.polygons[s.trianglePolygon[i]].normal));
    }
}

Hit SceneGeometry::completeHit(const Ray& ray, const AccelHit& a, bool surfaceCoords) const {
    Hit h;
    h.t = a.t;
    h.point = ray.origin + ray.dir * a.t;
    double scale = maxAbs(h.point);
    SurfacePoint sp;
    uint32_t index = a.index;
    switch (a.kind) {
    case ShapeKind::Polygon: {
        const PolygonShape& p = shapes_->polygons[index];
        // Float triangles: the offset must clear their rounding (ray.h).
        h.offset = kFloatOffsetRel * fastMax(scale, p.scale);
        const TriIndices& tri = shapes_->triangles[a.triangle];
        insetIntoTriangle(h.point, shapes_->vertices[tri[0]], shapes_->vertices[tri[1]],
                          shapes_->vertices[tri[2]], insets_[a.triangle], h.offset);
        sp.normal = p.normal;
        if (surfaceCoords) {
            Vec3 rel = h.point - p.origin;
            sp.u = dot(rel, p.uAxis);
            sp.v = dot(rel, cross(p.normal, p.uAxis));
        }
        h.prim = p.prim;
        h.modifier = p.modifier;
        break;
    }
    case ShapeKind::Sphere: {
        const SphereShape& s = shapes_->spheres[index];
        if (surfaceCoords)
            sp = sphereSurface(s, h.point);
        else
            sp.normal = sphereNormal(s, h.point);
        h.prim = s.prim;
        h.modifier = s.modifier;
        h.offset = kDoubleOffsetRel * fastMax(scale, s.radius);
        break;
    }
    case ShapeKind::Cone: {
        const ConeShape& c = shapes_->cones[index];
        sp = coneSurface(c, h.point);
        h.prim = c.prim;
        h.modifier = c.modifier;
        h.offset = kDoubleOffsetRel * std::fmax(scale, c.length + std::fmax(c.r0, c.r1));
        break;
    }
    case ShapeKind::Ring: {
        const RingShape& r = shapes_->rings[index];
        sp = ringSurface(r, h.point);
        h.prim = r.prim;
        h.modifier = r.modifier;
        h.offset = kDoubleOffsetRel * fastMax(scale, r.r1);
        break;
    }
    }
    h.normal = sp.normal;
    h.u = sp.u;
    h.v = sp.v;
    h.front = dot(ray.dir, h.normal) < 0;
    return h;
}

SceneCube sceneCubeFor(const Bounds3& bounds) {
    SceneCube cube;
    if (bounds.empty()) return cube;
    constexpr double kOMargin = 10 * 1e-6;  // oconv.c: OMARGIN = 10*FTINY
    Vec3 lo = bounds.min - Vec3{kOMargin, kOMargin, kOMargin};
    Vec3 hi = bounds.max + Vec3{kOMargin, kOMargin, kOMargin};
    Vec3 ext = hi - lo;
    cube.size = std::fmax(ext.x, std::fmax(ext.y, ext.z));
    cube.origin = (hi + lo - Vec3{cube.size, cube.size, cube.size}) * 0.5;
    return cube;
}

SceneCube SceneGeometry::sceneCube() const { return sceneCubeFor(shapes_->bounds); }

std::vector<int32_t> SceneGeometry::sourcesInDirection(const Vec3& dir) const {
    std::vector<int32_t> out;
    rp::sourcesInDirection(shapes_->sources, dir, out);
    return out;
}

}  // namespace rp
