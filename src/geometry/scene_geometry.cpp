// SceneGeometry queries and hit completion (see scene_geometry.h).
#include "geometry/scene_geometry.h"

#include <cmath>

#include "geometry/accel/embree_accel.h"
#include "scene/mesh_data.h"
#include "util/fast_minmax.h"
#include "util/warnings.h"

namespace rp {

struct SceneGeometry::ObjectGeometry {
    std::unique_ptr<ShapeSet> shapes;  // an octree's (heap: the accelerator points into it)
    std::vector<TriangleInset> insets;
    std::shared_ptr<const MeshData> mesh;
    Vec3 cubeOrigin;  // the object's cube (RADIANCE: what oconv bounds a placement by)
    double cubeSize = 0;
};

SceneGeometry::~SceneGeometry() = default;
SceneGeometry::SceneGeometry(SceneGeometry&&) noexcept = default;
SceneGeometry& SceneGeometry::operator=(SceneGeometry&&) noexcept = default;

std::optional<Hit> SceneGeometry::closestHit(const Ray& ray, const ModifierSet* skip) const {
    AccelHit a;
    if (!accel_->intersect(ray, skip, a)) return std::nullopt;
    if (a.placement >= 0) return completePlacedHit(ray, a);
    if (a.kind == ShapeKind::Polygon)
        coincident_.resolve(*shapes_, ray.origin, ray.dir, skip, a.index, a.triangle, a.t);
    return completeHit(ray, a);
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
        double room = dot(*v[(i + 2) % 3] - *v[i], t.inward[i]);     // height of the third vertex
        t.minRoom = std::isnan(room) || std::isnan(t.minRoom) ? NAN : std::fmin(t.minRoom, room);
    }
    return t;
}

template <class TriangleInset>
void insetIntoTriangle(Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const TriangleInset& t,
                       double inset) {
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

namespace {

template <class Inset>
std::vector<Inset> polygonInsets(const ShapeSet& s) {
    std::vector<Inset> insets;
    insets.reserve(s.triangles.size());
    for (size_t i = 0; i < s.triangles.size(); ++i) {
        const TriIndices& tri = s.triangles[i];
        insets.push_back(triangleInset<Inset>(s.vertices[tri[0]], s.vertices[tri[1]],
                                              s.vertices[tri[2]],
                                              s.polygons[s.trianglePolygon[i]].normal));
    }
    return insets;
}

Bounds3 cubeBoundsIn(const Vec3& origin, double size, const Transform& toWorld) {
    Bounds3 b;
    for (int c = 0; c < 8; ++c) {
        Vec3 corner{origin.x + ((c & 1) ? size : 0), origin.y + ((c & 2) ? size : 0),
                    origin.z + ((c & 4) ? size : 0)};
        b.extend(toWorld.mapPoint(corner));
    }
    return b;
}

// Nesting deeper than this is taken for a mistake (each level multiplies placements).
constexpr int kMaxInstanceDepth = 32;

}  // namespace

SceneGeometry::SceneGeometry(const Scene& scene)
    : shapes_(std::make_unique<ShapeSet>(buildShapes(scene))) {
    insets_ = polygonInsets<TriangleInset>(*shapes_);
    coincident_ = CoincidentPolygons(scene, *shapes_);
    bounds_ = shapes_->bounds;
    // Objects, innermost first so that an octree's cube can include what it places.
    objects_.resize(scene.objects.size());
    for (size_t k = scene.objects.size(); k-- > 0;) {
        const SceneObject& so = scene.objects[k];
        ObjectGeometry& og = objects_[k];
        if (so.kind == SceneObject::Kind::Mesh) {
            og.mesh = so.mesh;
            og.cubeOrigin = {so.mesh->cubeOrigin[0], so.mesh->cubeOrigin[1],
                             so.mesh->cubeOrigin[2]};
            og.cubeSize = so.mesh->cubeSize;
            continue;
        }
        og.shapes = std::make_unique<ShapeSet>(buildShapes(scene, so.firstPrim, so.endPrim));
        og.insets = polygonInsets<TriangleInset>(*og.shapes);
        Bounds3 b = og.shapes->bounds;
        for (int32_t i = so.firstPrim; i < so.endPrim; ++i) {
            const Primitive& p = scene.prims[size_t(i)];
            if (p.placed < 0) continue;
            const ObjectGeometry& inner = objects_[size_t(p.placed)];
            b.extend(
                cubeBoundsIn(inner.cubeOrigin, inner.cubeSize, parseTransform(p.sargs, 1, p.loc)));
        }
        SceneCube cube = sceneCubeFor(b);
        og.cubeOrigin = cube.origin;
        og.cubeSize = cube.size;
    }
    place(scene, 0, scene.ownCount(), Transform{}, nullptr, 0);

    std::vector<AccelObject> objects;
    for (const ObjectGeometry& og : objects_) objects.push_back({og.shapes.get(), og.mesh.get()});
    std::vector<AccelPlacement> placements;
    for (const Placement& p : placements_) placements.push_back(p.where);
    accel_ = std::make_unique<EmbreeAccel>(*shapes_, std::move(objects), std::move(placements));
}

// RADIANCE compat (o_instance.c, o_mesh.c): inside an instance with a modifier, every
// surface is that instance (its modifier, world-space patterns); otherwise the surfaces
// keep their own modifiers and their patterns move with the object. A mesh with a
// modifier is likewise that mesh; without one its triangles take the mesh's materials.
void SceneGeometry::place(const Scene& scene, int32_t begin, int32_t end, const Transform& outer,
                          const Placement* fixedBy, int depth) {
    for (int32_t i = begin; i < end; ++i) {
        const Primitive& p = scene.prims[size_t(i)];
        if (p.type != PrimType::Instance && p.type != PrimType::Mesh) continue;
        if (p.placed < 0)
            throw InputError(p.loc, std::string(primTypeName(p.type)) + " '" + p.name +
                                        "': its file was not loaded");
        if (depth >= kMaxInstanceDepth)
            throw InputError(p.loc, "instance '" + p.name + "': instances nested more than " +
                                        std::to_string(kMaxInstanceDepth) + " deep");
        Placement pl;
        pl.where.object = uint32_t(p.placed);
        pl.where.xf = TransformPair::of(outer * parseTransform(p.sargs, 1, p.loc));
        const SceneObject& so = scene.objects[size_t(p.placed)];
        std::optional<TransformPair> outerSpace;
        if (!outer.isIdentity()) outerSpace = TransformPair::of(outer);
        if (fixedBy) {
            pl.where.fixed = true;
            pl.prim = fixedBy->prim;
            pl.where.fixedModifier = fixedBy->where.fixedModifier;
            pl.patternSpace = fixedBy->patternSpace;
        } else if (p.modifier != kVoid) {
            pl.where.fixed = true;
            pl.prim = i;
            pl.where.fixedModifier = p.modifier;
            pl.patternSpace = outerSpace;
        } else {
            pl.prim = i;
            pl.patternSpace = pl.where.xf;
        }
        pl.where.meshMaterialBase = so.firstPrim;
        const ObjectGeometry& og = objects_[size_t(p.placed)];
        bounds_.extend(cubeBoundsIn(og.cubeOrigin, og.cubeSize, pl.where.xf.forward));
        placements_.push_back(pl);
        if (so.kind == SceneObject::Kind::Octree) {
            const Placement copy = placements_.back();  // the vector may grow below
            place(scene, so.firstPrim, so.endPrim, copy.where.xf.forward,
                  copy.where.fixed ? &copy : nullptr, depth + 1);
        }
    }
}

namespace {

// A hit on one of `shapes` (the scene's own, or an octree's in its own space). Placed
// hits need at least `minOffset`, the world coordinates' rounding in object units.
template <class Inset>
Hit shapeHit(const ShapeSet& shapes, const std::vector<Inset>& insets, const Ray& ray,
             const AccelHit& a, double minOffset = 0) {
    Hit h;
    h.t = a.t;
    h.point = ray.origin + ray.dir * a.t;
    double scale = maxAbs(h.point);
    uint32_t index = a.index;
    switch (a.kind) {
        case ShapeKind::Polygon: {
            const PolygonShape& p = shapes.polygons[index];
            // Float triangles: the offset must clear their rounding (ray.h).
            h.offset = fastMax(kFloatOffsetRel * fastMax(scale, p.scale), minOffset);
            const TriIndices& tri = shapes.triangles[a.triangle];
            insetIntoTriangle(h.point, shapes.vertices[tri[0]], shapes.vertices[tri[1]],
                              shapes.vertices[tri[2]], insets[a.triangle], h.offset);
            h.normal = p.normal;
            h.prim = p.prim;
            h.modifier = p.modifier;
            break;
        }
        case ShapeKind::Sphere: {
            const SphereShape& s = shapes.spheres[index];
            h.normal = sphereNormal(s, h.point);
            h.prim = s.prim;
            h.modifier = s.modifier;
            h.offset = kDoubleOffsetRel * fastMax(scale, s.radius);
            break;
        }
        case ShapeKind::Cone: {
            const ConeShape& c = shapes.cones[index];
            h.normal = coneNormal(c, h.point);
            h.prim = c.prim;
            h.modifier = c.modifier;
            h.offset = kDoubleOffsetRel * std::fmax(scale, c.length + std::fmax(c.r0, c.r1));
            break;
        }
        case ShapeKind::Ring: {
            const RingShape& r = shapes.rings[index];
            h.normal = r.normal;
            h.prim = r.prim;
            h.modifier = r.modifier;
            h.offset = kDoubleOffsetRel * fastMax(scale, r.r1);
            break;
        }
        case ShapeKind::Mesh:
            RP_CHECK(false);  // mesh triangles are always placed
    }
    h.offset = fastMax(h.offset, minOffset);
    h.front = dot(ray.dir, h.normal) < 0;
    return h;
}

}  // namespace

Hit SceneGeometry::completeHit(const Ray& ray, const AccelHit& a) const {
    return shapeHit(*shapes_, insets_, ray, a);
}

namespace {

// A mesh triangle hit in the mesh's space (ray not normalised): point moved inside the
// triangle, geometric normal, and where all three vertices have them the interpolated
// normal (returned in `shading`, zero otherwise) and (u, v).
template <class Inset>
Hit meshHit(const MeshData& m, const Ray& local, const AccelHit& a, double minOffset,
            Vec3& shading) {
    const uint32_t* tri = &m.triangles[3 * size_t(a.index)];
    auto vertex = [&](int k) {
        const float* p = &m.positions[3 * size_t(tri[k])];
        return Vec3{p[0], p[1], p[2]};
    };
    const Vec3 v0 = vertex(0), v1 = vertex(1), v2 = vertex(2);
    const Vec3 n = cross(v1 - v0, v2 - v0);
    Hit h;
    h.t = a.t;
    h.point = local.origin + local.dir * a.t;
    h.normal = normalize(n);
    h.offset = fastMax(
        minOffset, kFloatOffsetRel * fastMax(maxAbs(h.point),
                                             fastMax(maxAbs(v0), fastMax(maxAbs(v1), maxAbs(v2)))));
    insetIntoTriangle(h.point, v0, v1, v2, triangleInset<Inset>(v0, v1, v2, h.normal), h.offset);
    shading = Vec3{};
    const uint8_t flags = m.flagsOf(tri[0]) & m.flagsOf(tri[1]) & m.flagsOf(tri[2]);
    if (!flags) return h;
    // Barycentric weights from the sub-triangle areas (signed along n).
    const double nn = dot(n, n);
    const double w0 = dot(n, cross(v1 - h.point, v2 - h.point)) / nn;
    const double w1 = dot(n, cross(v2 - h.point, v0 - h.point)) / nn;
    const double w[3] = {w0, w1, 1 - w0 - w1};
    if (flags & MeshData::kHasNormal) {
        for (int k = 0; k < 3; ++k) {
            const auto& vn = m.normals[tri[k]];
            shading += Vec3{vn[0], vn[1], vn[2]} * w[k];
        }
    }
    if (flags & MeshData::kHasUV) {
        for (int k = 0; k < 3; ++k) {
            h.u += w[k] * m.uvs[tri[k]][0];
            h.v += w[k] * m.uvs[tri[k]][1];
        }
    }
    return h;
}

}  // namespace

// The hit completed in the object's space from the ray taken there in double, then
// carried back: t is the same parameter in both spaces; the offset clears both the
// object's float rounding and that of the world coordinates the next ray starts from.
Hit SceneGeometry::completePlacedHit(const Ray& ray, const AccelHit& a) const {
    const Placement& pl = placements_[size_t(a.placement)];
    const ObjectGeometry& og = objects_[size_t(pl.where.object)];
    const Transform& fwd = pl.where.xf.forward;
    const Transform& back = pl.where.xf.backward;
    const Ray local{back.mapPoint(ray.origin), back.mapDirection(ray.dir), ray.tmax};
    // The next ray starts from world coordinates rounded to float: the point must be
    // inset and offset by that rounding too (in object units).
    const double minOffset = kFloatOffsetRel * maxAbs(ray.origin + ray.dir * a.t) / fwd.scale;
    Hit h;
    Vec3 shading;
    if (a.kind == ShapeKind::Mesh) {
        h = meshHit<TriangleInset>(*og.mesh, local, a, minOffset, shading);
        h.prim = pl.prim;
        h.modifier = pl.where.meshModifier(*og.mesh, a.index);
    } else {
        h = shapeHit(*og.shapes, og.insets, local, a, minOffset);
        h.modifier = pl.where.modifierOf(h.modifier);
        if (pl.where.fixed) h.prim = pl.prim;
    }
    const double invScale = 1.0 / fwd.scale;
    h.normal = fwd.mapDirection(h.normal) * invScale;
    if (lengthSquared(shading) > 0) {
        // RADIANCE o_mesh.c: the interpolated normal, normalised in world space, minus
        // the geometric normal.
        Vec3 s = fwd.mapDirection(shading);
        double len = length(s);
        if (len > 0) h.perturbation = s / len - h.normal;
    }
    h.point = fwd.mapPoint(h.point);
    h.offset *= fwd.scale;
    h.front = dot(ray.dir, h.normal) < 0;
    h.objectSpace = pl.patternSpace ? &*pl.patternSpace : nullptr;
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

SceneCube SceneGeometry::sceneCube() const { return sceneCubeFor(bounds_); }

std::vector<int32_t> SceneGeometry::sourcesInDirection(const Vec3& dir) const {
    std::vector<int32_t> out;
    rp::sourcesInDirection(shapes_->sources, dir, out);
    return out;
}

}  // namespace rp
