// Bucket index k-NN: equals brute force and the map's kd-tree search (same photons, same
// float distances) on uniform, clustered and planar photon sets, with radius limits and
// the normal filter; build determinism; PhotonLookup with and without the index.
#include "pmap/lookup_index.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "pmap/density.h"
#include "pmap/photon_map.h"
#include "util/rng.h"

namespace rp::pmap {
namespace {

enum class Layout { Uniform, Clustered, Planes };

// Uniform: box [-1,1]^3, random normals. Clustered: 20 Gaussian blobs of very different
// widths (dense and sparse regions, many duplicate-ish coordinates). Planes: the six faces
// of a box with their normals plus 10 % of photons on an interior plane facing both ways,
// as photons on surfaces are (the normal filter matters).
std::vector<Photon> makePhotons(Layout layout, size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<Vec3> centres;
    std::vector<double> widths;
    for (int i = 0; i < 20; ++i) {
        centres.emplace_back(u(rng), u(rng), u(rng));
        widths.push_back(std::pow(10.0, -3 + 2.5 * (u(rng) + 1) / 2));
    }
    std::vector<Photon> v;
    v.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        Vec3 p, nrm;
        switch (layout) {
            case Layout::Uniform:
                p = Vec3(u(rng), u(rng), u(rng));
                nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
                break;
            case Layout::Clustered: {
                const size_t c = rng() % centres.size();
                p = centres[c] + Vec3(g(rng), g(rng), g(rng)) * widths[c];
                nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
                break;
            }
            case Layout::Planes: {
                const unsigned face = rng() % 7;
                const double s = u(rng), t = u(rng);
                if (face == 6) {
                    p = Vec3(s, 0.2, t);
                    nrm = Vec3(0, rng() % 2 ? 1 : -1, 0);
                } else {
                    const int axis = face % 3;
                    const double side = face < 3 ? -1 : 1;
                    double c[3] = {s, t, s};
                    c[axis] = side;
                    c[(axis + 1) % 3] = s;
                    c[(axis + 2) % 3] = t;
                    p = Vec3(c[0], c[1], c[2]);
                    double nn[3] = {0, 0, 0};
                    nn[axis] = -side;
                    nrm = Vec3(nn[0], nn[1], nn[2]);
                }
                break;
            }
        }
        v.push_back(makePhoton(p, nrm, {1e-3, 1e-3, 1e-3}));
    }
    return v;
}

struct Result {
    float dist2;
    uint32_t index;
    bool operator==(const Result&) const = default;
};

std::vector<Result> bruteForce(std::span<const Photon> ph, const Vec3& pos, const Vec3* normal,
                               float maxDist2, size_t k) {
    const float q[3] = {float(pos.x), float(pos.y), float(pos.z)};
    std::vector<Result> all;
    for (size_t i = 0; i < ph.size(); ++i) {
        const float dx = q[0] - ph[i].pos[0], dy = q[1] - ph[i].pos[1], dz = q[2] - ph[i].pos[2];
        const float d2 = dx * dx + dy * dy + dz * dz;
        if (!(d2 < maxDist2)) continue;
        if (normal) {
            const float n[3] = {float(normal->x), float(normal->y), float(normal->z)};
            if (!(n[0] * ph[i].norm[0] + n[1] * ph[i].norm[1] + n[2] * ph[i].norm[2] >
                  kNormalTolerance))
                continue;
        }
        all.push_back({d2, uint32_t(i)});
    }
    std::sort(all.begin(), all.end(), [](const Result& a, const Result& b) {
        return a.dist2 < b.dist2 || (a.dist2 == b.dist2 && a.index < b.index);
    });
    if (all.size() > k) all.resize(k);
    return all;
}

// Sorted by (dist2, index); the heap property is checked on the way.
std::vector<Result> sortedHits(std::span<const PhotonHit> hits) {
    std::vector<Result> r;
    for (size_t i = 0; i < hits.size(); ++i) {
        if (i) {
            EXPECT_LE(hits[i].dist2, hits[(i - 1) / 2].dist2) << "not a max-heap";
        }
        r.push_back({hits[i].dist2, hits[i].index});
    }
    std::sort(r.begin(), r.end(), [](const Result& a, const Result& b) {
        return a.dist2 < b.dist2 || (a.dist2 == b.dist2 && a.index < b.index);
    });
    return r;
}

// Equal up to ties: the same distances, and the same photons strictly inside the furthest
// distance (photons at exactly the furthest distance may be swapped for one another).
void expectSameUpToTies(const std::vector<Result>& got, const std::vector<Result>& want,
                        const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t i = 0; i < got.size(); ++i) {
        ASSERT_EQ(got[i].dist2, want[i].dist2) << what << " i=" << i;
        if (got[i].dist2 < got.back().dist2) {
            ASSERT_EQ(got[i].index, want[i].index) << what;
        }
    }
}

TEST(PhotonLookupIndex, KNearestEqualsBruteForceAndKdTree) {
    for (Layout layout : {Layout::Uniform, Layout::Clustered, Layout::Planes}) {
        for (size_t n : {1u, 7u, 16u, 17u, 300u, 20000u}) {
            const auto photons = makePhotons(layout, n, 10 + uint32_t(n));
            const PhotonMap map(PhotonMapType::Global, photons);  // kd-tree (file) order
            const PhotonIndex index(map.photons(), n > 1000);
            ASSERT_EQ(index.size(), n);
            std::mt19937 rng(5);
            std::uniform_real_distribution<double> u(-1.1, 1.1);
            for (size_t k : {1u, 2u, 51u, 501u}) {
                std::vector<PhotonHit> a(k), b(k);
                for (float maxDist2 : {std::numeric_limits<float>::infinity(), 0.02f, 1e-4f}) {
                    for (int trial = 0; trial < 24; ++trial) {
                        // Half the queries at photons (on surfaces, in clusters).
                        Vec3 q(u(rng), u(rng), u(rng));
                        if (trial % 2) q = map.photons()[rng() % n].position();
                        const Vec3 nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
                        const Vec3* np = trial % 4 < 2 ? &nrm : nullptr;
                        const std::string what =
                            "layout=" + std::to_string(int(layout)) + " n=" + std::to_string(n) +
                            " k=" + std::to_string(k) + " trial=" + std::to_string(trial);
                        const size_t fa = index.findNearest(q, np, maxDist2, a);
                        const size_t fb = findNearestPhotons(map.photons(), q, np, maxDist2, b);
                        const auto want = bruteForce(map.photons(), q, np, maxDist2, k);
                        expectSameUpToTies(sortedHits({a.data(), fa}), want, what + " index");
                        expectSameUpToTies(sortedHits({b.data(), fb}), want, what + " kdtree");
                    }
                }
            }
        }
    }
}

// The scratch overload (density estimates): the k nearest with the furthest at [0], the
// others in any order. Covers the bucketed selection's normal, crowded-step (clusters)
// and unbounded-radius paths.
TEST(PhotonLookupIndex, ScratchOverloadPutsFurthestFirst) {
    for (Layout layout : {Layout::Uniform, Layout::Clustered, Layout::Planes}) {
        const auto photons = makePhotons(layout, 20000, 77);
        const PhotonIndex index(photons, false);
        std::mt19937 rng(6);
        std::vector<PhotonHit> scratch;
        for (size_t k : {1u, 2u, 51u, 501u}) {
            for (float maxDist2 : {std::numeric_limits<float>::infinity(), 0.02f}) {
                for (int trial = 0; trial < 40; ++trial) {
                    const Vec3 q = photons[rng() % photons.size()].position();
                    const size_t n = index.findNearestSlots(q, nullptr, maxDist2, k, scratch);
                    const auto want = bruteForce(photons, q, nullptr, maxDist2, k);
                    ASSERT_EQ(n, want.size());
                    std::vector<float> got;
                    for (size_t i = 0; i < n; ++i) {
                        got.push_back(scratch[i].dist2);
                        ASSERT_LE(scratch[i].dist2, scratch[0].dist2);
                    }
                    std::sort(got.begin(), got.end());
                    for (size_t i = 0; i < n; ++i) ASSERT_EQ(got[i], want[i].dist2) << i;
                }
            }
        }
    }
}

TEST(PhotonLookupIndex, EmptyAndOutsideBounds) {
    const PhotonIndex empty(std::span<const Photon>{});
    std::vector<PhotonHit> out(5);
    EXPECT_EQ(empty.findNearest(Vec3(0, 0, 0), nullptr, 1.0f, out), 0u);
    const auto photons = makePhotons(Layout::Uniform, 100, 3);
    const PhotonIndex index(photons);
    // Far outside the bounding box: nothing within the radius, everything without limit.
    EXPECT_EQ(index.findNearest(Vec3(10, 0, 0), nullptr, 1.0f, out), 0u);
    EXPECT_EQ(index.findNearest(Vec3(10, 0, 0), nullptr, 1e9f, out), 5u);
    EXPECT_EQ(index.findNearest(Vec3(0, 0, 0), nullptr, 1e9f, {}), 0u);
}

TEST(PhotonLookupIndex, BuildIsDeterministicAcrossThreads) {
    const auto photons = makePhotons(Layout::Clustered, 100000, 9);
    const PhotonIndex serial(photons, false);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    const PhotonIndex parallel(photons, true);
    std::vector<PhotonHit> a(60), b(60);
    for (size_t i = 0; i < photons.size(); i += 997) {
        const Vec3 q = photons[i].position();
        const size_t fa = serial.findNearest(q, nullptr, 1e9f, a);
        const size_t fb = parallel.findNearest(q, nullptr, 1e9f, b);
        ASSERT_EQ(fa, fb);
        for (size_t j = 0; j < fa; ++j) {
            ASSERT_EQ(a[j].dist2, b[j].dist2);
            ASSERT_EQ(a[j].index, b[j].index);
        }
    }
    // Index memory: positions, normals, flux and indices plus nodes, 23 bytes per padded
    // slot; 26.2 here (100000 photons give leaves of 24-25 photons, padded to 28 slots).
    const double perPhoton = double(serial.memoryBytes()) / double(photons.size());
    EXPECT_GT(perPhoton, 23.0);
    EXPECT_LT(perPhoton, 27.0);
}

// The slot interface density estimates use: the same hits (distances, heap order) as
// findNearest, slots mapping to the same photons, and each slot's flux equal to fluxRgb().
TEST(PhotonLookupIndex, SlotsNameTheSamePhotonsAndFlux) {
    auto photons = makePhotons(Layout::Planes, 20000, 12);
    std::mt19937 rng(5);
    for (Photon& p : photons) p.setFlux(1e-3 * (rng() % 1000 + 1), 1e-5 * (rng() % 97), 2e-4);
    const PhotonIndex index(photons);
    std::vector<PhotonHit> a(51), b(51);
    for (size_t i = 0; i < photons.size(); i += 211) {
        const Vec3 q = photons[i].position();
        const Vec3 n(0, 1, 0);
        const size_t fa = index.findNearest(q, &n, 0.05f, a);
        const size_t fb = index.findNearestSlots(q, &n, 0.05f, b);
        ASSERT_EQ(fa, fb);
        for (size_t j = 0; j < fa; ++j) {
            ASSERT_EQ(a[j].dist2, b[j].dist2);
            ASSERT_EQ(a[j].index, index.photonIndex(b[j].index));
            ASSERT_EQ(index.slotFlux(b[j].index), photons[a[j].index].fluxRgb());
        }
    }
}

TEST(PhotonLookupIndex, PhotonLookupSameWithAndWithoutIndex) {
    const PhotonMap map(PhotonMapType::Global, makePhotons(Layout::Planes, 50000, 4));
    LazyPhotonIndex lazy;
    const PhotonIndex& index = lazy.get(map.photons());
    EXPECT_EQ(&index, &lazy.get(map.photons()));  // built once
    for (int k : {1, 50, 500}) {
        PhotonLookup plain(map, LookupParams{k, 0, 0.5});
        PhotonLookup fast(map, LookupParams{k, 0, 0.5}, &index);
        std::mt19937 rng(8);
        for (int i = 0; i < 300; ++i) {
            const Photon& p = map.photons()[rng() % map.size()];
            Vec3 n(p.norm[0] / 127.0, p.norm[1] / 127.0, p.norm[2] / 127.0);
            n = normalize(n);
            const auto a = plain.surfaceDensity(p.position(), n);
            const auto b = fast.surfaceDensity(p.position(), n);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 1e-12 * a[c]) << k;
            EXPECT_EQ(plain.precompDensity(p.position(), n), fast.precompDensity(p.position(), n));
        }
        EXPECT_EQ(plain.maxDist2(), fast.maxDist2());
        EXPECT_EQ(plain.shortLookups(), fast.shortLookups());
    }
}

// Regression: a co-planar set (z all 0) queried at the square's centre with k = 101 missed
// close photons with x >= 0.5 when the far-subtree test scaled the cell distance by 4
// (pruning cells nearer than the search radius); with k = 10 the result was still right.
// Checked to fail with that factor restored, with this photon set.
TEST(PhotonLookupIndex, PlanarSquareCentreRegression) {
    std::vector<Photon> photons;
    Rng rng(7, RngDomain::Test, 0);
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double x = rng.uniform(), y = rng.uniform();
        photons.push_back(makePhoton({x, y, 0}, {0, 0, 1}, {1e-4, 1e-4, 1e-4}));
    }
    const PhotonMap map(PhotonMapType::Global, std::move(photons));
    const PhotonIndex index(map.photons(), false);
    const Vec3 q(0.5, 0.5, 0);
    for (size_t k : {10u, 101u}) {
        std::vector<PhotonHit> a(k), b(k);
        const size_t fa = index.findNearest(q, nullptr, 0.08f, a);
        const size_t fb = findNearestPhotons(map.photons(), q, nullptr, 0.08f, b);
        const auto want = bruteForce(map.photons(), q, nullptr, 0.08f, k);
        expectSameUpToTies(sortedHits({a.data(), fa}), want, "index k=" + std::to_string(k));
        expectSameUpToTies(sortedHits({b.data(), fb}), want, "kdtree k=" + std::to_string(k));
    }
}

// Co-planar sets (one coordinate constant, so one extent is 0) of 20k photons, some with
// coordinates snapped to a grid (many photons share a split coordinate), against brute
// force for k from one to many leaves (kLeafSize 32), with queries at random points,
// exactly at photon coordinates, at 0.5 (where median splits fall) and mixed, on and off
// the plane. Far cells matter here: with k = 101..500 the search radius spans several
// leaves, so any over-pruning of far subtrees shows up as a missed photon.
TEST(PhotonLookupIndex, PlanarSetsEqualBruteForce) {
    for (int variant = 0; variant < 6; ++variant) {
        const int flatAxis = variant % 3;  // the constant coordinate
        const bool snapped = variant >= 3;
        Rng rng(100 + variant, RngDomain::Test, 0);
        std::vector<Photon> photons;
        const size_t n = 20000;
        for (size_t i = 0; i < n; ++i) {
            double s = rng.uniform(), t = rng.uniform();
            if (snapped) {  // 257 values per axis, 0.5 among them
                s = std::round(s * 256) / 256;
                t = std::round(t * 256) / 256;
            }
            double c[3];
            c[flatAxis] = variant == 1 ? 0.25 : 0.0;
            c[(flatAxis + 1) % 3] = s;
            c[(flatAxis + 2) % 3] = t;
            double nn[3] = {0, 0, 0};
            nn[flatAxis] = 1;
            photons.push_back(
                makePhoton({c[0], c[1], c[2]}, {nn[0], nn[1], nn[2]}, {1e-4, 1e-4, 1e-4}));
        }
        const PhotonMap map(PhotonMapType::Global, std::move(photons));
        const auto ph = map.photons();
        const bool parallel = variant % 2 == 1;  // same tree either way (build test)
        const PhotonIndex index(ph, parallel);
        for (size_t k : {1u, 50u, 101u, 500u}) {
            std::vector<PhotonHit> a(k), b(k);
            for (float maxDist2 : {0.08f, std::numeric_limits<float>::infinity()}) {
                for (int trial = 0; trial < 60; ++trial) {
                    const Photon& p = ph[rng.below(n)];
                    const Photon& r = ph[rng.below(n)];
                    Vec3 q;
                    switch (trial % 6) {
                        case 0:
                            q = p.position();
                            break;
                        case 1:
                            q = Vec3(0.5, 0.5, 0.5);
                            break;
                        case 2:
                            q = Vec3(rng.uniform(), rng.uniform(), rng.uniform());
                            break;
                        case 3:
                            q = Vec3(p.pos[0], r.pos[1], p.pos[2]);
                            break;
                        case 4:
                            q = Vec3(0.5, p.pos[1], 0.5);
                            break;
                        default:
                            q = Vec3(p.pos[0], 0.5, r.pos[2]);
                            break;
                    }
                    if (trial % 12 < 6) {  // on the plane, as surface lookups are
                        double c[3] = {q.x, q.y, q.z};
                        c[flatAxis] = ph[0].pos[flatAxis];
                        q = Vec3(c[0], c[1], c[2]);
                    }
                    const std::string what = "variant=" + std::to_string(variant) +
                                             " k=" + std::to_string(k) +
                                             " trial=" + std::to_string(trial) +
                                             " maxDist2=" + std::to_string(maxDist2) +
                                             " parallel=" + std::to_string(parallel);
                    const size_t fa = index.findNearest(q, nullptr, maxDist2, a);
                    const size_t fb = findNearestPhotons(ph, q, nullptr, maxDist2, b);
                    const auto want = bruteForce(ph, q, nullptr, maxDist2, k);
                    expectSameUpToTies(sortedHits({a.data(), fa}), want, what + " index");
                    expectSameUpToTies(sortedHits({b.data(), fb}), want, what + " kdtree");
                }
            }
        }
    }
}

// Photons stacked on a few identical positions (as in a caustic's focus, where Morton codes
// coincide and the index splits by count) and a dense cluster a million times smaller than
// the map: equal to brute force up to ties, for k within one stack, across stacks and
// across everything; the selection handles runs of equal distances.
TEST(PhotonLookupIndex, StackedAndTinyClustersEqualBruteForce) {
    std::vector<Photon> photons;
    Rng rng(77, RngDomain::Test, 0);
    const Vec3 stacks[3] = {Vec3(0.1, 0.2, 0), Vec3(0.1, 0.2000001, 0), Vec3(0.9, 0.9, 0)};
    for (int i = 0; i < 3000; ++i)
        photons.push_back(makePhoton(stacks[i % 3], {0, 0, 1}, {1, 1, 1}));
    for (int i = 0; i < 3000; ++i)  // a cluster 1e-6 wide, and a sparse background
        photons.push_back(makePhoton(
            Vec3(0.5 + 1e-6 * rng.uniform(), 0.5 + 1e-6 * rng.uniform(), 0), {0, 0, 1}, {1, 1, 1}));
    for (int i = 0; i < 2000; ++i)
        photons.push_back(makePhoton(Vec3(rng.uniform(), rng.uniform(), 0), {0, 0, 1}, {1, 1, 1}));
    const PhotonMap map(PhotonMapType::Global, photons);
    const PhotonIndex index(map.photons(), false);
    const Vec3 up(0, 0, 1);
    for (const Vec3& q :
         {stacks[0], stacks[2], Vec3(0.5, 0.5, 0), Vec3(0.5000005, 0.5, 0), Vec3(0.3, 0.3, 0)}) {
        for (size_t k : {1u, 51u, 999u, 1001u, 2500u, 9000u}) {
            std::vector<PhotonHit> a(k);
            const size_t fa = index.findNearest(q, &up, 10.f, a);
            const auto want = bruteForce(map.photons(), q, &up, 10.f, k);
            expectSameUpToTies(sortedHits({a.data(), fa}), want,
                               "k=" + std::to_string(k) + " q=" + std::to_string(q.x));
        }
    }
}

// Sets where the radius guessed from a leaf's box is far off: photons on a line (the box
// has no area, so the guess starts tiny and grows pass by pass), on two perpendicular
// faces meeting at an edge (boxes across the edge overstate the area), and a dense patch
// beside a sparse one. Equal to brute force up to ties, with and without the normal filter
// and a radius limit.
TEST(PhotonLookupIndex, GuessUnfriendlySetsEqualBruteForce) {
    Rng rng(91, RngDomain::Test, 0);
    for (int variant = 0; variant < 3; ++variant) {
        std::vector<Photon> photons;
        for (int i = 0; i < 12000; ++i) {
            const double s = rng.uniform(), t = rng.uniform();
            if (variant == 0) {
                photons.push_back(makePhoton(Vec3(s, 0.3, 0.7), {0, 0, 1}, {1, 1, 1}));
            } else if (variant == 1) {
                const bool floor = i % 2 == 0;
                photons.push_back(floor ? makePhoton(Vec3(s, t, 0), {0, 0, 1}, {1, 1, 1})
                                        : makePhoton(Vec3(s, 0, t), {0, 1, 0}, {1, 1, 1}));
            } else {
                const bool dense = i % 4 != 0;
                photons.push_back(
                    makePhoton(dense ? Vec3(0.5 + 0.01 * s, 0.5 + 0.01 * t, 0) : Vec3(s, t, 0),
                               {0, 0, 1}, {1, 1, 1}));
            }
        }
        const PhotonMap map(PhotonMapType::Global, photons);
        const PhotonIndex index(map.photons(), false);
        const Vec3 up(0, 0, 1);
        for (int trial = 0; trial < 40; ++trial) {
            Vec3 q = map.photons()[rng.below(map.size())].position();
            if (trial % 3 == 0) q = q + Vec3(0.01 * rng.uniform(), 0.01 * rng.uniform(), 0.002);
            for (size_t k : {1u, 51u, 501u}) {
                for (float maxDist2 : {std::numeric_limits<float>::infinity(), 0.001f}) {
                    const Vec3* np = trial % 2 ? &up : nullptr;
                    std::vector<PhotonHit> a(k);
                    const size_t fa = index.findNearest(q, np, maxDist2, a);
                    const auto want = bruteForce(map.photons(), q, np, maxDist2, k);
                    expectSameUpToTies(sortedHits({a.data(), fa}), want,
                                       "variant=" + std::to_string(variant) + " trial=" +
                                           std::to_string(trial) + " k=" + std::to_string(k));
                }
            }
        }
    }
}

}  // namespace
}  // namespace rp::pmap
