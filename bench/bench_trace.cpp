// Ray throughput of SceneGeometry on a generated scene of about 1 M triangles.
//
// Scene: 100,000 small random 12-sided polygons (radius 0.05..0.15 m, random position
// and orientation) in a 20 m box; half are regular (convex: fanned into 10 triangles),
// half are 6-pointed stars (concave: ear-clipped into 10 triangles): 1,000,000 triangles.
// (A 50 m box of 0.25..0.75 m polygons gave the same rays/s within noise.)
// Rays: incoherent, origins uniform in the box, directions uniform on the sphere, fixed
// seed. Closest-hit includes the double-precision refinement and the hit completion
// (point, normal, u/v, offset); occlusion uses tmax = 10 m.
// Counters: rays/s (kIsRate). "threads:all" runs a TBB parallel_for over the batch.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "geometry/scene_geometry.h"

namespace {

using namespace rp;

constexpr int kPolygons = 100000;
constexpr int kSides = 12;
constexpr double kBox = 20;
constexpr int kBatch = 1 << 16;

Vec3 randomDir(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    for (;;) {
        Vec3 d{u(rng), u(rng), u(rng)};
        double l = lengthSquared(d);
        if (l > 1e-6 && l <= 1) return d / std::sqrt(l);
    }
}

Scene makeScene() {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> pos(0, kBox), rad(0.05, 0.15);
    Scene s;
    s.prims.reserve(kPolygons);
    for (int i = 0; i < kPolygons; ++i) {
        Primitive p;
        p.type = PrimType::Polygon;
        p.name = "p" + std::to_string(i);
        p.modifierName = "void";
        Vec3 c{pos(rng), pos(rng), pos(rng)};
        Vec3 n = randomDir(rng);
        Vec3 e1 = normalize(cross(n, std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
        Vec3 e2 = cross(n, e1);
        double r = rad(rng);
        bool star = i % 2;
        for (int k = 0; k < kSides; ++k) {
            double a = 2 * kPi * k / kSides;
            double rk = star && k % 2 ? 0.5 * r : r;
            Vec3 v = c + e1 * (rk * std::cos(a)) + e2 * (rk * std::sin(a));
            p.rargs.insert(p.rargs.end(), {v.x, v.y, v.z});
        }
        s.prims.push_back(std::move(p));
    }
    return s;
}

struct Fixture {
    std::unique_ptr<SceneGeometry> geometry;
    std::vector<Ray> rays;
};

Fixture& fixture() {
    static Fixture f = [] {
        Fixture x;
        Scene s = makeScene();
        x.geometry = std::make_unique<SceneGeometry>(s);
        std::mt19937_64 rng(777);
        std::uniform_real_distribution<double> pos(0, kBox);
        x.rays.resize(kBatch);
        for (Ray& r : x.rays) r = {{pos(rng), pos(rng), pos(rng)}, randomDir(rng)};
        return x;
    }();
    return f;
}

void BM_Build(benchmark::State& state) {
    Scene s = makeScene();
    for (auto _ : state) {
        SceneGeometry g(s);
        benchmark::DoNotOptimize(g.triangleCount());
        state.counters["triangles"] = double(g.triangleCount());
    }
}

void BM_ClosestHit(benchmark::State& state) {
    Fixture& f = fixture();
    bool parallel = state.range(0) != 0;
    std::vector<double> t(kBatch);
    for (auto _ : state) {
        auto one = [&](int i) {
            auto h = f.geometry->closestHit(f.rays[i]);
            t[i] = h ? h->t : -1;
        };
        if (parallel)
            tbb::parallel_for(0, kBatch, one);
        else
            for (int i = 0; i < kBatch; ++i) one(i);
        benchmark::DoNotOptimize(t.data());
    }
    long hits = 0;
    for (double x : t) hits += x >= 0;
    state.counters["rays/s"] = benchmark::Counter(double(kBatch) * state.iterations(),
                                                  benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / kBatch;
    state.counters["threads_used"] = parallel ? tbb::info::default_concurrency() : 1;
}

void BM_Occluded(benchmark::State& state) {
    Fixture& f = fixture();
    bool parallel = state.range(0) != 0;
    std::vector<char> occ(kBatch);
    for (auto _ : state) {
        auto one = [&](int i) { occ[i] = f.geometry->occluded(f.rays[i].origin, f.rays[i].dir, 10); };
        if (parallel)
            tbb::parallel_for(0, kBatch, one);
        else
            for (int i = 0; i < kBatch; ++i) one(i);
        benchmark::DoNotOptimize(occ.data());
    }
    long n = 0;
    for (char c : occ) n += c;
    state.counters["rays/s"] = benchmark::Counter(double(kBatch) * state.iterations(),
                                                  benchmark::Counter::kIsRate);
    state.counters["occluded_fraction"] = double(n) / kBatch;
    state.counters["threads_used"] = parallel ? tbb::info::default_concurrency() : 1;
}

}  // namespace

BENCHMARK(BM_Build)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_ClosestHit)->ArgName("threads_all")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Occluded)->ArgName("threads_all")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
