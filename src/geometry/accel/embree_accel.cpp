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
#include "geometry/accel/embree_accel.h"
#include "util/fast_minmax.h"

#include <embree3/rtcore.h>

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

struct QueryContext {
    RTCIntersectContext rtc;  // first member: Embree hands callbacks &rtc
    const ShapeSet* shapes;
    Vec3 org, dir;
    double tmax;
    const ModifierSet* skip;  // null or non-empty
    bool checkTriangles;      // filter applies the double-precision plane test
    double userT;             // double t of the last user-geometry hit accepted
};

QueryContext* queryContext(RTCIntersectContext* c) { return reinterpret_cast<QueryContext*>(c); }

// t of the ray against the polygon's exact plane; false if the ray lies in the plane.
inline bool planeT(const PolygonShape& p, const Vec3& o, const Vec3& d, double& t) {
    double dn = dot(p.normal, d);
    if (dn == 0) return false;
    t = (p.offset - dot(p.normal, o)) / dn;
    return true;
}

inline bool validPolygonHit(const QueryContext& ctx, uint32_t tri, uint32_t& polygon, double& t) {
    polygon = ctx.shapes->trianglePolygon[tri];
    return planeT(ctx.shapes->polygons[polygon], ctx.org, ctx.dir, t) && t > 0 && t < ctx.tmax;
}

void contextFilter(const RTCFilterFunctionNArguments* args) {
    const QueryContext* ctx = queryContext(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        if (RTCHitN_geomID(args->hit, args->N, i) != unsigned(ShapeKind::Polygon)) continue;
        uint32_t tri = RTCHitN_primID(args->hit, args->N, i);
        uint32_t polygon = ctx->shapes->trianglePolygon[tri];
        if (ctx->skip && ctx->skip->contains(ctx->shapes->polygons[polygon].modifier)) {
            args->valid[i] = 0;
            continue;
        }
        double t;
        if (ctx->checkTriangles && !validPolygonHit(*ctx, tri, polygon, t)) args->valid[i] = 0;
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

// A shape's exact test from the query's double ray (t in (0, tmax)), unless its modifier
// is skipped: for Embree's user-geometry callbacks and the directly tested shapes alike.
template <class F>
bool hitUserShape(const typename F::Shape& s, const QueryContext& ctx, double tmax, double& t) {
    if (ctx.skip && ctx.skip->contains(s.modifier)) return false;
    return F::hit(s, ctx.org, ctx.dir, tmax, t);
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
    if (!hitUserShape<F>(shapes[args->primID], *ctx, fastMin(ctx->tmax, double(rh->ray.tfar)), t))
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
    const QueryContext* ctx = queryContext(args->context);
    RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
    double t;
    if (hitUserShape<F>(shapes[args->primID], *ctx, std::fmin(ctx->tmax, double(ray->tfar)), t))
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
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    bool embreeEmpty = true;  // no geometry attached: queries skip Embree
    std::vector<DirectShape> direct;  // analytic shapes tested outside Embree

    explicit Impl(const ShapeSet& s) : shapes(s) {}
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    void addTriangles() {
        if (shapes.triangles.empty()) return;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), shapes.vertices.size()));
        for (size_t i = 0; i < shapes.vertices.size(); ++i) {
            v[3 * i] = float(shapes.vertices[i].x);
            v[3 * i + 1] = float(shapes.vertices[i].y);
            v[3 * i + 2] = float(shapes.vertices[i].z);
        }
        auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), shapes.triangles.size()));
        for (size_t i = 0; i < shapes.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = shapes.triangles[i][k];
        attach(g, ShapeKind::Polygon);
    }

    template <class F>
    void addUser(const std::vector<typename F::Shape>& list, ShapeKind kind) {
        if (list.empty()) return;
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
        attach(g, kind);
    }

    // hitUserShape for a direct shape.
    bool hitDirect(const DirectShape& d, const QueryContext& ctx, double tmax, double& t) const {
        switch (d.kind) {
        case ShapeKind::Sphere: return hitUserShape<SphereFamily>(shapes.spheres[d.index], ctx, tmax, t);
        case ShapeKind::Cone: return hitUserShape<ConeFamily>(shapes.cones[d.index], ctx, tmax, t);
        case ShapeKind::Ring: return hitUserShape<RingFamily>(shapes.rings[d.index], ctx, tmax, t);
        case ShapeKind::Polygon: break;
        }
        return false;
    }
    // Nearest direct shape closer than `hit` (or than the ray's tmax when !found).
    bool nearestDirect(const QueryContext& ctx, bool found, AccelHit& hit) const {
        double tmax = found ? hit.t : ctx.tmax;
        for (const DirectShape& d : direct) {
            double t;
            if (!hitDirect(d, ctx, tmax, t)) continue;
            hit = {d.kind, d.index, 0, t};
            tmax = t;
            found = true;
        }
        return found;
    }

    void attach(RTCGeometry g, ShapeKind kind) {
        embreeEmpty = false;
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene, g, unsigned(kind));
        rtcReleaseGeometry(g);  // the scene holds the reference now
    }

    void initContext(QueryContext& ctx, const Ray& ray, const ModifierSet* skip) const {
        rtcInitIntersectContext(&ctx.rtc);
        ctx.shapes = &shapes;
        ctx.org = ray.origin;
        ctx.dir = ray.dir;
        ctx.tmax = ray.tmax;
        ctx.skip = skip && !skip->empty() ? skip : nullptr;
        ctx.checkTriangles = false;
        ctx.userT = 0;
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
        auto kind = ShapeKind(rh.hit.geomID);
        if (kind != ShapeKind::Polygon) {
            hit = {kind, rh.hit.primID, 0, ctx.userT};
            return true;
        }
        uint32_t polygon;
        double t;
        if (validPolygonHit(ctx, rh.hit.primID, polygon, t)) {
            hit = {kind, polygon, rh.hit.primID, t};
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

EmbreeAccel::EmbreeAccel(const ShapeSet& shapes) : impl_(std::make_unique<Impl>(shapes)) {
    Impl& m = *impl_;
    m.device = rtcNewDevice(nullptr);
    if (!m.device)
        throw std::runtime_error("embree: cannot create device (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(m.device, errorCallback, nullptr);
    m.scene = rtcNewScene(m.device);
    // Context filters carry the modifier skip set and the double-precision retry.
    rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);
    m.addTriangles();
    if (shapes.spheres.size() + shapes.cones.size() + shapes.rings.size() <= kDirectShapes) {
        for (uint32_t i = 0; i < shapes.spheres.size(); ++i) m.direct.push_back({ShapeKind::Sphere, i});
        for (uint32_t i = 0; i < shapes.cones.size(); ++i) m.direct.push_back({ShapeKind::Cone, i});
        for (uint32_t i = 0; i < shapes.rings.size(); ++i) m.direct.push_back({ShapeKind::Ring, i});
    } else {
        m.addUser<SphereFamily>(shapes.spheres, ShapeKind::Sphere);
        m.addUser<ConeFamily>(shapes.cones, ShapeKind::Cone);
        m.addUser<RingFamily>(shapes.rings, ShapeKind::Ring);
    }
    rtcCommitScene(m.scene);
}

EmbreeAccel::~EmbreeAccel() = default;

size_t EmbreeAccel::triangleCount() const { return impl_->shapes.triangles.size(); }

bool EmbreeAccel::intersect(const Ray& ray, const ModifierSet* skip, AccelHit& hit) const {
    const Impl& m = *impl_;
    QueryContext ctx;
    m.initContext(ctx, ray, skip);
    const bool found = !m.embreeEmpty && intersectEmbree(m.scene, ctx, ray, hit);
    return m.direct.empty() ? found : m.nearestDirect(ctx, found, hit);
}

bool EmbreeAccel::occluded(const Ray& ray, const ModifierSet* skip) const {
    const Impl& m = *impl_;
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
