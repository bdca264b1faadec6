// Bias compensation: the bandwidth stays in [bw1, bw2], grows to bw2 where the density is
// uniform, stays small next to a density edge, and the result depends only on the query
// point (not on the order of queries or the number of threads).
#include "pmap/bias_comp.h"

#include <gtest/gtest.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <random>

#include "pmap/density.h"
#include "pmap/photon_map.h"

namespace rp::pmap {
namespace {

// n photons uniform on [0, xMax] x [0, 1] in the plane z = 0, normal +z.
PhotonMap planeMap(size_t n, double xMax, uint32_t seed, std::array<double, 3> flux) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i)
        v.push_back(makePhoton(Vec3(u(rng) * xMax, u(rng), 0), Vec3(0, 0, 1), flux));
    PhotonMap map(PhotonMapType::Global, std::move(v));
    map.makeSearchable();
    return map;
}

const Vec3 kUp(0, 0, 1);

TEST(BiasComp, UniformDensityGrowsToUpperBandwidth) {
    const size_t n = 200000;
    const PhotonMap map = planeMap(n, 1.0, 11, {1e-3, 2e-3, 5e-4});
    PhotonLookup lookup(map, LookupParams{500, 0, 0.5});
    BiasCompStats stats;
    const auto flux = map.photons()[0].fluxRgb();
    double sum = 0;
    int m = 0;
    for (int i = 1; i <= 19; ++i)
        for (int j = 1; j <= 19; ++j) {
            const Vec3 q(0.05 * i, 0.05 * j, 0);
            const auto e = lookup.biasCompensatedDensity(q, kUp, 50, 500, &stats);
            sum += e[1] / (n * flux[1] / kPi);
            ++m;
        }
    EXPECT_EQ(stats.lookups, uint64_t(m));
    EXPECT_GE(stats.minBandwidth, 50);
    EXPECT_LE(stats.maxBandwidth, 500);
    // The noise yardstick is the spread of the history E(1..50), so a binary-search step
    // rejects by chance now and then (as RADIANCE's random test does on average); over a
    // uniform density the bandwidth still ends far above bw1 (RADIANCE's rule: ~276).
    EXPECT_GT(stats.meanBandwidth(), 4 * 50) << stats.report("global");
    EXPECT_NEAR(sum / m, 1.0, 0.02);
}

TEST(BiasComp, StaysSmallNextToDensityEdge) {
    // Photons on x < 0.5 only, at the density of 200k per unit area. Queries 0.01 from
    // the edge (r(50) ~ 0.009, r(500) ~ 0.028): a fixed bandwidth of 500 reaches well over
    // the edge and underestimates; compensation must keep the bandwidth lower and the
    // estimate closer to the truth.
    const size_t n = 100000;
    const PhotonMap map = planeMap(n, 0.5, 12, {1e-3, 1e-3, 1e-3});
    const double truth = 2.0 * n * map.photons()[0].fluxRgb()[0] / kPi;
    PhotonLookup lookup(map, LookupParams{500, 0, 0.5});
    PhotonLookup fixed(map, LookupParams{500, 0, 0.5});
    BiasCompStats stats;
    double errComp = 0, errFixed = 0;
    int m = 0;
    for (int j = 1; j <= 39; ++j) {
        const Vec3 q(0.49, 0.025 * j, 0);
        errComp += lookup.biasCompensatedDensity(q, kUp, 50, 500, &stats)[0] / truth - 1;
        errFixed += fixed.surfaceDensity(q, kUp)[0] / truth - 1;
        ++m;
    }
    // Measured: mean bandwidth 243 (uniform: 470), mean error -14 % (fixed 500: -32 %). The
    // local test cannot see a bias below ~z/sqrt(bw1) = 28 % at the first binary-search
    // step, so the compensation is partial (bias_comp.h).
    EXPECT_LT(stats.meanBandwidth(), 0.6 * 500) << stats.report("global");
    EXPECT_GE(stats.minBandwidth, 50);
    EXPECT_LT(errFixed / m, -0.15);  // fixed bandwidth: strongly biased
    EXPECT_LT(std::abs(errComp / m), 0.6 * std::abs(errFixed / m));  // compensated: less
}

TEST(BiasComp, BandwidthStaysInRangeAndFewPhotons) {
    const PhotonMap map = planeMap(2000, 1.0, 13, {1, 1, 1});
    PhotonLookup lookup(map, LookupParams{300, 0, 0.5});
    BiasCompStats stats;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.2, 1.2);  // also off the plane's edges
    for (int i = 0; i < 400; ++i)
        lookup.biasCompensatedDensity(Vec3(u(rng), u(rng), 0), kUp, 20, 300, &stats);
    EXPECT_GE(stats.minBandwidth, 20);
    EXPECT_LE(stats.maxBandwidth, 300);
    // Fewer photons than bw1: everything found but the furthest is used.
    const PhotonMap tiny = planeMap(10, 1.0, 14, {1, 1, 1});
    PhotonLookup small(tiny, LookupParams{50, 1e3, 0.5});
    BiasCompStats s2;
    small.biasCompensatedDensity(Vec3(0.5, 0.5, 0), kUp, 20, 50, &s2);
    EXPECT_EQ(s2.minBandwidth, 9);
    EXPECT_EQ(s2.maxBandwidth, 9);
    // Seen from below, no photon passes the normal filter: 0, not counted.
    BiasCompStats s3;
    EXPECT_EQ(small.biasCompensatedDensity(Vec3(0.5, 0.5, 0), Vec3(0, 0, -1), 2, 5, &s3),
              (std::array<double, 3>{0, 0, 0}));
    EXPECT_EQ(s3.lookups, 0u);
}

TEST(BiasComp, EqualBandwidthsMatchSurfaceDensity) {
    const PhotonMap map = planeMap(20000, 1.0, 15, {1, 2, 3});
    PhotonLookup a(map, LookupParams{80, 0, 0.5});
    PhotonLookup b(map, LookupParams{80, 0, 0.5});
    for (int i = 0; i < 50; ++i) {
        const Vec3 q(0.02 * i, 0.5, 0);  // includes the border: short-of-queue cases
        const auto x = a.surfaceDensity(q, kUp);
        const auto y = b.biasCompensatedDensity(q, kUp, 80, 80);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], y[c], 1e-12 * x[c]) << i;
    }
}

TEST(BiasComp, IndependentOfQueryOrderAndThreads) {
    const PhotonMap map = planeMap(50000, 1.0, 16, {1e-3, 1e-3, 1e-3});
    std::vector<Vec3> queries;
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 2000; ++i) queries.emplace_back(u(rng), u(rng), 0);
    // Fixed maximum radius (-am): the photons found depend on the query point only.
    const LookupParams params{400, 0.2, 0.5};
    std::vector<std::array<double, 3>> forward(queries.size()), backward(queries.size()),
        threaded(queries.size());
    {
        PhotonLookup l(map, params);
        for (size_t i = 0; i < queries.size(); ++i)
            forward[i] = l.biasCompensatedDensity(queries[i], kUp, 40, 400);
    }
    {
        PhotonLookup l(map, params);
        for (size_t i = queries.size(); i-- > 0;)
            backward[i] = l.biasCompensatedDensity(queries[i], kUp, 40, 400);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        tbb::enumerable_thread_specific<PhotonLookup> lookups(map, params);
        tbb::parallel_for(size_t(0), queries.size(), [&](size_t i) {
            threaded[i] = lookups.local().biasCompensatedDensity(queries[i], kUp, 40, 400);
        });
    }
    for (size_t i = 0; i < queries.size(); ++i) {
        ASSERT_EQ(forward[i], backward[i]) << i;
        ASSERT_EQ(forward[i], threaded[i]) << i;
    }
}

TEST(BiasComp, StatsReport) {
    BiasCompStats a, b;
    EXPECT_EQ(a.report("caustic"), "");
    a.add(50, 0.1);
    a.add(100, 0.2);
    b.add(300, 0.05);
    a.merge(b);
    EXPECT_EQ(a.lookups, 3u);
    EXPECT_EQ(a.report("caustic"), "50/300/150.0 caustic, (0.050/0.200/0.132 error)");
}

}  // namespace
}  // namespace rp::pmap
