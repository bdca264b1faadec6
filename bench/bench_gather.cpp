// The final gather's ceiling (issue 49): Embree's own ray rate on the rays of a final
// gather, against our tracing of the same rays. The rays: the hemisphere that
// `rtrace -I -ab 1 -ad 1024 -as 0 -aa 0` sends from each of the 400 work-plane sensors of
// bench/speed_vs_radiance.sh (render::sampleHemisphere's own divisions and directions,
// recorded instead of traced; fixed seed), in the scene of the octree named by RP_GATHER_OCTREE
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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

#include "geometry/scene_geometry.h"
#include "render/ambient_hemisphere.h"
#include "scene/scene_load.h"
#include "util/rng.h"

namespace {

using namespace rp;

struct Gather {
    std::unique_ptr<SceneGeometry> geometry;
    std::vector<Ray> rays;
    std::vector<size_t> sensorStart;  // each sensor's first ray, then rays.size()
    RTCDevice device = nullptr;
    RTCScene own = nullptr;  // the triangles alone, as Embree takes them by default
};

// The hemisphere's rays as sampleHemisphere shoots them, not traced.
class RecordingTracer final : public render::HemisphereTracer {
public:
    explicit RecordingTracer(std::vector<Ray>& rays) : rays_(rays) {}
    Sample trace(const Vec3& origin, const Vec3& dir, int, double, double) override {
        rays_.push_back({origin, dir});
        return {};
    }

private:
    std::vector<Ray>& rays_;
};

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

    // The sensors of speed_vs_radiance.sh, just above the work plane (z = 0.8); rtrace
    // -I's hemisphere of -ad 1024 (render/ambient.cpp: no cache, weight 1, no -as).
    render::HemisphereParams params = render::hemisphereDivisions(1024, 0, 1, 1);
    params.gradients = false;
    RecordingTracer record(g->rays);
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            g->sensorStart.push_back(g->rays.size());
            Rng rng(49, RngDomain::Test, uint64_t(20 * i + j));
            render::sampleHemisphere(Vec3(0.15 + i * 0.2975, 0.1 + j * 0.19, 0.8001), Vec3(0, 0, 1),
                                     params, record, rng);
        }
    g->sensorStart.push_back(g->rays.size());
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
            // One packet per 16 rays of a sensor's hemisphere (a shared origin), the
            // last one partly filled.
            alignas(64) RTCRayHit16 p;
            alignas(64) int valid[16];
            for (size_t s = 0; s + 1 < g->sensorStart.size(); ++s)
                for (size_t b = g->sensorStart[s]; b < g->sensorStart[s + 1]; b += 16) {
                    const size_t n = std::min<size_t>(16, g->sensorStart[s + 1] - b);
                    for (size_t l = 0; l < 16; ++l) {
                        const Ray& r = g->rays[b + std::min(l, n - 1)];
                        valid[l] = l < n ? -1 : 0;
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
                    for (size_t l = 0; l < n; ++l)
                        hits += p.hit.geomID[l] != RTC_INVALID_GEOMETRY_ID;
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
