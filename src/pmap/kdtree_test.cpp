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

// Large trees are checked in parallel subtrees: damage in either half is found, and the
// message (the smaller misplaced node) does not depend on which task finished first.
TEST(KdTree, ParallelOrderCheckFindsDamageInEitherHalf) {
    const auto tree = buildKdTree(randomPhotons(300000, 21), true);
    EXPECT_EQ(checkKdTreeOrder(tree), "");
    for (size_t i : {size_t{70000}, size_t{200000}}) {  // under the left and right halves
        auto broken = tree;
        std::swap(broken[i], broken[i + 4000]);
        const std::string a = checkKdTreeOrder(broken), b = checkKdTreeOrder(broken);
        EXPECT_NE(a, "") << i;
        EXPECT_EQ(a, b);
    }
}

}  // namespace
}  // namespace rp::pmap
