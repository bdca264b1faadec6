// Density estimate against the analytic irradiance of a uniformly lit plane, and the
// automatic maximum search radius state machine.
#include "pmap/density.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace rp::pmap {
namespace {

// N photons uniformly distributed on the unit square z = 0, normal +z, equal flux.
PhotonMap unitSquareMap(size_t n, uint32_t seed, std::array<double, 3> flux) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Photon> v;
    v.reserve(n);
    for (size_t i = 0; i < n; ++i)
        v.push_back(makePhoton(Vec3(u(rng), u(rng), 0), Vec3(0, 0, 1), flux));
    PhotonMap map(PhotonMapType::Global, std::move(v));
    map.makeSearchable();
    return map;
}

// Truth: irradiance E = N * flux / area, and RADIANCE's estimate is E / pi.
// Tolerance: the k-NN estimate k / (pi r^2) has relative standard deviation ~ 1/sqrt(k)
// (pi r^2 times the density is Gamma(k)-distributed), and RADIANCE's radius between the k-th
// and (k+1)-th photon biases it by at most ~1/(2k). Query discs 0.1 apart (radius ~0.028)
// do not overlap, so the M = 49 estimates are independent: each must lie within 5 sigma
// = 5/sqrt(k), their mean within 4/sqrt(k M) + 1/k (2.8 % for k = 500).
TEST(Density, UniformPlaneMatchesAnalyticIrradiance) {
    const size_t n = 200000;
    const int k = 500;
    PhotonMap map = unitSquareMap(n, 2024, {1e-3, 2e-3, 5e-4});
    const auto flux = map.photons()[0].fluxRgb();  // after RGBE rounding, same for all
    PhotonLookup lookup(map, LookupParams{k, 0, 0.5});
    double sum[3] = {0, 0, 0};
    int m = 0;
    for (int i = 2; i <= 8; ++i)
        for (int j = 2; j <= 8; ++j) {
            auto e = lookup.surfaceDensity(Vec3(0.1 * i, 0.1 * j, 0), Vec3(0, 0, 1));
            for (int c = 0; c < 3; ++c) {
                const double truth = n * flux[c] / (kPi * 1.0);
                EXPECT_NEAR(e[c] / truth, 1.0, 5.0 / std::sqrt(k)) << i << "," << j;
                sum[c] += e[c] / truth;
            }
            ++m;
        }
    const double tol = 4.0 / std::sqrt(double(k) * m) + 1.0 / k;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c] / m, 1.0, tol) << "channel " << c;
    // Colour ratios are exact: every photon has the same flux.
    auto e = lookup.surfaceDensity(Vec3(0.5, 0.5, 0), Vec3(0, 0, 1));
    EXPECT_NEAR(e[1] / e[0], double(flux[1]) / flux[0], 1e-12);
    EXPECT_EQ(lookup.shortLookups(), 0u);
}

// Volume photons uniform in the unit cube, all travelling along +x: the estimate is the
// flux density over 4 pi, times the phase function toward the query direction (RADIANCE
// volumePhotonDensity), with the surface estimate's 1/sqrt(k) spread.
TEST(Density, VolumeDensityOfUniformPhotons) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> u(0, 1);
    const size_t n = 400000;
    const int k = 1000;
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i)
        v.push_back(makePhoton(Vec3(u(rng), u(rng), u(rng)), Vec3(1, 0, 0), {1e-3, 1e-3, 1e-3}));
    PhotonMap map(PhotonMapType::Volume, std::move(v));
    map.makeSearchable();
    const double flux = map.photons()[0].fluxRgb()[0];
    PhotonLookup lookup(map, LookupParams{k, 0, 0.5});
    const auto hg = [](double g, double c) {
        const double d = 1 + g * g - 2 * g * c;
        return g == 0 ? 1.0 : (1 - g * g) / (d * std::sqrt(d));
    };
    const double iso = n * flux / (4 * kPi);
    const Vec3 centre(0.5, 0.5, 0.5);
    EXPECT_NEAR(lookup.volumeDensity(centre, Vec3(0, 1, 0), 0, hg)[0] / iso, 1, 5 / std::sqrt(k));
    // Forward (out = +x) with g = 0.5: 6 x; backward: 0.5 / 2.25.
    EXPECT_NEAR(lookup.volumeDensity(centre, Vec3(1, 0, 0), 0.5, hg)[0] / (6 * iso), 1,
                5 / std::sqrt(k));
    EXPECT_NEAR(lookup.volumeDensity(centre, Vec3(-1, 0, 0), 0.5, hg)[0] / (iso * 0.5 / 2.25), 1,
                5 / std::sqrt(k));
    // No normal filter: any query "direction" finds the same photons.
    EXPECT_EQ(lookup.volumeDensity(centre, Vec3(0, 0, 1), 0, hg),
              lookup.volumeDensity(centre, Vec3(0, 0, -1), 0, hg));
}

TEST(Density, NormalFilterAndTooFewPhotons) {
    PhotonMap map = unitSquareMap(1000, 1, {1, 1, 1});
    PhotonLookup lookup(map, LookupParams{20, 0, 0.5});
    // Seen from below, every photon faces away.
    auto e = lookup.surfaceDensity(Vec3(0.5, 0.5, 0), Vec3(0, 0, -1));
    EXPECT_EQ(e, (std::array<double, 3>{0, 0, 0}));
    // Far away: nothing within the search radius.
    e = lookup.surfaceDensity(Vec3(50, 50, 0), Vec3(0, 0, 1));
    EXPECT_EQ(e, (std::array<double, 3>{0, 0, 0}));
    EXPECT_EQ(lookup.shortLookups(), 0u);  // 0 or 1 found: not counted (RADIANCE threshold)
    PhotonMap empty;
    PhotonLookup none(empty, LookupParams{});
    EXPECT_EQ(none.surfaceDensity(Vec3(), Vec3(0, 0, 1)), (std::array<double, 3>{0, 0, 0}));
}

TEST(Density, BandwidthClampedToPhotonCount) {
    PhotonMap map = unitSquareMap(10, 1, {1, 1, 1});
    PhotonLookup lookup(map, LookupParams{40, 0, 0.5});
    EXPECT_EQ(lookup.bandwidth(), 10);
    EXPECT_EQ(lookup.findPhotons(Vec3(0.5, 0.5, 0), nullptr).size(), 10u);
}

TEST(Density, AutomaticMaxSearchRadius) {
    const size_t n = 10000;
    const int k = 50;
    PhotonMap map = unitSquareMap(n, 7, {1, 1, 1});
    PhotonLookup lookup(map, LookupParams{k, 0, 0.5});
    // Initial and limiting squared radius: 100 (k+1) CoGdist / N, CoGdist ~ 1/6 here.
    const double limit = lookup.maxDist2Limit();
    EXPECT_EQ(limit, static_cast<float>(100.0 * (k + 1) * map.stats().cogDist2 / n));
    EXPECT_NEAR(map.stats().cogDist2, 1.0 / 6, 0.01);
    EXPECT_EQ(lookup.maxDist2(), limit);

    // 1000 consecutive good lookups shrink it by 0.9, twice.
    for (int i = 0; i < 999; ++i) lookup.findPhotons(Vec3(0.5, 0.5, 0), nullptr);
    EXPECT_EQ(lookup.maxDist2(), limit);
    lookup.findPhotons(Vec3(0.5, 0.5, 0), nullptr);
    EXPECT_DOUBLE_EQ(lookup.maxDist2(), limit * 0.9);
    for (int i = 0; i < 1000; ++i) lookup.findPhotons(Vec3(0.5, 0.5, 0), nullptr);
    EXPECT_DOUBLE_EQ(lookup.maxDist2(), limit * 0.9 * 0.9);

    // A query just beyond the edge: the search disc only clips a thin sliver of the square
    // (~13 photons expected), a short lookup with more than one photon -> radius^2 x 4.
    const double r = std::sqrt(lookup.maxDist2());
    auto hits = lookup.findPhotons(Vec3(1 + r - 0.012, 0.5, 0), nullptr);
    EXPECT_GT(hits.size(), 1u);
    EXPECT_LT(hits.size(), (k + 1) / 2u);
    EXPECT_EQ(lookup.shortLookups(), 1u);
    EXPECT_DOUBLE_EQ(lookup.maxDist2(), limit * 0.9 * 0.9 * 4);
    // Now above the limit: a further short lookup no longer grows it.
    const double r2 = std::sqrt(lookup.maxDist2());
    hits = lookup.findPhotons(Vec3(1 + r2 - 0.008, 0.5, 0), nullptr);
    EXPECT_GT(hits.size(), 1u);
    EXPECT_LT(hits.size(), (k + 1) / 2u);
    EXPECT_EQ(lookup.shortLookups(), 2u);
    EXPECT_DOUBLE_EQ(lookup.maxDist2(), limit * 0.9 * 0.9 * 4);
    EXPECT_EQ(lookup.lookups(), 2002u);
}

TEST(Density, FixedMaxSearchRadius) {
    PhotonMap map = unitSquareMap(10000, 8, {1, 1, 1});
    PhotonLookup lookup(map, LookupParams{50, 0.02, 0.5});  // -am 0.02: ~12 photons in reach
    EXPECT_DOUBLE_EQ(lookup.maxDist2(), 0.02 * 0.02);
    for (int i = 0; i < 2000; ++i) lookup.findPhotons(Vec3(0.5, 0.5, 0), nullptr);
    EXPECT_EQ(lookup.shortLookups(), 2000u);
    EXPECT_DOUBLE_EQ(lookup.maxDist2(), 0.02 * 0.02);  // never adapted
}

TEST(Density, PrecompTakesNearestPhotonFlux) {
    std::vector<Photon> v = {makePhoton(Vec3(0, 0, 0), Vec3(0, 0, 1), {1, 2, 3}),
                             makePhoton(Vec3(1, 0, 0), Vec3(0, 0, 1), {4, 5, 6}),
                             makePhoton(Vec3(0.2, 0, 0), Vec3(0, 0, -1), {7, 8, 9})};
    PhotonMap map(PhotonMapType::PreComp, v);
    map.makeSearchable();
    PhotonLookup lookup(map, LookupParams{1, 0, 0.5});
    auto e = lookup.precompDensity(Vec3(0.3, 0, 0), Vec3(0, 0, 1));  // skips the -z photon
    const auto want = v[0].fluxRgb();                                // the nearest facing +z
    EXPECT_EQ(e, (std::array<double, 3>{want[0], want[1], want[2]}));
    EXPECT_NEAR(e[0], 1, 0.01);
}

}  // namespace
}  // namespace rp::pmap
