// Ray throughput of SceneGeometry on generated scenes of about 1 M triangles.
//
// "room" scene (the headline figure): a closed 20 x 20 x 5 m room (6 polygons) holding
// 1,000 tessellated spheres of 1,024 triangles each (16 x 32 quads as polygons, radius
// 0.15..0.45 m) on a jittered grid: 1,024,006 triangles, like furniture-heavy interiors.
// "cornell": ../shared/validation/cornell/scene.rad (26 triangles, 1 sphere), rays from
// random points inside the box.
// "soup" scene (a stress case): 100,000 small random 12-sided polygons (radius 0.05..0.15 m, random
// position and orientation) in a 20 m box; half are regular (convex: fanned into 10 triangles),
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

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "geometry/scene_geometry.h"
#include "scene/scene_load.h"

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

void addQuad(Scene& s, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    Primitive p;
    p.type = PrimType::Polygon;
    p.name = "q" + std::to_string(s.prims.size());
    p.modifierName = "void";
    for (const Vec3& v : {a, b, c, d}) p.rargs.insert(p.rargs.end(), {v.x, v.y, v.z});
    s.prims.push_back(std::move(p));
}

constexpr double kRoomX = 20, kRoomY = 20, kRoomZ = 5;

Scene makeRoomScene() {
    Scene s;
    const Vec3 o{0, 0, 0}, X{kRoomX, 0, 0}, Y{0, kRoomY, 0}, Z{0, 0, kRoomZ};
    addQuad(s, o, Y, X + Y, X);              // floor, facing up
    addQuad(s, Z, Z + X, Z + X + Y, Z + Y);  // ceiling
    addQuad(s, o, X, X + Z, Z);              // walls
    addQuad(s, Y, Y + Z, X + Y + Z, X + Y);
    addQuad(s, o, Z, Y + Z, Y);
    addQuad(s, X, X + Y, X + Y + Z, X + Z);
    std::mt19937_64 rng(4242);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3), rad(0.15, 0.45);
    constexpr int kNu = 32, kNv = 16;
    for (int gx = 0; gx < 40; ++gx)
        for (int gy = 0; gy < 25; ++gy) {
            Vec3 c{0.5 * (gx + 0.5) + jitter(rng) * 0.2, 0.8 * (gy + 0.5) + jitter(rng),
                   1.0 + 3.0 * std::fabs(jitter(rng))};
            double r = std::min(rad(rng), 0.24);
            auto at = [&](int iu, int iv) {
                double ph = 2 * kPi * iu / kNu, th = kPi * iv / kNv;
                return c + Vec3{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                std::cos(th)} *
                               r;
            };
            for (int iv = 0; iv < kNv; ++iv)
                for (int iu = 0; iu < kNu; ++iu)
                    addQuad(s, at(iu, iv), at(iu, iv + 1), at(iu + 1, iv + 1), at(iu + 1, iv));
        }
    return s;
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

Fixture makeFixture(const Scene& s, const Vec3& lo, const Vec3& hi) {
    Fixture x;
    x.geometry = std::make_unique<SceneGeometry>(s);
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> u(0, 1);
    x.rays.resize(kBatch);
    for (Ray& r : x.rays) {
        Vec3 o{lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y),
               lo.z + u(rng) * (hi.z - lo.z)};
        r = {o, randomDir(rng)};
    }
    return x;
}

// range(1): 0 = room scene, 1 = soup scene, 2 = ../shared/validation/cornell.
Fixture& fixture(int which) {
    if (which == 2) {
        static Fixture cornell =
            makeFixture(loadScene({RP_SHARED_DIR "/validation/cornell/scene.rad"}),
                        {0.01, 0.01, 0.01}, {5.49, 5.49, 5.49});
        return cornell;
    }
    if (which == 0) {
        static Fixture room = makeFixture(makeRoomScene(), {0.01, 0.01, 0.01},
                                          {kRoomX - 0.01, kRoomY - 0.01, kRoomZ - 0.01});
        return room;
    }
    static Fixture soup = makeFixture(makeScene(), {0, 0, 0}, {kBox, kBox, kBox});
    return soup;
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
    Fixture& f = fixture(int(state.range(1)));
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
    state.counters["rays/s"] =
        benchmark::Counter(double(kBatch) * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / kBatch;
    state.counters["threads_used"] = parallel ? tbb::info::default_concurrency() : 1;
}

void BM_Occluded(benchmark::State& state) {
    Fixture& f = fixture(int(state.range(1)));
    bool parallel = state.range(0) != 0;
    std::vector<char> occ(kBatch);
    for (auto _ : state) {
        auto one = [&](int i) {
            occ[i] = f.geometry->occluded(f.rays[i].origin, f.rays[i].dir, 10);
        };
        if (parallel)
            tbb::parallel_for(0, kBatch, one);
        else
            for (int i = 0; i < kBatch; ++i) one(i);
        benchmark::DoNotOptimize(occ.data());
    }
    long n = 0;
    for (char c : occ) n += c;
    state.counters["rays/s"] =
        benchmark::Counter(double(kBatch) * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["occluded_fraction"] = double(n) / kBatch;
    state.counters["threads_used"] = parallel ? tbb::info::default_concurrency() : 1;
}

}  // namespace

BENCHMARK(BM_Build)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
// Args: {threads_all, scene} with scene 0 = room, 1 = soup, 2 = cornell.
BENCHMARK(BM_ClosestHit)
    ->ArgNames({"threads_all", "scene"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Occluded)
    ->ArgNames({"threads_all", "scene"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
