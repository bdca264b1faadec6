// Speed of the .cal evaluator: the gensky sky function (lib/skybright.cal, CIE clear sky
// with the daylight scene's arguments) at varying directions, one thread. Each
// iteration is one ray: setRay (clears cached variables) plus one skybr evaluation.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "calc/program.h"
#include "calc/search_path.h"

namespace {

using namespace rp;
using namespace rp::calc;

// The project's lib/ folder, found from this source file's path (RAYPATH overrides).
std::string libDir() {
    std::string here = __FILE__;
    return here.substr(0, here.rfind("/bench/")) + "/lib";
}

std::vector<Vec3> directions(int n) {
    std::vector<Vec3> dirs;
    for (int i = 0; i < n; ++i) {  // spiral over the sphere, both hemispheres
        double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
        dirs.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return dirs;
}

void runSky(benchmark::State& state, std::vector<double> args) {
    Builder b(defaultSearchPath(libDir()));
    b.loadFile("rayinit.cal");
    b.loadFile("skybright.cal");
    auto prog = b.build();
    auto skybr = prog->variable("skybr");
    if (!skybr) {
        state.SkipWithError("skybr not found");
        return;
    }
    Evaluator ev(prog);
    auto dirs = directions(4096);
    RayContext ray;
    ray.args = args;
    std::size_t i = 0;
    double sum = 0;
    for (auto _ : state) {
        ray.D = dirs[i++ & 4095];
        ev.setRay(ray);
        sum += ev.eval(*skybr);
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations());
}

void BM_SkybrightClear(benchmark::State& state) {
    runSky(state, {1, 8.79, 20.0, 0.526, 0.153855, -0.727432, 0.668708});
}
void BM_SkybrightIntermediate(benchmark::State& state) {
    runSky(state, {4, 8.79, 20.0, 0.9, 0.153855, -0.727432, 0.668708});
}

BENCHMARK(BM_SkybrightClear);
BENCHMARK(BM_SkybrightIntermediate);

}  // namespace

BENCHMARK_MAIN();
