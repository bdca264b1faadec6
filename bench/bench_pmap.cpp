// Photon map speed: kd-tree build of 1 M photons (1 thread and all threads), k-NN lookups
// per second for k = 50 and 500 through each photon store (in core, incore_store.h; out of
// core with a 100k-photon cache, ooc_store.h) on photons on the surfaces of a room-like
// box and uniform in a box, bias-compensated lookups (50..500), the in-core store's build,
// file save and load, opening a map for searching, and bytes per photon.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <random>

#include "pmap/density.h"
#include "pmap/incore_store.h"
#include "pmap/photon_map.h"

namespace {

using namespace rp;
using namespace rp::pmap;

constexpr size_t kMillion = 1000000;

// A point on one of the six inner faces of a 6 x 4 x 3 m room, chosen in proportion to
// area, with the inward normal.
struct SurfacePoint {
    Vec3 pos, normal;
};
SurfacePoint roomPoint(std::mt19937_64& rng) {
    const double sx = 6, sy = 4, sz = 3;
    const double areas[3] = {sx * sy, sx * sz, sy * sz};  // floor/ceiling, y walls, x walls
    std::uniform_real_distribution<double> u(0, 1);
    double a = u(rng) * 2 * (areas[0] + areas[1] + areas[2]);
    const bool high = u(rng) < 0.5;
    double s = u(rng), t = u(rng);
    if (a < 2 * areas[0]) return {Vec3(s * sx, t * sy, high ? sz : 0), Vec3(0, 0, high ? -1 : 1)};
    if (a < 2 * (areas[0] + areas[1]))
        return {Vec3(s * sx, high ? sy : 0, t * sz), Vec3(0, high ? -1 : 1, 0)};
    return {Vec3(high ? sx : 0, s * sy, t * sz), Vec3(high ? -1 : 1, 0, 0)};
}

std::vector<Photon> roomPhotons(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    std::vector<Photon> v;
    v.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        SurfacePoint p = roomPoint(rng);
        v.push_back(makePhoton(p.pos, p.normal, {u(rng) * 1e-6, u(rng) * 1e-6, u(rng) * 1e-6}));
    }
    return v;
}

const PhotonMap& roomMap() {
    static const PhotonMap map(PhotonMapType::Global, roomPhotons(kMillion, 1));
    return map;
}

void BM_BuildKdTree1M(benchmark::State& state) {
    const int threads = static_cast<int>(state.range(0));
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<size_t>(threads));
    const auto photons = roomPhotons(kMillion, 2);
    for (auto _ : state) {
        auto tree = buildKdTree(photons, threads > 1);
        benchmark::DoNotOptimize(tree.data());
    }
    state.counters["threads"] = threads;
    state.counters["photons/s"] =
        benchmark::Counter(double(kMillion) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BuildKdTree1M)
    ->Arg(1)
    ->Arg(static_cast<int>(tbb::info::default_concurrency()))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Stats + tree, as mkpmap does after photon distribution (all threads).
void BM_BuildPhotonMap1M(benchmark::State& state) {
    const auto photons = roomPhotons(kMillion, 2);
    for (auto _ : state) {
        PhotonMap map(PhotonMapType::Global, photons);
        benchmark::DoNotOptimize(map.photons().data());
    }
}
BENCHMARK(BM_BuildPhotonMap1M)->Unit(benchmark::kMillisecond)->UseRealTime();

// Photons uniform in the room's volume (as volume photons would be), normals random.
std::vector<Photon> boxPhotons(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1), f(0.5, 1.5);
    std::vector<Photon> v;
    v.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        Vec3 p(6 * u(rng), 4 * u(rng), 3 * u(rng));
        Vec3 nrm = normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        v.push_back(makePhoton(p, nrm, {f(rng) * 1e-6, f(rng) * 1e-6, f(rng) * 1e-6}));
    }
    return v;
}

const PhotonMap& boxMap() {
    static const PhotonMap map(PhotonMapType::Volume, boxPhotons(kMillion, 3));
    return map;
}

std::string tempMapPath(const char* name) {
    return (std::filesystem::temp_directory_path() /
            ("bench_pmap_" + std::to_string(::getpid()) + name))
        .string();
}

// The map opened for searching, in core or out of core (100k photons resident and cached
// per thread, pages of 4 x 50), as a renderer opens it; made on first use.
const PhotonMap& searchable(bool box, bool outOfCore) {
    static std::once_flag once[2][2];
    static PhotonMap maps[2][2];
    std::call_once(once[box][outOfCore], [&] {
        const std::string path = tempMapPath(box ? "_box.pm" : "_room.pm");
        (box ? boxMap() : roomMap()).save(path, "bench_pmap", true);
        StoreOptions o;
        if (outOfCore) o.cachePhotons = 100000;
        maps[box][outOfCore] = PhotonMap::open(path, o);
        std::filesystem::remove(path);  // the out-of-core store keeps it open
    });
    return maps[box][outOfCore];
}

// Query points: on the room's surfaces with their normals (room map), or uniform in the
// box without a normal filter (box map, as volume lookups).
std::vector<SurfacePoint> queryPoints(bool box, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<SurfacePoint> q;
    for (int i = 0; i < 4096; ++i)
        q.push_back(box ? SurfacePoint{Vec3(6 * u(rng), 4 * u(rng), 3 * u(rng)), Vec3()}
                        : roomPoint(rng));
    return q;
}

// One lookup per iteration (k+1 nearest, adaptive radius) through PhotonLookup; each
// benchmark thread has its own. Args: k, map (0 room surfaces, 1 uniform box), store
// (0 in core, 1 out of core).
void BM_Lookup1M(benchmark::State& state) {
    const int k = static_cast<int>(state.range(0));
    const bool box = state.range(1) != 0, outOfCore = state.range(2) != 0;
    const PhotonMap& map = searchable(box, outOfCore);
    PhotonLookup lookup(map, LookupParams{k, 0, 0.5});
    const auto queries = queryPoints(box, 100 + state.thread_index());
    size_t i = 0, found = 0;
    for (auto _ : state) {
        const SurfacePoint& q = queries[i++ & 4095];
        found += lookup.findPhotons(q.pos, box ? nullptr : &q.normal).size();
    }
    state.SetLabel(std::string(box ? "box " : "room ") + map.store().describe());
    state.counters["lookups/s"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["found"] = double(found) / double(state.iterations());
    state.counters["short"] = double(lookup.shortLookups());
}
BENCHMARK(BM_Lookup1M)->ArgsProduct({{50, 500}, {0, 1}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Lookup1M)
    ->ArgsProduct({{50, 500}, {0}, {0, 1}})
    ->Unit(benchmark::kMicrosecond)
    ->Threads(2)
    ->UseRealTime();

// Full density estimate (lookup + flux sum) for comparison with the bare lookup.
void BM_SurfaceDensity1M(benchmark::State& state) {
    const PhotonMap& map = searchable(false, state.range(1) != 0);
    PhotonLookup lookup(map, LookupParams{static_cast<int>(state.range(0)), 0, 0.5});
    const auto queries = queryPoints(false, 7);
    size_t i = 0;
    for (auto _ : state) {
        const SurfacePoint& q = queries[i++ & 4095];
        benchmark::DoNotOptimize(lookup.surfaceDensity(q.pos, q.normal));
    }
    state.SetLabel(map.store().describe());
    state.counters["lookups/s"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SurfaceDensity1M)->ArgsProduct({{50, 500}, {0, 1}})->Unit(benchmark::kMicrosecond);

// Bias-compensated estimate, bandwidth 50..500, on the room map.
void BM_BiasCompDensity1M(benchmark::State& state) {
    const PhotonMap& map = searchable(false, state.range(0) != 0);
    PhotonLookup lookup(map, LookupParams{500, 0, 0.5});
    const auto queries = queryPoints(false, 9);
    BiasCompStats stats;
    size_t i = 0;
    for (auto _ : state) {
        const SurfacePoint& q = queries[i++ & 4095];
        benchmark::DoNotOptimize(lookup.biasCompensatedDensity(q.pos, q.normal, 50, 500, &stats));
    }
    state.SetLabel(stats.report("global") + " " + map.store().describe());
    state.counters["lookups/s"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BiasCompDensity1M)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// In-core store build over 1 M photons (all threads) and its size.
void BM_BuildStore1M(benchmark::State& state) {
    const PhotonMap& map = roomMap();
    size_t bytes = 0;
    for (auto _ : state) {
        InCoreStore store = InCoreStore::copyOf(map.photons(), {}, true);
        bytes = store.memoryBytes();
        benchmark::DoNotOptimize(&store);
    }
    state.counters["store bytes/photon"] = double(bytes) / double(map.size());
    state.counters["photons/s"] =
        benchmark::Counter(double(kMillion) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BuildStore1M)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SaveLoad1M(benchmark::State& state) {
    const PhotonMap& map = roomMap();
    const std::string path = tempMapPath(".pm");
    const bool load = state.range(0) != 0;
    if (load) map.save(path, "bench_pmap", true);
    for (auto _ : state) {
        if (load) {
            PhotonMap m = PhotonMap::load(path);
            benchmark::DoNotOptimize(m.photons().data());
        } else {
            map.save(path, "bench_pmap", true);
        }
    }
    const double fileBytes = double(std::filesystem::file_size(path));
    std::filesystem::remove(path);
    state.SetLabel(load ? "load" : "save");
    state.counters["bytes/photon on disk"] = fileBytes / double(map.size());
    state.counters["bytes/photon in memory"] = double(sizeof(Photon));
    state.counters["MB/s"] =
        benchmark::Counter(fileBytes * state.iterations() / 1e6, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SaveLoad1M)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// What a renderer does before its first lookup: open the map for searching in core (read
// and check the file, build the store).
void BM_OpenInCore1M(benchmark::State& state) {
    const std::string path = tempMapPath(".pm");
    roomMap().save(path, "bench_pmap", true);
    size_t bytes = 0;
    for (auto _ : state) {
        PhotonMap m = PhotonMap::open(path, StoreOptions{});
        bytes = m.store().memoryBytes();
        benchmark::DoNotOptimize(&m);
    }
    std::filesystem::remove(path);
    state.counters["store bytes/photon"] = double(bytes) / double(kMillion);
    state.counters["photons/s"] =
        benchmark::Counter(double(kMillion) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_OpenInCore1M)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
