// Embree 3 device, scene and callbacks (see embree_accel.h).
//
// Precision model. Embree traverses in float. Every query keeps its double-precision
// ray in a QueryContext that extends RTCIntersectContext, so that
//  - user geometry (quadrics, rings) is intersected entirely in double from that ray;
//    its float bounds are padded so the rounded ray cannot miss the box. A scene with
//    only a few such shapes tests them directly instead (kDirectShapes), also in double;
//  - a triangle hit is re-evaluated in double against its polygon's exact plane. If that
//    disowns it (origin on or behind the plane, ray in the plane), the query is re-run
//    once with a context filter that applies the double test to every candidate. The
//    filter costs traversal speed, so the common case runs without it.
// Modifier skipping uses the same context filter (triangles) and the user intersectors
// (quadrics) reading the context: no per-geometry filter, so no cost when unused.
//
// Placed objects. Each object (an octree's shapes, a mesh) is one Embree scene; each
// placement an Embree instance of it (geometry id kFirstPlacement + index). Callbacks
// inside an instance see Embree's instance id in their context and take the query's
// double ray into that object's space (localRay), so the double-precision tests above
// hold inside instances too; t is the same parameter in both spaces (object-space
// directions are not renormalised).
#include "geometry/accel/embree_accel.h"

#include <embree3/rtcore.h>

#include "util/fast_minmax.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace rp {

namespace {

constexpr unsigned kFirstPlacement = 8;  // geometry ids below are the scene's own ShapeKinds

struct QueryContext {
    RTCIntersectContext rtc;  // first member: Embree hands callbacks &rtc
    const ShapeSet* shapes;   // the scene's own
    const std::vector<AccelObject>* objects;
    const std::vector<AccelPlacement>* placements;
    Vec3 org, dir;
    double tmax;
    const ModifierSet* skip;  // null or non-empty
    bool checkTriangles;      // filter applies the double-precision plane test
    double userT;             // double t of the last user-geometry hit accepted
    unsigned localInst;       // instance whose object-space ray localOrg/localDir hold
    Vec3 localOrg, localDir;
};

struct LocalRay {
    const Vec3& o;
    const Vec3& d;
};

QueryContext* queryContext(RTCIntersectContext* c) { return reinterpret_cast<QueryContext*>(c); }

inline const AccelPlacement& placementOf(const QueryContext& ctx, unsigned inst) {
    return (*ctx.placements)[inst - kFirstPlacement];
}

// The query's double ray in the space of the geometry Embree is testing: the world, or
// the object space of instance `inst` (computed once per query and instance; not
// copied for the world, which is most rays).
[[gnu::always_inline]] inline LocalRay localRay(QueryContext& ctx, unsigned inst) {
    if (inst == RTC_INVALID_GEOMETRY_ID) return {ctx.org, ctx.dir};
    if (inst != ctx.localInst) {
        const AccelPlacement& p = placementOf(ctx, inst);
        ctx.localOrg = p.xf.backward.mapPoint(ctx.org);
        ctx.localDir = p.xf.backward.mapDirection(ctx.dir);
        ctx.localInst = inst;
    }
    return {ctx.localOrg, ctx.localDir};
}

[[gnu::always_inline]] inline const ShapeSet& shapesIn(const QueryContext& ctx, unsigned inst) {
    if (inst == RTC_INVALID_GEOMETRY_ID) return *ctx.shapes;
    return *(*ctx.objects)[placementOf(ctx, inst).object].shapes;
}

// Whether the skip set passes through a surface with modifier `own` inside `inst`.
inline bool skipped(const QueryContext& ctx, unsigned inst, int32_t own) {
    if (!ctx.skip) return false;
    if (inst != RTC_INVALID_GEOMETRY_ID) own = placementOf(ctx, inst).modifierOf(own);
    return ctx.skip->contains(own);
}

// t of the ray against the polygon's exact plane; false if the ray lies in the plane.
inline bool planeT(const PolygonShape& p, const Vec3& o, const Vec3& d, double& t) {
    double dn = dot(p.normal, d);
    if (dn == 0) return false;
    t = (p.offset - dot(p.normal, o)) / dn;
    return true;
}

// Forced inline: out of line it cost a call per photon bounce (mkpmap on the Cornell box).
[[gnu::always_inline]] inline bool validPolygonHit(QueryContext& ctx, unsigned inst, uint32_t tri,
                                                   uint32_t& polygon, double& t) {
    const ShapeSet& shapes = shapesIn(ctx, inst);
    polygon = shapes.trianglePolygon[tri];
    const LocalRay r = localRay(ctx, inst);
    return planeT(shapes.polygons[polygon], r.o, r.d, t) && t > 0 && t < ctx.tmax;
}

// A mesh triangle's plane in double from its float vertices (which are the surface).
inline bool validMeshHit(QueryContext& ctx, unsigned inst, uint32_t tri, double& t) {
    const MeshData& m = *(*ctx.objects)[placementOf(ctx, inst).object].mesh;
    auto vertex = [&](int k) {
        const float* p = &m.positions[3 * size_t(m.triangles[3 * size_t(tri) + size_t(k)])];
        return Vec3{p[0], p[1], p[2]};
    };
    const Vec3 v0 = vertex(0);
    const Vec3 n = cross(vertex(1) - v0, vertex(2) - v0);
    const LocalRay r = localRay(ctx, inst);
    const double dn = dot(n, r.d);
    if (dn == 0) return false;
    t = dot(v0 - r.o, n) / dn;
    return t > 0 && t < ctx.tmax;
}

inline int32_t meshModifier(const QueryContext& ctx, unsigned inst, uint32_t tri) {
    const AccelPlacement& p = placementOf(ctx, inst);
    return p.meshModifier(*(*ctx.objects)[p.object].mesh, tri);
}

void contextFilter(const RTCFilterFunctionNArguments* args) {
    QueryContext* ctx = queryContext(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned geom = RTCHitN_geomID(args->hit, args->N, i);
        const unsigned inst = RTCHitN_instID(args->hit, args->N, i, 0);
        const uint32_t tri = RTCHitN_primID(args->hit, args->N, i);
        double t;
        if (geom == unsigned(ShapeKind::Polygon)) {
            const ShapeSet& shapes = shapesIn(*ctx, inst);
            uint32_t polygon = shapes.trianglePolygon[tri];
            if (skipped(*ctx, inst, shapes.polygons[polygon].modifier) ||
                (ctx->checkTriangles && !validPolygonHit(*ctx, inst, tri, polygon, t)))
                args->valid[i] = 0;
        } else if (geom == unsigned(ShapeKind::Mesh)) {
            if ((ctx->skip && ctx->skip->contains(meshModifier(*ctx, inst, tri))) ||
                (ctx->checkTriangles && !validMeshHit(*ctx, inst, tri, t)))
                args->valid[i] = 0;
        }
    }
}
// ---- user geometry: one Embree geometry per analytic family -------------------------

struct SphereFamily {
    using Shape = SphereShape;
    static bool hit(const Shape& s, const Vec3& o, const Vec3& d, double tmax, double& t) {
        return intersectSphere(s, o, d, 0.0, tmax, t);
    }
    static Bounds3 bounds(const Shape& s) { return sphereBounds(s); }
};
struct ConeFamily {
    using Shape = ConeShape;
    static bool hit(const Shape& s, const Vec3& o, const Vec3& d, double tmax, double& t) {
        return intersectCone(s, o, d, 0.0, tmax, t);
    }
    static Bounds3 bounds(const Shape& s) { return coneBounds(s); }
};
struct RingFamily {
    using Shape = RingShape;
    static bool hit(const Shape& s, const Vec3& o, const Vec3& d, double tmax, double& t) {
        return intersectRing(s, o, d, 0.0, tmax, t);
    }
    static Bounds3 bounds(const Shape& s) { return ringBounds(s); }
};

// The shape list a family's geometry was given as user data (addUser).
template <class F>
const std::vector<typename F::Shape>& shapesOf(void* userPtr) {
    return *static_cast<const std::vector<typename F::Shape>*>(userPtr);
}

// Float box that surely contains the double box, with room for the float rounding of
// the ray Embree traverses with (a few ulps of the coordinates involved).
template <class F>
void boundsFunc(const RTCBoundsFunctionArguments* args) {
    const auto& shapes = shapesOf<F>(args->geometryUserPtr);
    RTCBounds* o = args->bounds_o;
    if (args->primID >= shapes.size()) {
        // The culling stand-in of a lone shape (addUser): a small box beside its box,
        // centred at max + (max - min) + (1,1,1), half-width 1e-3 (1 + largest extent).
        Bounds3 b = F::bounds(shapes[0]);
        const Vec3 e = b.max - b.min;
        const Vec3 p = b.max + e + Vec3{1, 1, 1};
        const double h = 1e-3 * (1 + std::fmax(e.x, std::fmax(e.y, e.z)));
        o->lower_x = float(p.x - h);
        o->lower_y = float(p.y - h);
        o->lower_z = float(p.z - h);
        o->upper_x = float(p.x + h);
        o->upper_y = float(p.y + h);
        o->upper_z = float(p.z + h);
        return;
    }
    Bounds3 b = F::bounds(shapes[args->primID]);
    double pad = std::ldexp(std::fmax(maxAbs(b.min), maxAbs(b.max)), -20);
    auto down = [](double x) { return std::nextafter(float(x), -HUGE_VALF); };
    auto up = [](double x) { return std::nextafter(float(x), HUGE_VALF); };
    o->lower_x = down(b.min.x - pad);
    o->lower_y = down(b.min.y - pad);
    o->lower_z = down(b.min.z - pad);
    o->upper_x = up(b.max.x + pad);
    o->upper_y = up(b.max.y + pad);
    o->upper_z = up(b.max.z + pad);
}

// A shape's exact test from the query's double ray (t in (0, tmax)) in the space of
// `inst`, unless its modifier is skipped: for Embree's user-geometry callbacks and the
// directly tested shapes alike.
template <class F>
bool hitUserShape(const typename F::Shape& s, QueryContext& ctx, unsigned inst, double tmax,
                  double& t) {
    if (skipped(ctx, inst, s.modifier)) return false;
    const LocalRay r = localRay(ctx, inst);
    return F::hit(s, r.o, r.d, tmax, t);
}

template <class F>
void intersectFunc(const RTCIntersectFunctionNArguments* args) {
    RP_CHECK(args->N == 1);  // we only issue rtcIntersect1
    if (!args->valid[0]) return;
    const auto& shapes = shapesOf<F>(args->geometryUserPtr);
    if (args->primID >= shapes.size()) return;  // a culling stand-in (addUser)
    QueryContext* ctx = queryContext(args->context);
    RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    double t;
    if (!hitUserShape<F>(shapes[args->primID], *ctx, args->context->instID[0],
                         fastMin(ctx->tmax, double(rh->ray.tfar)), t))
        return;
    rh->ray.tfar = float(t);  // rounding is monotonic, so still <= the previous tfar
    rh->hit.Ng_x = rh->hit.Ng_y = rh->hit.Ng_z = 0;  // completed in double by the caller
    rh->hit.u = rh->hit.v = 0;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
    ctx->userT = t;
}

template <class F>
void occludedFunc(const RTCOccludedFunctionNArguments* args) {
    RP_CHECK(args->N == 1);  // we only issue rtcOccluded1
    if (!args->valid[0]) return;
    const auto& shapes = shapesOf<F>(args->geometryUserPtr);
    if (args->primID >= shapes.size()) return;  // a culling stand-in (addUser)
    QueryContext* ctx = queryContext(args->context);
    RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
    double t;
    if (hitUserShape<F>(shapes[args->primID], *ctx, args->context->instID[0],
                        std::fmin(ctx->tmax, double(ray->tfar)), t))
        ray->tfar = -HUGE_VALF;  // Embree's "occluded" mark
}

// Scenes with at most this many analytic shapes (spheres, cones and rings together) test
// them directly after the triangle query instead of as Embree user geometry. Why: Embree
// traverses the tree of each geometry type separately, and even the tree of one lone shape
// cost ~170 instructions per ray (callgrind, Cornell's glass ball: a third of the triangle
// traversal's), against ~40 for the shape's own exact test. With more shapes their tree
// pays for itself.
constexpr size_t kDirectShapes = 4;

struct DirectShape {
    ShapeKind kind;
    uint32_t index;  // into the ShapeSet array of `kind`
};

void errorCallback(void*, RTCError code, const char* message) {
    if (code == RTC_ERROR_NONE) return;
    throw std::runtime_error("embree error " + std::to_string(int(code)) + ": " +
                             (message ? message : ""));
}

}  // namespace

struct EmbreeAccel::Impl {
    const ShapeSet& shapes;
    std::vector<AccelObject> objects;
    std::vector<AccelPlacement> placements;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<RTCScene> objectScenes;  // per object; null for an empty one
    bool embreeEmpty = true;             // no geometry attached: queries skip Embree
    std::vector<DirectShape> direct;     // analytic shapes tested outside Embree

    Impl(const ShapeSet& s, std::vector<AccelObject> o, std::vector<AccelPlacement> p)
        : shapes(s), objects(std::move(o)), placements(std::move(p)) {}
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        for (RTCScene s : objectScenes)
            if (s) rtcReleaseScene(s);
        if (device) rtcReleaseDevice(device);
    }

    // `mesh`: compact (memory is a big mesh's limit) and robust. Why robust: a mesh's
    // triangles share edges, and Embree's fast float test lets rays through exactly on
    // them (4.6 % of rays aimed at a grid's edges, geometry test
    // Placement.MeshEdgesAreAlmostWatertight; robust: 0.06 %), where RADIANCE's edge
    // test (o_mesh.c volume_sign) lets none; robust costs mesh rays about 10 %. The scene's
    // own polygons keep the fast test: their only shared edges are the diagonals of
    // their triangulation (geometry tests Polygon.SharedEdge*).
    RTCScene newScene(RTCBuildQuality quality, bool mesh) const {
        RTCScene sc = rtcNewScene(device);
        // Context filters carry the modifier skip set and the double-precision retry.
        int flags = RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION;
        if (mesh) flags |= RTC_SCENE_FLAG_COMPACT | RTC_SCENE_FLAG_ROBUST;
        rtcSetSceneFlags(sc, RTCSceneFlags(flags));
        rtcSetSceneBuildQuality(sc, quality);
        return sc;
    }

    // Polygons' triangles, converted to float (the double vertices stay in the ShapeSet).
    bool addTriangles(RTCScene sc, const ShapeSet& set) {
        if (set.triangles.empty()) return false;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              set.vertices.size()));
        for (size_t i = 0; i < set.vertices.size(); ++i) {
            v[3 * i] = float(set.vertices[i].x);
            v[3 * i + 1] = float(set.vertices[i].y);
            v[3 * i + 2] = float(set.vertices[i].z);
        }
        auto* idx = static_cast<uint32_t*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(uint32_t), set.triangles.size()));
        for (size_t i = 0; i < set.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = set.triangles[i][k];
        attach(sc, g, unsigned(ShapeKind::Polygon));
        return true;
    }

    // A mesh's own float arrays as Embree's buffers: the mesh is not copied.
    bool addMesh(RTCScene sc, const MeshData& m) {
        if (m.triangleCount() == 0) return false;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                   m.positions.data(), 0, 3 * sizeof(float), m.vertexCount());
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                   m.triangles.data(), 0, 3 * sizeof(uint32_t), m.triangleCount());
        attach(sc, g, unsigned(ShapeKind::Mesh));
        return true;
    }

    template <class F>
    bool addUser(RTCScene sc, const std::vector<typename F::Shape>& list, ShapeKind kind) {
        if (list.empty()) return false;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        // Embree builds no node over a geometry of one primitive: the root is its leaf,
        // so every ray called the shape's intersector (a lone glass sphere: 9.9 M calls
        // for 9.9 M mkpmap rays, 0.66 M of them hits). A second primitive that is never
        // hit, a small box beside the first (boundsFunc), gives the tree a node whose
        // box test skips the rays that miss the shape's box.
        rtcSetGeometryUserPrimitiveCount(g, unsigned(list.size() == 1 ? 2 : list.size()));
        rtcSetGeometryUserData(g, const_cast<void*>(static_cast<const void*>(&list)));
        rtcSetGeometryBoundsFunction(g, boundsFunc<F>, nullptr);
        rtcSetGeometryIntersectFunction(g, intersectFunc<F>);
        rtcSetGeometryOccludedFunction(g, occludedFunc<F>);
        attach(sc, g, unsigned(kind));
        return true;
    }

    bool addAllUser(RTCScene sc, const ShapeSet& set) {
        bool any = addUser<SphereFamily>(sc, set.spheres, ShapeKind::Sphere);
        any |= addUser<ConeFamily>(sc, set.cones, ShapeKind::Cone);
        any |= addUser<RingFamily>(sc, set.rings, ShapeKind::Ring);
        return any;
    }

    // An object's Embree scene, or null if it has nothing to trace. Meshes are built at
    // medium quality: they are the large ones, and on a 10 M-triangle grid low
    // quality's Morton build reserved more memory (840 against 534 MB) and took longer.
    RTCScene buildObject(const AccelObject& o) {
        const bool mesh = o.mesh != nullptr;
        RTCScene sc = newScene(mesh ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH, mesh);
        bool any =
            mesh ? addMesh(sc, *o.mesh) : addTriangles(sc, *o.shapes) | addAllUser(sc, *o.shapes);
        if (!any) {
            rtcReleaseScene(sc);
            return nullptr;
        }
        rtcCommitScene(sc);
        return sc;
    }

    void addPlacements() {
        for (const AccelObject& o : objects) objectScenes.push_back(buildObject(o));
        for (size_t i = 0; i < placements.size(); ++i) {
            const AccelPlacement& p = placements[i];
            RTCScene inner = objectScenes[p.object];
            if (!inner) continue;
            RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(g, inner);
            rtcSetGeometryTimeStepCount(g, 1);
            float xfm[12];  // 3x4, column-major: the linear part's columns, then the translation
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 3; ++r)
                    xfm[3 * c + r] = float(p.xf.forward.m[size_t(r)][size_t(c)]);
            rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
            attach(scene, g, kFirstPlacement + unsigned(i));
        }
    }

    // hitUserShape for a direct shape (the scene's own, never inside an instance).
    bool hitDirect(const DirectShape& d, QueryContext& ctx, double tmax, double& t) const {
        const unsigned top = RTC_INVALID_GEOMETRY_ID;
        switch (d.kind) {
            case ShapeKind::Sphere:
                return hitUserShape<SphereFamily>(shapes.spheres[d.index], ctx, top, tmax, t);
            case ShapeKind::Cone:
                return hitUserShape<ConeFamily>(shapes.cones[d.index], ctx, top, tmax, t);
            case ShapeKind::Ring:
                return hitUserShape<RingFamily>(shapes.rings[d.index], ctx, top, tmax, t);
            case ShapeKind::Polygon:
            case ShapeKind::Mesh:
                break;
        }
        return false;
    }
    // Nearest direct shape closer than `hit` (or than the ray's tmax when !found).
    bool nearestDirect(QueryContext& ctx, bool found, AccelHit& hit) const {
        double tmax = found ? hit.t : ctx.tmax;
        for (const DirectShape& d : direct) {
            double t;
            if (!hitDirect(d, ctx, tmax, t)) continue;
            hit = {d.kind, d.index, 0, -1, t};
            tmax = t;
            found = true;
        }
        return found;
    }

    void attach(RTCScene sc, RTCGeometry g, unsigned id) {
        if (sc == scene) embreeEmpty = false;
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(sc, g, id);
        rtcReleaseGeometry(g);  // the scene holds the reference now
    }

    void initContext(QueryContext& ctx, const Ray& ray, const ModifierSet* skip) const {
        rtcInitIntersectContext(&ctx.rtc);
        ctx.shapes = &shapes;
        ctx.objects = &objects;
        ctx.placements = &placements;
        ctx.org = ray.origin;
        ctx.dir = ray.dir;
        ctx.tmax = ray.tmax;
        ctx.skip = skip && !skip->empty() ? skip : nullptr;
        ctx.checkTriangles = false;
        ctx.userT = 0;
        ctx.localInst = RTC_INVALID_GEOMETRY_ID;
        if (ctx.skip) ctx.rtc.filter = contextFilter;
    }
};
namespace {
#if defined(__SSE2__)
// (v.x, v.y, v.z, 0) as floats, rounded as float(double) rounds.
inline __m128 floatsWithZero(const Vec3& v) {
    const __m128 xy = _mm_cvtpd_ps(_mm_loadu_pd(&v.x));
    const __m128 z0 = _mm_cvtpd_ps(_mm_load_sd(&v.z));  // upper lane zeroed by the load
    return _mm_movelh_ps(xy, z0);
}
#endif

void setRay(RTCRay& r, const Ray& ray) {
#if defined(__SSE2__)
    // Origin with tnear = 0 and direction with time = 0 as two 16-byte stores: Embree
    // starts by loading each as one vector, and a vector load of four separate float
    // stores cannot be forwarded from the store buffer (a stall on every ray).
    static_assert(offsetof(RTCRay, tnear) == 12 && offsetof(RTCRay, dir_x) == 16 &&
                  offsetof(RTCRay, time) == 28);
    _mm_storeu_ps(&r.org_x, floatsWithZero(ray.origin));
    _mm_storeu_ps(&r.dir_x, floatsWithZero(ray.dir));
#else
    r.org_x = float(ray.origin.x);
    r.org_y = float(ray.origin.y);
    r.org_z = float(ray.origin.z);
    r.dir_x = float(ray.dir.x);
    r.dir_y = float(ray.dir.y);
    r.dir_z = float(ray.dir.z);
    r.tnear = 0.0f;
    r.time = 0.0f;
#endif
    r.tfar = ray.tmax < double(std::numeric_limits<float>::max()) ? float(ray.tmax) : HUGE_VALF;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
}
// The nearest hit among Embree's geometry, triangles re-evaluated in double.
bool intersectEmbree(RTCScene scene, QueryContext& ctx, const Ray& ray, AccelHit& hit) {
    for (int attempt = 0; attempt < 2; ++attempt) {
        alignas(16) RTCRayHit rh;
        setRay(rh.ray, ray);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx.rtc, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        const auto kind = ShapeKind(rh.hit.geomID);
        const unsigned inst = rh.hit.instID[0];
        const int32_t placement =
            inst == RTC_INVALID_GEOMETRY_ID ? -1 : int32_t(inst - kFirstPlacement);
        const uint32_t prim = rh.hit.primID;
        double t;
        if (kind == ShapeKind::Polygon) {
            uint32_t polygon;
            if (validPolygonHit(ctx, inst, prim, polygon, t)) {
                hit = {kind, polygon, prim, placement, t};
                return true;
            }
        } else if (kind == ShapeKind::Mesh) {
            if (validMeshHit(ctx, inst, prim, t)) {
                hit = {kind, prim, prim, placement, t};
                return true;
            }
        } else {
            hit = {kind, prim, 0, placement, ctx.userT};
            return true;
        }
        // The float test found a triangle that the exact plane disowns: trace again with
        // every triangle candidate checked in double.
        ctx.checkTriangles = true;
        ctx.rtc.filter = contextFilter;
    }
    return false;  // unreachable in practice: the filtered pass only returns valid hits
}

}  // namespace

EmbreeAccel::EmbreeAccel(const ShapeSet& shapes, std::vector<AccelObject> objects,
                         std::vector<AccelPlacement> placements)
    : impl_(std::make_unique<Impl>(shapes, std::move(objects), std::move(placements))) {
    Impl& m = *impl_;
    m.device = rtcNewDevice(nullptr);
    if (!m.device)
        throw std::runtime_error("embree: cannot create device (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(m.device, errorCallback, nullptr);
    m.scene = m.newScene(RTC_BUILD_QUALITY_HIGH, false);
    m.addTriangles(m.scene, shapes);
    if (shapes.spheres.size() + shapes.cones.size() + shapes.rings.size() <= kDirectShapes) {
        for (uint32_t i = 0; i < shapes.spheres.size(); ++i)
            m.direct.push_back({ShapeKind::Sphere, i});
        for (uint32_t i = 0; i < shapes.cones.size(); ++i) m.direct.push_back({ShapeKind::Cone, i});
        for (uint32_t i = 0; i < shapes.rings.size(); ++i) m.direct.push_back({ShapeKind::Ring, i});
    } else {
        m.addAllUser(m.scene, shapes);
    }
    m.addPlacements();
    rtcCommitScene(m.scene);
}

EmbreeAccel::~EmbreeAccel() = default;

size_t EmbreeAccel::triangleCount() const { return impl_->shapes.triangles.size(); }

namespace {
// Embree handles coordinates up to about 1.8e18 (its FLT_LARGE) and aborts on larger ones;
// a ray that starts farther out than any scene can reach is a miss, as a ray outside
// RADIANCE's octree cube is (raytrace.c localhit).
constexpr double kLargestCoordinate = 1e18;
// (NaN fails every comparison: such a ray is not traced either.)
inline bool traceable(const Ray& ray) {
    auto ok = [](const Vec3& v) {
        return std::fabs(v.x) <= kLargestCoordinate && std::fabs(v.y) <= kLargestCoordinate &&
               std::fabs(v.z) <= kLargestCoordinate;
    };
    return ok(ray.origin) && ok(ray.dir);
}
}  // namespace

bool EmbreeAccel::intersect(const Ray& ray, const ModifierSet* skip, AccelHit& hit) const {
    const Impl& m = *impl_;
    if (!traceable(ray)) return false;
    QueryContext ctx;
    m.initContext(ctx, ray, skip);
    const bool found = !m.embreeEmpty && intersectEmbree(m.scene, ctx, ray, hit);
    return m.direct.empty() ? found : m.nearestDirect(ctx, found, hit);
}

bool EmbreeAccel::occluded(const Ray& ray, const ModifierSet* skip) const {
    const Impl& m = *impl_;
    if (!traceable(ray)) return false;
    QueryContext ctx;
    m.initContext(ctx, ray, skip);
    // Embree first: most shadow rays that are blocked at all are blocked by triangles,
    // and then the direct shapes need no test.
    if (!m.embreeEmpty) {
        alignas(16) RTCRay r;
        setRay(r, ray);
        rtcOccluded1(m.scene, &ctx.rtc, &r);
        if (r.tfar < 0) return true;
    }
    for (const DirectShape& d : m.direct) {
        double t;
        if (m.hitDirect(d, ctx, ray.tmax, t)) return true;
    }
    return false;
}

}  // namespace rp
