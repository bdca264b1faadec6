// The final gather's ceiling (issue 49): Embree's own ray rate on the rays of a final
// gather, against our tracing of the same rays. The rays: the hemisphere that
// `rtrace -I -ab 1 -ad 1024 -as 0 -aa 0` sends from each of the 400 work-plane sensors of
// bench/speed_vs_radiance.sh (18 x 57 stratified cosine-weighted divisions, one jittered
// ray each, fixed seed), in the scene of the octree named by RP_GATHER_OCTREE
// (bench/gather_ceiling.sh makes examples/daylit_office's; skipped without it).
//   EmbreeOwn/1   rtcIntersect1 over the scene's triangles in float, default context:
//                 what Embree alone does with these rays (the ceiling).
//   EmbreeOwn/16  rtcIntersect16, one packet per 16 rays of a hemisphere (a shared origin).
//   Ours          SceneGeometry::closestHit: the same Embree scene with our context filter,
//                 the double-precision refinement and the hit record (point, normals,
//                 modifier, offset), as the renderer traces every ray.
// gather_ceiling.sh sets these beside the gather rate of rtrace itself.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>
#include <vector>

#include "geometry/scene_geometry.h"
#include "render/ambient_hemisphere.h"
#include "scene/scene_load.h"

namespace {

using namespace rp;

struct Gather {
    std::unique_ptr<SceneGeometry> geometry;
    std::vector<Ray> rays;  // 16-ray runs share an origin (kRaysPerSensor is a multiple)
    RTCDevice device = nullptr;
    RTCScene own = nullptr;  // the triangles alone, as Embree takes them by default
};

constexpr int kTheta = 18, kPhi = 57;  // hemisphereDivisions(1024, 0, 1, 1)
constexpr int kRaysPerSensor = 1040;   // 1026 rounded up to 16: a few rays twice

Gather* makeGather() {
    const char* path = std::getenv("RP_GATHER_OCTREE");
    if (!path) return nullptr;
    auto* g = new Gather;
    const Scene scene = loadScene({path});
    g->geometry = std::make_unique<SceneGeometry>(scene);
    const ShapeSet& shapes = g->geometry->shapes();
    g->device = rtcNewDevice(nullptr);
    g->own = rtcNewScene(g->device);
    rtcSetSceneBuildQuality(g->own, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry tri = rtcNewGeometry(g->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(tri, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          shapes.vertices.size()));
    for (size_t i = 0; i < shapes.vertices.size(); ++i) {
        v[3 * i] = float(shapes.vertices[i].x);
        v[3 * i + 1] = float(shapes.vertices[i].y);
        v[3 * i + 2] = float(shapes.vertices[i].z);
    }
    auto* idx = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(tri, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), shapes.triangles.size()));
    for (size_t i = 0; i < shapes.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) idx[3 * i + k] = shapes.triangles[i][k];
    rtcCommitGeometry(tri);
    rtcAttachGeometry(g->own, tri);
    rtcReleaseGeometry(tri);
    rtcCommitScene(g->own);

    // The sensors of speed_vs_radiance.sh, just above the work plane (z = 0.8).
    std::mt19937_64 rng(49);
    std::uniform_real_distribution<double> u(0, 1);
    const Vec3 n(0, 0, 1);
    Vec3 ux, uy;
    render::tangentFrame(n, ux, uy);
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            const Vec3 o(0.15 + i * 0.2975, 0.1 + j * 0.19, 0.8001);
            for (int r = 0; r < kRaysPerSensor; ++r) {
                const int div = r % (kTheta * kPhi);
                const double sin2 = (div / kPhi + u(rng)) / kTheta;
                const double phi = 2 * kPi * (div % kPhi + u(rng)) / kPhi;
                const double s = std::sqrt(sin2), c = std::sqrt(std::max(0.0, 1 - sin2));
                g->rays.push_back(
                    {o, normalize(ux * (std::cos(phi) * s) + uy * (std::sin(phi) * s) + n * c)});
            }
        }
    return g;
}

Gather* gather() {
    static Gather* g = makeGather();
    return g;
}

void setCounters(benchmark::State& state, size_t rays, size_t hits) {
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["hit share"] = double(hits) / double(rays);
}

void BM_EmbreeOwn(benchmark::State& state) {
    Gather* g = gather();
    if (!g) return state.SkipWithError("RP_GATHER_OCTREE not set");
    const int width = static_cast<int>(state.range(0));
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    size_t rays = 0, hits = 0;
    for (auto _ : state) {
        if (width == 1) {
            for (const Ray& r : g->rays) {
                RTCRayHit rh{};
                rh.ray.org_x = float(r.origin.x);
                rh.ray.org_y = float(r.origin.y);
                rh.ray.org_z = float(r.origin.z);
                rh.ray.dir_x = float(r.dir.x);
                rh.ray.dir_y = float(r.dir.y);
                rh.ray.dir_z = float(r.dir.z);
                rh.ray.tfar = HUGE_VALF;
                rh.ray.mask = ~0u;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(g->own, &ctx, &rh);
                hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        } else {
            alignas(64) RTCRayHit16 p;
            alignas(64) int valid[16];
            for (int l = 0; l < 16; ++l) valid[l] = -1;
            for (size_t b = 0; b < g->rays.size(); b += 16) {
                for (int l = 0; l < 16; ++l) {
                    const Ray& r = g->rays[b + l];
                    p.ray.org_x[l] = float(r.origin.x);
                    p.ray.org_y[l] = float(r.origin.y);
                    p.ray.org_z[l] = float(r.origin.z);
                    p.ray.dir_x[l] = float(r.dir.x);
                    p.ray.dir_y[l] = float(r.dir.y);
                    p.ray.dir_z[l] = float(r.dir.z);
                    p.ray.tnear[l] = 0;
                    p.ray.time[l] = 0;
                    p.ray.tfar[l] = HUGE_VALF;
                    p.ray.mask[l] = ~0u;
                    p.ray.id[l] = 0;
                    p.ray.flags[l] = 0;
                    p.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
                }
                rtcIntersect16(valid, g->own, &ctx, &p);
                for (int l = 0; l < 16; ++l) hits += p.hit.geomID[l] != RTC_INVALID_GEOMETRY_ID;
            }
        }
        rays += g->rays.size();
    }
    setCounters(state, rays, hits);
}
BENCHMARK(BM_EmbreeOwn)->Arg(1)->Arg(16)->Unit(benchmark::kMillisecond);

void BM_Ours(benchmark::State& state) {
    Gather* g = gather();
    if (!g) return state.SkipWithError("RP_GATHER_OCTREE not set");
    size_t rays = 0, hits = 0;
    for (auto _ : state) {
        for (const Ray& r : g->rays) hits += g->geometry->closestHit(r).has_value();
        rays += g->rays.size();
    }
    setCounters(state, rays, hits);
}
BENCHMARK(BM_Ours)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
