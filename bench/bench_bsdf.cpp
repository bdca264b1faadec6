// BSDF data lookups and samples per second (the validation blinds, Klems and tensor tree),
// over a fixed set of random direction pairs, after every sampling table is built.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "bsdf/bsdf.h"
#include "util/rng.h"

namespace {

using namespace rp;

struct Fixture {
    std::shared_ptr<const bsdf::BsdfData> sd;
    std::vector<Vec3> in, out;
    explicit Fixture(const char* file) {
        sd = bsdf::loadBsdfFile(std::string(RP_SHARED_DIR) + "/validation/bsdf/" + file);
        Rng rng(1, RngDomain::Test, 0);
        for (int i = 0; i < 4096; ++i) {
            auto dir = [&](double zsign) {
                const double r = std::sqrt(rng.uniform()), a = 2 * kPi * rng.uniform();
                return Vec3{r * std::cos(a), r * std::sin(a), zsign * std::sqrt(1 - r * r)};
            };
            in.push_back(dir(1));
            out.push_back(dir(-1));
        }
    }
};

void lookup(benchmark::State& st, const char* file) {
    Fixture f(file);
    size_t i = 0;
    for (auto _ : st) {
        benchmark::DoNotOptimize(f.sd->evaluate(f.in[i], f.out[i]));
        i = (i + 1) & 4095;
    }
    st.SetItemsProcessed(st.iterations());
}

void sample(benchmark::State& st, const char* file) {
    Fixture f(file);
    const bsdf::Distribution& d = *f.sd->transmission(true)->components.front();
    Vec3 o;
    for (const Vec3& v : f.in) d.sample(v, .5, .5, o);  // build the tables first
    Rng rng(2, RngDomain::Test, 0);
    size_t i = 0;
    for (auto _ : st) {
        benchmark::DoNotOptimize(d.sample(f.in[i], rng.uniform(), rng.uniform(), o));
        i = (i + 1) & 4095;
    }
    st.SetItemsProcessed(st.iterations());
}

BENCHMARK_CAPTURE(lookup, klems, "blinds_klems.xml");
BENCHMARK_CAPTURE(lookup, ttree, "blinds_ttree.xml");
BENCHMARK_CAPTURE(sample, klems, "blinds_klems.xml");
BENCHMARK_CAPTURE(sample, ttree, "blinds_ttree.xml");

}  // namespace

BENCHMARK_MAIN();
