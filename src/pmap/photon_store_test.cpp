// Every photon store answers the one search as brute force does: the same photons (up to
// ties at the k-th distance) and the same float distances, with radius limits, the normal
// filter and the caustic filter, on uniform, clustered, planar and stacked photon sets;
// the out-of-core store with a cache far smaller than the map. Also: the in-core build
// does not depend on threads, and the budget switches a map out of core with a message.
#include "pmap/photon_store.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "pmap/incore_store.h"
#include "pmap/photon_map.h"
#include "util/temp_dir_for_tests.h"
#include "util/warnings.h"

namespace rp::pmap {
namespace {

enum class Layout { Uniform, Clustered, Planes, Stacked };

// Uniform: box [-1,1]^3, random normals. Clustered: 20 Gaussian blobs of very different
// widths. Planes: the six faces of a box with their normals plus photons on an interior
// plane facing both ways. Stacked: 30 points holding many photons each (a caustic's
// focus: more photons at one position than a leaf holds). Photon i has primary i (its
// name in the results) and every third is caustic.
std::vector<Photon> makePhotons(Layout layout, size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<Vec3> centres;
    std::vector<double> widths;
    for (int i = 0; i < 30; ++i) {
        centres.emplace_back(u(rng), u(rng), u(rng));
        widths.push_back(std::pow(10.0, -3 + 2.5 * (u(rng) + 1) / 2));
    }
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i) {
        Vec3 p, nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
        if (layout == Layout::Uniform) {
            p = Vec3(u(rng), u(rng), u(rng));
        } else if (layout == Layout::Clustered) {
            const size_t c = rng() % 20;
            p = centres[c] + Vec3(g(rng), g(rng), g(rng)) * widths[c];
        } else if (layout == Layout::Stacked) {
            p = centres[rng() % centres.size()];
            nrm = Vec3(0, 0, 1);
        } else {
            const unsigned face = rng() % 7;
            const double s = u(rng), t = u(rng);
            if (face == 6) {
                p = Vec3(s, 0.2, t);
                nrm = Vec3(0, rng() % 2 ? 1 : -1, 0);
            } else {
                const int axis = face % 3;
                const double side = face < 3 ? -1 : 1;
                double c[3];
                c[axis] = side;
                c[(axis + 1) % 3] = s;
                c[(axis + 2) % 3] = t;
                p = Vec3(c[0], c[1], c[2]);
                double nn[3] = {0, 0, 0};
                nn[axis] = -side;
                nrm = Vec3(nn[0], nn[1], nn[2]);
            }
        }
        v.push_back(makePhoton(p, nrm, {1e-3 * (1 + i % 5), 1e-3, 1e-3}, i % 3 == 0,
                               static_cast<uint32_t>(i)));
    }
    return v;
}

struct Result {
    float dist2;
    uint32_t id;
    bool operator<(const Result& o) const {
        return dist2 < o.dist2 || (dist2 == o.dist2 && id < o.id);
    }
};

std::vector<Result> bruteForce(std::span<const Photon> ph, const PhotonQuery& q) {
    const float p[3] = {float(q.pos.x), float(q.pos.y), float(q.pos.z)};
    std::vector<Result> all;
    for (const Photon& f : ph) {
        const float dx = p[0] - f.pos[0], dy = p[1] - f.pos[1], dz = p[2] - f.pos[2];
        const float d2 = dx * dx + dy * dy + dz * dz;
        if (!(d2 < q.maxDist2) || (q.causticOnly && !f.caustic())) continue;
        if (q.normal) {
            const float n[3] = {float(q.normal->x), float(q.normal->y), float(q.normal->z)};
            if (!(n[0] * f.norm[0] + n[1] * f.norm[1] + n[2] * f.norm[2] > kNormalTolerance))
                continue;
            if (q.slab > 0 && !(std::fabs((f.pos[0] - p[0]) * n[0] + (f.pos[1] - p[1]) * n[1] +
                                          (f.pos[2] - p[2]) * n[2]) < q.slab))
                continue;
        }
        all.push_back({d2, f.primary});
    }
    const size_t k = std::min(q.k, all.size());
    std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k), all.end());
    all.resize(k);
    return all;
}

// The furthest first, then the found photons' attributes as stored.
std::vector<Result> checked(std::span<const FoundPhoton> hits, std::span<const Photon> ph) {
    std::vector<Result> r;
    for (const FoundPhoton& h : hits) {
        EXPECT_LE(h.dist2, hits[0].dist2) << "the furthest must come first";
        const Photon& p = ph[h.primary];
        EXPECT_EQ(h.flux, p.flux);
        EXPECT_EQ(h.caustic(), p.caustic());
        r.push_back({h.dist2, h.primary});
    }
    std::sort(r.begin(), r.end());
    return r;
}

// Equal up to ties: the same distances, and the same photons strictly inside the furthest.
void expectSameUpToTies(const std::vector<Result>& got, const std::vector<Result>& want,
                        const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t i = 0; i < got.size(); ++i) {
        ASSERT_EQ(got[i].dist2, want[i].dist2) << what << " i=" << i;
        if (got[i].dist2 < got.back().dist2) {
            ASSERT_EQ(got[i].id, want[i].id) << what;
        }
    }
}

// Both stores of a contribution map of `photons` (so that photons carry their names).
struct Stores {
    explicit Stores(const std::vector<Photon>& photons, const TempDir& dir) {
        PhotonMap map(PhotonMapType::Contrib, photons,
                      std::vector<PhotonPrimary>(photons.size(), PhotonPrimary{0}));
        const std::string f = dir.file("m.pm");
        map.save(f, "", true);
        inCore = PhotonMap::open(f, StoreOptions{});
        indexed = PhotonMap::open(f, StoreOptions{});  // read from the index inCore left
        StoreOptions tiny;                             // 15 resident photons, 64 cached, pages of 8
        tiny.cachePhotons = std::min<uint64_t>(64, photons.size() > 1 ? photons.size() - 1 : 1);
        tiny.pageSize = 4;
        tiny.bandwidth = 2;
        outOfCore = PhotonMap::open(f, tiny);
    }
    PhotonMap inCore, indexed, outOfCore;
};

TEST(PhotonStore, EveryStoreEqualsBruteForce) {
    TempDir dir;
    for (Layout layout : {Layout::Uniform, Layout::Clustered, Layout::Planes, Layout::Stacked}) {
        for (size_t n : {1u, 7u, 17u, 300u, 20000u}) {
            const auto photons = makePhotons(layout, n, 10 + uint32_t(n));
            const Stores stores(photons, dir);
            if (n > 64) {
                ASSERT_NE(stores.outOfCore.store().describe().find("out of core"),
                          std::string::npos);
            }
            std::mt19937 rng(5);
            std::uniform_real_distribution<double> u(-1.1, 1.1);
            for (const PhotonMap* m : {&stores.inCore, &stores.indexed, &stores.outOfCore}) {
                const PhotonStore& store = m->store();
                ASSERT_EQ(store.size(), n);
                auto cursor = store.makeCursor();
                std::vector<FoundPhoton> out;
                for (size_t k : {1u, 2u, 51u, 501u})
                    for (float r2 : {std::numeric_limits<float>::infinity(), 0.02f, 1e-4f})
                        for (int trial = 0; trial < 16; ++trial) {
                            Vec3 q(u(rng), u(rng), u(rng));
                            if (trial % 2) q = photons[rng() % n].position();  // on surfaces
                            const Vec3 nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
                            PhotonQuery query{q, trial % 4 < 2 ? &nrm : nullptr, trial % 8 >= 6, r2,
                                              k};
                            if (trial % 4 == 1) query.slab = 0.05f;  // -ape's own surface
                            const std::string what = store.describe() + " layout " +
                                                     std::to_string(int(layout)) + " n " +
                                                     std::to_string(n) + " k " + std::to_string(k) +
                                                     " trial " + std::to_string(trial);
                            const size_t found = store.findNearest(*cursor, query, out);
                            expectSameUpToTies(checked({out.data(), found}, photons),
                                               bruteForce(photons, query), what);
                        }
            }
        }
    }
}

// The in-core store of `photons` (named by their index) against brute force at `queries`.
void expectInCoreMatches(std::vector<Photon> photons, const std::vector<Vec3>& queries,
                         const Vec3* normal, std::initializer_list<size_t> ks,
                         std::initializer_list<float> radii, const std::string& what) {
    for (size_t i = 0; i < photons.size(); ++i) photons[i].primary = static_cast<uint32_t>(i);
    const InCoreStore store = InCoreStore::copyOf(photons, {false, true}, false);
    auto cursor = store.makeCursor();
    std::vector<FoundPhoton> out;
    for (size_t qi = 0; qi < queries.size(); ++qi)
        for (size_t k : ks)
            for (float r2 : radii) {
                const PhotonQuery q{queries[qi], normal, false, r2, k};
                const size_t n = store.findNearest(*cursor, q, out);
                expectSameUpToTies(checked({out.data(), n}, photons), bruteForce(photons, q),
                                   what + " query " + std::to_string(qi) + " k " +
                                       std::to_string(k) + " r2 " + std::to_string(r2));
            }
}

// Co-planar sets (one extent 0), some snapped to a grid (many photons share a split
// coordinate), with queries at photons, at 0.5 (where splits fall) and mixed, on and off
// the plane: with k up to 500 the radius spans several leaves, so any over-pruning of far
// cells shows up as a missed photon.
TEST(PhotonStore, PlanarSetsEqualBruteForce) {
    for (int variant = 0; variant < 6; ++variant) {
        const int flat = variant % 3;
        std::mt19937 rng(100 + variant);
        std::uniform_real_distribution<double> u(0, 1);
        std::vector<Photon> photons;
        for (int i = 0; i < 20000; ++i) {
            double st[2] = {u(rng), u(rng)};
            if (variant >= 3)
                for (double& v : st) v = std::round(v * 256) / 256;
            double c[3], nn[3] = {0, 0, 0};
            c[flat] = variant == 1 ? 0.25 : 0.0;
            c[(flat + 1) % 3] = st[0];
            c[(flat + 2) % 3] = st[1];
            nn[flat] = 1;
            photons.push_back(
                makePhoton({c[0], c[1], c[2]}, {nn[0], nn[1], nn[2]}, {1e-4, 1e-4, 1e-4}));
        }
        std::vector<Vec3> queries;
        for (int t = 0; t < 30; ++t) {
            const Photon& p = photons[rng() % photons.size()];
            Vec3 q = t % 3 == 0   ? p.position()
                     : t % 3 == 1 ? Vec3(0.5, 0.5, 0.5)
                                  : Vec3(p.pos[0], 0.5, u(rng));
            if (t % 2 == 0) {  // on the plane, as surface lookups are
                double c[3] = {q.x, q.y, q.z};
                c[flat] = photons[0].pos[flat];
                q = Vec3(c[0], c[1], c[2]);
            }
            queries.push_back(q);
        }
        expectInCoreMatches(photons, queries, nullptr, {1, 50, 101, 500},
                            {0.08f, std::numeric_limits<float>::infinity()},
                            "variant " + std::to_string(variant));
    }
}

// Photons stacked on identical positions (split by count) and a cluster a million times
// smaller than the map, for k within one stack, across stacks and across everything.
TEST(PhotonStore, StackedAndTinyClustersEqualBruteForce) {
    std::vector<Photon> photons;
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> u(0, 1);
    const Vec3 stacks[3] = {Vec3(0.1, 0.2, 0), Vec3(0.1, 0.2000001, 0), Vec3(0.9, 0.9, 0)};
    for (int i = 0; i < 3000; ++i)
        photons.push_back(makePhoton(stacks[i % 3], {0, 0, 1}, {1, 1, 1}));
    for (int i = 0; i < 3000; ++i)
        photons.push_back(
            makePhoton(Vec3(0.5 + 1e-6 * u(rng), 0.5 + 1e-6 * u(rng), 0), {0, 0, 1}, {1, 1, 1}));
    for (int i = 0; i < 2000; ++i)
        photons.push_back(makePhoton(Vec3(u(rng), u(rng), 0), {0, 0, 1}, {1, 1, 1}));
    const Vec3 up(0, 0, 1);
    expectInCoreMatches(
        photons,
        {stacks[0], stacks[2], Vec3(0.5, 0.5, 0), Vec3(0.5000005, 0.5, 0), Vec3(0.3, 0.3, 0)}, &up,
        {1, 51, 999, 1001, 2500, 9000}, {10.f}, "stacks");
}

// Sets where the radius guessed from a leaf's box is far off: photons on a line, on two
// faces meeting at an edge, and a dense patch beside a sparse one.
TEST(PhotonStore, GuessUnfriendlySetsEqualBruteForce) {
    std::mt19937 rng(91);
    std::uniform_real_distribution<double> u(0, 1);
    for (int variant = 0; variant < 3; ++variant) {
        std::vector<Photon> photons;
        for (int i = 0; i < 12000; ++i) {
            const double s = u(rng), t = u(rng);
            if (variant == 0)
                photons.push_back(makePhoton(Vec3(s, 0.3, 0.7), {0, 0, 1}, {1, 1, 1}));
            else if (variant == 1)
                photons.push_back(i % 2 ? makePhoton(Vec3(s, 0, t), {0, 1, 0}, {1, 1, 1})
                                        : makePhoton(Vec3(s, t, 0), {0, 0, 1}, {1, 1, 1}));
            else
                photons.push_back(
                    makePhoton(i % 4 ? Vec3(0.5 + 0.01 * s, 0.5 + 0.01 * t, 0) : Vec3(s, t, 0),
                               {0, 0, 1}, {1, 1, 1}));
        }
        std::vector<Vec3> queries;
        for (int t = 0; t < 20; ++t) {
            Vec3 q = photons[rng() % photons.size()].position();
            if (t % 3 == 0) q = q + Vec3(0.01 * u(rng), 0.01 * u(rng), 0.002);
            queries.push_back(q);
        }
        const Vec3 up(0, 0, 1);
        for (const Vec3* np : {static_cast<const Vec3*>(nullptr), &up})
            expectInCoreMatches(photons, queries, np, {1, 51, 501},
                                {std::numeric_limits<float>::infinity(), 0.001f},
                                "variant " + std::to_string(variant));
    }
}

TEST(PhotonStore, InCoreBuildDoesNotDependOnThreads) {
    const auto photons = makePhotons(Layout::Planes, 100000, 3);
    const InCoreStore serial = InCoreStore::copyOf(photons, {true, true}, false);
    const InCoreStore parallel = [&] {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        return InCoreStore::copyOf(photons, {true, true}, true);
    }();
    auto c1 = serial.makeCursor();
    auto c2 = parallel.makeCursor();
    std::vector<FoundPhoton> a, b;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 500; ++i) {
        const PhotonQuery q{photons[rng() % photons.size()].position(), nullptr, false, 0.1f, 50};
        const size_t na = serial.findNearest(*c1, q, a), nb = parallel.findNearest(*c2, q, b);
        ASSERT_EQ(na, nb);
        for (size_t j = 0; j < na; ++j) {
            ASSERT_EQ(a[j].dist2, b[j].dist2);
            ASSERT_EQ(a[j].primary, b[j].primary);
        }
    }
    EXPECT_EQ(serial.memoryBytes(), parallel.memoryBytes());
}

// The index (a store written out and read back) searches as the store it was written
// from, and is refused for any other key, attributes or count, and when cut short,
// lengthened or damaged anywhere (its CRC-32).
TEST(PhotonStore, InCoreIndexReadsBackOnlyWhatWasWritten) {
    const auto photons = makePhotons(Layout::Planes, 3000, 8);
    const InCoreStore::Attributes attrs{true, true};
    const InCoreStore store = InCoreStore::copyOf(photons, attrs, false);
    const InCoreStore::IndexKey key{1, 2, 3};
    std::ostringstream out;
    store.writeIndex(out, key);
    const std::string bytes = out.str();
    auto read = [&](const std::string& b, const InCoreStore::IndexKey& k, InCoreStore::Attributes a,
                    uint64_t n) {
        std::istringstream in(b);
        return InCoreStore::readIndex(in, k, a, n);
    };
    const std::optional<InCoreStore> back = read(bytes, key, attrs, photons.size());
    ASSERT_TRUE(back);
    EXPECT_EQ(back->memoryBytes(), store.memoryBytes());
    auto c1 = store.makeCursor();
    auto c2 = back->makeCursor();
    std::vector<FoundPhoton> a, b;
    std::mt19937 rng(2);
    for (int i = 0; i < 200; ++i) {
        const Vec3 up(0, 0, 1);
        const PhotonQuery q{photons[rng() % photons.size()].position(), i % 2 ? &up : nullptr,
                            false, 0.1f, 40};
        const size_t na = store.findNearest(*c1, q, a), nb = back->findNearest(*c2, q, b);
        ASSERT_EQ(na, nb);
        for (size_t j = 0; j < na; ++j) {
            ASSERT_EQ(a[j].dist2, b[j].dist2);
            ASSERT_EQ(a[j].primary, b[j].primary);
            ASSERT_EQ(a[j].flux, b[j].flux);
            ASSERT_EQ(std::memcmp(a[j].norm, b[j].norm, 3), 0);
        }
    }
    EXPECT_FALSE(read(bytes, {1, 2, 4}, attrs, photons.size()));
    EXPECT_FALSE(read(bytes, key, {false, true}, photons.size()));
    EXPECT_FALSE(read(bytes, key, attrs, photons.size() - 1));
    EXPECT_FALSE(read(bytes + "x", key, attrs, photons.size()));
    for (size_t cut : {size_t{0}, size_t{10}, size_t{100}, bytes.size() / 2, bytes.size() - 1})
        EXPECT_FALSE(read(bytes.substr(0, cut), key, attrs, photons.size())) << cut;
    for (size_t at = 0; at < bytes.size(); at += 997) {
        std::string damaged = bytes;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
        EXPECT_FALSE(read(damaged, key, attrs, photons.size())) << at;
    }
}

// A damaged index whose CRC-32 was made to match again is still refused when its tree
// could not be walked safely: a child shared by two parents (its photons would be found
// twice), a child before its parent, a leaf past the arrays.
TEST(PhotonStore, InCoreIndexRefusesMalformedTrees) {
    const auto photons = makePhotons(Layout::Uniform, 5000, 9);
    const InCoreStore store = InCoreStore::copyOf(photons, {false, false}, false);
    const InCoreStore::IndexKey key{4, 5, 6};
    std::ostringstream out;
    store.writeIndex(out, key);
    const std::string bytes = out.str();
    uint32_t headBytes;  // incore_store_index.cpp: the head's size at byte 8, the body's
    std::memcpy(&headBytes, bytes.data() + 8, 4);  // CRC-32 in its last four bytes
    ASSERT_LT(headBytes, bytes.size());
    // The nodes come first in the body, 16 bytes each: leftMax, rightMin, axisInfo, link.
    auto withNode = [&](uint32_t node, uint32_t field, uint32_t value) {
        std::string b = bytes;
        std::memcpy(b.data() + headBytes + 16 * node + 4 * field, &value, 4);
        const uint32_t crc = static_cast<uint32_t>(
            crc32(crc32(0, nullptr, 0), reinterpret_cast<const Bytef*>(b.data() + headBytes),
                  static_cast<uInt>(b.size() - headBytes)));
        std::memcpy(b.data() + headBytes - 4, &crc, 4);
        std::istringstream in(b);
        return InCoreStore::readIndex(in, key, {false, false}, photons.size()).has_value();
    };
    uint32_t rootLink;
    std::memcpy(&rootLink, bytes.data() + headBytes + 12, 4);
    ASSERT_GT(rootLink, 1u);
    EXPECT_TRUE(withNode(0, 3, rootLink)) << "the unchanged tree with its CRC made again";
    EXPECT_FALSE(withNode(0, 3, 1)) << "right child = left child";
    EXPECT_FALSE(withNode(0, 3, 0)) << "a child before its parent";
    EXPECT_FALSE(withNode(0, 2, 7)) << "no such axis";
    uint32_t leaf = 1;  // the first leaf: the left spine's end
    for (uint32_t axisInfo;; ++leaf) {
        std::memcpy(&axisInfo, bytes.data() + headBytes + 16 * leaf + 8, 4);
        if ((axisInfo & 3) == 3) break;
    }
    EXPECT_FALSE(withNode(leaf, 3, 1u << 30)) << "a leaf's slots past the arrays";
    EXPECT_FALSE(withNode(leaf, 2, 3u | (65u << 2))) << "more photons than a leaf holds";
}

TEST(PhotonStore, InCoreMemoryPerPhoton) {
    const auto photons = makePhotons(Layout::Planes, 200000, 4);
    const size_t plain = InCoreStore::copyOf(photons, {false, false}).memoryBytes();
    const size_t contrib = InCoreStore::copyOf(photons, {false, true}).memoryBytes();
    // Position, normal and flux (19 bytes) plus leaf padding and nodes.
    EXPECT_LT(double(plain) / photons.size(), 21.0);
    EXPECT_LT(double(contrib) / photons.size(), 26.0);
}

TEST(PhotonStore, MapsBeyondTheBudgetGoOutOfCoreWithAMessage) {
    TempDir dir;
    const auto photons = makePhotons(Layout::Uniform, 5000, 6);
    const std::string f = dir.file("g.pm");
    PhotonMap(PhotonMapType::Global, photons).save(f, "", true);
    std::vector<std::string> warnings;
    setWarningSink([&](const std::string& m) { warnings.push_back(m); });
    StoreOptions budget;
    budget.memoryBudget = 5000 * sizeof(Photon);  // just fits
    EXPECT_EQ(PhotonMap::open(f, budget).store().describe(), "in core");
    EXPECT_TRUE(warnings.empty());
    budget.memoryBudget = 4000 * sizeof(Photon);
    const PhotonMap m = PhotonMap::open(f, budget);
    setWarningSink(nullptr);
    EXPECT_NE(m.store().describe().find("out of core"), std::string::npos);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(f), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("out of core"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace rp::pmap
