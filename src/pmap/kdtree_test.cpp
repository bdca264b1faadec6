// kd-tree: heap order and shape, parallel build determinism, k-NN and 1-NN against brute force.
#include "pmap/kdtree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace rp::pmap {
namespace {

std::vector<Photon> randomPhotons(size_t n, uint32_t seed, float scale = 1.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i) {
        Vec3 p(u(rng) * scale, u(rng) * scale * 0.5, u(rng) * scale * 0.25);
        Vec3 nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
        v.push_back(makePhoton(p, nrm, {u(rng) + 1, u(rng) + 1, u(rng) + 1}, i % 3 == 0,
                               static_cast<uint32_t>(i)));
    }
    return v;
}

bool samePhotonMultiset(std::vector<Photon> a, std::span<const Photon> tree) {
    std::vector<Photon> b(tree.begin(), tree.end());
    auto key = [](const Photon& p) { return p.primary; };
    std::sort(a.begin(), a.end(), [&](auto& x, auto& y) { return key(x) < key(y); });
    std::sort(b.begin(), b.end(), [&](auto& x, auto& y) { return key(x) < key(y); });
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        Photon x = a[i], y = b[i];
        x.setDiscr(0);
        y.setDiscr(0);
        if (!(x == y)) return false;
    }
    return true;
}

TEST(KdTree, HeapOrderPropertyAndPhotonsKept) {
    for (size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 100u, 1000u, 33333u}) {
        auto in = randomPhotons(n, static_cast<uint32_t>(n));
        auto tree = buildKdTree(in, false);
        ASSERT_EQ(tree.size(), n);
        EXPECT_EQ(checkKdTree(tree), "") << n;
        EXPECT_TRUE(samePhotonMultiset(in, tree)) << n;
    }
}

// Points on a line are all split along x; an in-order walk of a valid, left-balanced heap
// then visits them in sorted order, which pins down both the order and the median choice.
TEST(KdTree, LeftBalancedShapeForN1To100) {
    for (size_t n = 1; n <= 100; ++n) {
        std::vector<Photon> in;
        std::mt19937 rng(static_cast<uint32_t>(n));
        std::vector<int> xs(n);
        for (size_t i = 0; i < n; ++i) xs[i] = static_cast<int>(i);
        std::shuffle(xs.begin(), xs.end(), rng);
        for (int x : xs) in.push_back(makePhoton(Vec3(x, 0, 0), Vec3(0, 0, 1), {1, 1, 1}));
        auto tree = buildKdTree(in, false);
        ASSERT_EQ(checkKdTree(tree), "") << n;
        std::vector<float> order;
        std::function<void(size_t)> walk = [&](size_t node) {
            if (node > n) return;
            if (2 * node <= n) {  // internal nodes split along x (leaves: any axis)
                EXPECT_EQ(tree[node - 1].discr(), 0);
            }
            walk(2 * node);
            order.push_back(tree[node - 1].pos[0]);
            walk(2 * node + 1);
        };
        walk(1);
        for (size_t i = 0; i < n; ++i) ASSERT_EQ(order[i], static_cast<float>(i)) << "n=" << n;
        // Left-balanced: the root's left subtree holds every node of the last level up to
        // half of its capacity, so the root is the element of rank |left subtree|.
        size_t h = 0;
        while ((size_t{2} << h) - 1 < n) ++h;  // height: levels 0..h
        size_t full = (size_t{1} << h) - 1;    // nodes above the last level
        size_t last = n - full;
        size_t leftSize =
            h ? ((size_t{1} << (h - 1)) - 1) + std::min(last, size_t{1} << (h - 1)) : 0;
        EXPECT_EQ(tree[0].pos[0], static_cast<float>(leftSize)) << n;
    }
}

// The in-order layout and the heap are one gather apart: kdInOrderIndex names, for
// each heap node, the in-order position buildKdTree copies it from.
TEST(KdTree, InOrderIndexMatchesTheHeap) {
    for (size_t n : {1u, 2u, 3u, 5u, 8u, 13u, 64u, 100u, 1023u, 1024u, 1025u, 3000u}) {
        auto in = randomPhotons(n, static_cast<uint32_t>(n) + 3);
        auto tree = buildKdTree(in, false);
        std::vector<Photon> inOrder = in;
        buildKdTreeInOrder(inOrder, false);
        for (size_t node = 1; node <= n; ++node)
            ASSERT_EQ(tree[node - 1], inOrder[kdInOrderIndex(node, n)]) << n << " " << node;
    }
}

TEST(KdTree, SplitAxisIsLargestExtent) {
    auto in = randomPhotons(1000, 3);  // extents 2 : 1 : 0.5
    auto tree = buildKdTree(in, false);
    EXPECT_EQ(tree[0].discr(), 0);
}

TEST(KdTree, ParallelBuildEqualsSerial) {
    auto in = randomPhotons(200000, 5);
    auto a = buildKdTree(in, false);
    auto b = buildKdTree(in, true);
    EXPECT_EQ(a, b);
    EXPECT_EQ(checkKdTree(b), "");
}

TEST(KdTree, DuplicatePositions) {
    std::vector<Photon> in;
    for (int i = 0; i < 500; ++i)
        in.push_back(makePhoton(Vec3(i % 3, 0.5, (i % 7) * 0.25), Vec3(0, 0, 1), {1, 1, 1}));
    auto tree = buildKdTree(in, true);
    EXPECT_EQ(checkKdTree(tree), "");
    PhotonHit hits[600];
    Vec3 q(1, 0.5, 0.5);
    EXPECT_EQ(findNearestPhotons(tree, q, nullptr, 1e30f, hits), 500u);
}

TEST(KdTree, CheckDetectsBrokenOrder) {
    auto tree = buildKdTree(randomPhotons(100, 9), false);
    auto broken = tree;
    std::swap(broken[1], broken[2]);  // root's children exchanged
    EXPECT_NE(checkKdTree(broken), "");
    broken = tree;
    broken[5].flags |= 3;  // split axis 3 does not exist
    EXPECT_NE(checkKdTree(broken), "");
}

// Brute force with the same single-precision arithmetic as the search.
std::vector<float> bruteForce(std::span<const Photon> tree, const Vec3& pos, const Vec3* n,
                              float maxDist2, size_t k) {
    const float q[3] = {float(pos.x), float(pos.y), float(pos.z)};
    std::vector<float> d;
    for (const Photon& p : tree) {
        const float dx = q[0] - p.pos[0], dy = q[1] - p.pos[1], dz = q[2] - p.pos[2];
        const float d2 = dx * dx + dy * dy + dz * dz;
        if (!(d2 < maxDist2)) continue;
        if (n && !(float(n->x) * p.norm[0] + float(n->y) * p.norm[1] + float(n->z) * p.norm[2] >
                   kNormalTolerance))
            continue;
        d.push_back(d2);
    }
    std::sort(d.begin(), d.end());
    if (d.size() > k) d.resize(k);
    return d;
}

TEST(KdTree, KNearestEqualsBruteForce) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (size_t n : {0u, 1u, 2u, 5u, 64u, 1000u, 5000u}) {
        auto tree = buildKdTree(randomPhotons(n, static_cast<uint32_t>(n) + 1), n > 1000);
        for (size_t k : {1u, 2u, 10u, 50u, 500u, 6000u}) {
            std::vector<PhotonHit> hits(k);
            for (float maxDist2 : {std::numeric_limits<float>::infinity(), 0.05f}) {
                for (int trial = 0; trial < 20; ++trial) {
                    Vec3 q(u(rng), u(rng) * 0.5, u(rng) * 0.25);
                    Vec3 nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
                    const Vec3* np = trial % 2 ? &nrm : nullptr;
                    size_t found = findNearestPhotons(tree, q, np, maxDist2, hits);
                    auto want = bruteForce(tree, q, np, maxDist2, k);
                    ASSERT_EQ(found, want.size()) << "n=" << n << " k=" << k;
                    std::vector<float> got;
                    for (size_t i = 0; i < found; ++i) {
                        got.push_back(hits[i].dist2);
                        // Max-heap on dist2.
                        if (i) {
                            ASSERT_LE(hits[i].dist2, hits[(i - 1) / 2].dist2);
                        }
                        // Each hit's distance is that of the photon it names.
                        const Photon& p = tree[hits[i].index];
                        const float dx = float(q.x) - p.pos[0], dy = float(q.y) - p.pos[1],
                                    dz = float(q.z) - p.pos[2];
                        ASSERT_EQ(hits[i].dist2, dx * dx + dy * dy + dz * dz);
                    }
                    std::sort(got.begin(), got.end());
                    ASSERT_EQ(got, want) << "n=" << n << " k=" << k << " trial=" << trial;
                }
            }
        }
    }
}

TEST(KdTree, SingleNearestEqualsBruteForce) {
    auto tree = buildKdTree(randomPhotons(3000, 77), false);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int t = 0; t < 200; ++t) {
        Vec3 q(u(rng), u(rng), u(rng));
        Vec3 nrm = normalize(Vec3(u(rng), u(rng), u(rng)));
        float d2 = -1;
        int64_t idx = findNearestPhoton(tree, q, &nrm, 0.1f, &d2);
        auto want = bruteForce(tree, q, &nrm, 0.1f, 1);
        if (want.empty()) {
            EXPECT_EQ(idx, -1);
        } else {
            ASSERT_GE(idx, 0);
            EXPECT_EQ(d2, want[0]);
        }
    }
    EXPECT_EQ(findNearestPhoton(std::span<const Photon>(), Vec3(), nullptr, 1.0f), -1);
}

}  // namespace
}  // namespace rp::pmap
