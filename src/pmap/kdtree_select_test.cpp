// Histogram median selection in place: the rank-k photon is std::sort's on the whole key
// (photonKeyLess), the partition holds, the photons are kept, on random sets with many
// ties, signed zeros, negative, huge and subnormal values; a tree does not depend on the
// order of its input.
#include "pmap/kdtree_select.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "pmap/kdtree.h"

namespace rp::pmap {
namespace {

// n photons whose coordinates come from `pick` (primary = input index, to check the set).
template <class Pick>
std::vector<Photon> photonsFrom(size_t n, Pick pick) {
    std::vector<Photon> v(n);
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) v[i].pos[a] = pick();
        v[i].primary = static_cast<uint32_t>(i);
    }
    return v;
}

// Selects rank k on `axis` and checks the result against a copy sorted on the whole key
// (primary = input index makes every key distinct, so rank k is one photon).
void checkSelect(const std::vector<Photon>& in, size_t k, int axis) {
    std::vector<Photon> r = in;
    float lo[3], hi[3];
    photonBounds(in, lo, hi);
    selectRank(r.data(), r.size(), k, axis, lo[axis], hi[axis]);
    std::vector<Photon> sorted = in;
    std::sort(sorted.begin(), sorted.end(),
              [axis](const Photon& a, const Photon& b) { return photonKeyLess(a, b, axis); });
    ASSERT_EQ(r[k].primary, sorted[k].primary) << "n=" << in.size() << " k=" << k;
    const float m = r[k].pos[axis];
    for (size_t i = 0; i < k; ++i) {
        ASSERT_LE(r[i].pos[axis], m) << i;
        ASSERT_TRUE(photonKeyLess(r[i], r[k], axis)) << i;
    }
    for (size_t i = k + 1; i < in.size(); ++i) {
        ASSERT_GE(r[i].pos[axis], m) << i;
        ASSERT_TRUE(photonKeyLess(r[k], r[i], axis)) << i;
    }
    std::vector<uint32_t> ids;
    for (size_t i = 0; i < in.size(); ++i) ids.push_back(r[i].primary);
    std::sort(ids.begin(), ids.end());
    for (size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i);
}

TEST(KdTreeSelect, RandomSetsWithManyTiesMatchSort) {
    std::mt19937 rng(7);
    for (size_t n : {2u, 3u, 7u, 24u, 25u, 100u, 1000u, 5000u, 70000u}) {
        // Few distinct values (walls: photons sharing a coordinate), with signed zeros.
        std::uniform_int_distribution<int> few(-3, 3);
        auto ties = photonsFrom(n, [&] { return few(rng) == 0 ? -0.0f : few(rng) * 0.5f; });
        // Continuous values plus a big block of one value.
        std::uniform_real_distribution<float> u(-2.0f, 6.0f);
        auto mixed = photonsFrom(n, [&] { return u(rng) < 2.0f ? 5.5f : u(rng); });
        // All equal.
        auto same = photonsFrom(n, [] { return 1.25f; });
        for (size_t k : {size_t{0}, n / 2, n - 1, n / 3}) {
            checkSelect(ties, k, 0);
            checkSelect(mixed, k, 1);
            checkSelect(same, k, 2);
        }
    }
}

TEST(KdTreeSelect, WideRangeAndTinyValues) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> e(-30.0f, 30.0f), s(-1.0f, 1.0f);
    auto wide = photonsFrom(20000, [&] { return s(rng) * std::pow(10.0f, e(rng)); });
    for (size_t k : {size_t{0}, size_t{9999}, size_t{19999}}) checkSelect(wide, k, 0);
    // Ranges that overflow float (falls back to nth_element) and subnormal values.
    auto huge = photonsFrom(5000, [&] { return s(rng) * 3e38f; });
    checkSelect(huge, 2500, 1);
    auto tiny = photonsFrom(5000, [&] { return s(rng) * 1e-43f; });
    checkSelect(tiny, 2500, 2);
}

TEST(KdTreeSelect, TwoValuesAndSortedInputs) {
    // Two distinct values (the pivots can bracket every photon) and sorted / reversed
    // input (the strided sample sees the extremes only at its ends).
    for (size_t n : {33u, 1000u, 50000u}) {
        size_t i = 0;
        auto two = photonsFrom(n, [&] { return (i++ % 5) < 2 ? 1.0f : 2.0f; });
        auto up = photonsFrom(n, [&] { return static_cast<float>(i++ / 3); });
        auto down = photonsFrom(n, [&] { return -static_cast<float>(i++ / 3); });
        for (size_t k : {size_t{0}, n / 2, n - 1, 2 * n / 5, 2 * n / 5 - 1}) {
            checkSelect(two, k, 0);
            checkSelect(up, k, 1);
            checkSelect(down, k, 2);
        }
    }
}

TEST(KdTreeSelect, LooseBoundsStillSplit) {
    // Bounds far wider than the photons (a narrowed cell can be much larger than its
    // photons' extent): the first histogram puts everything in one bucket.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(1.0f, 1.0001f);
    auto in = photonsFrom(3000, [&] { return u(rng); });
    std::vector<Photon> r = in;
    selectRank(r.data(), in.size(), 1500, 0, -1e6f, 1e6f);
    std::vector<float> sorted;
    for (const Photon& p : in) sorted.push_back(p.pos[0]);
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(r[1500].pos[0], sorted[1500]);
    for (size_t i = 0; i < 1500; ++i) ASSERT_LE(r[i].pos[0], r[1500].pos[0]);
    for (size_t i = 1501; i < in.size(); ++i) ASSERT_GE(r[i].pos[0], r[1500].pos[0]);
}

TEST(KdTreeSelect, SmallRangeWithNaNKeepsEveryPhoton) {
    // Outside selectRank's contract (finite positions), but a NaN must not make the
    // small-range sort drop or duplicate photons.
    for (size_t n : {5u, 24u}) {
        float next = 0;
        auto in = photonsFrom(n, [&] { return next += 1.0f; });
        in[1].pos[0] = std::numeric_limits<float>::quiet_NaN();
        for (Photon& p : in) p.primary += 7;  // no id is 0, as a zeroed record would be
        std::vector<Photon> r = in;
        selectRank(r.data(), n, n / 2, 0, 0, 1e3f);
        std::vector<uint32_t> ids;
        for (size_t i = 0; i < n; ++i) ids.push_back(r[i].primary);
        std::sort(ids.begin(), ids.end());
        for (size_t i = 0; i < n; ++i) ASSERT_EQ(ids[i], i + 7) << "n=" << n;
    }
}

TEST(KdTreeSelect, KeyOrdersCoordinatesThenRecord) {
    Photon a, b;
    a.pos[0] = b.pos[0] = 1.0f;
    a.pos[1] = 2.0f;
    b.pos[1] = -3.0f;
    EXPECT_TRUE(photonKeyLess(b, a, 0));   // x ties, y decides
    EXPECT_TRUE(photonKeyLess(b, a, 1));   // on y
    EXPECT_FALSE(photonKeyLess(a, b, 2));  // z ties, then x ties, then y
    b.pos[1] = 2.0f;
    b.primary = 1;
    EXPECT_TRUE(photonKeyLess(a, b, 2));  // same position: the rest of the record
    b.primary = 0;
    b.setDiscr(2);
    EXPECT_FALSE(photonKeyLess(a, b, 0));  // the split axis does not count
    EXPECT_FALSE(photonKeyLess(b, a, 0));
    b.pos[2] = -0.0f;  // signed zeros compare equal, as floats
    EXPECT_FALSE(photonKeyLess(a, b, 2));
    EXPECT_FALSE(photonKeyLess(b, a, 2));
    EXPECT_LT(orderedFloatBits(-1.0f), orderedFloatBits(-0.5f));
    EXPECT_LT(orderedFloatBits(-0.5f), orderedFloatBits(0.0f));
    EXPECT_LT(orderedFloatBits(0.0f), orderedFloatBits(1e-40f));
    EXPECT_LT(orderedFloatBits(1e-40f), orderedFloatBits(3.0f));
}

TEST(KdTreeSelect, TreeWithManyTiesIsValid) {
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> few(0, 4);
    std::uniform_real_distribution<float> u(0.0f, 5.5f);
    // Photons on the six walls of a box: one coordinate 0 or 5.5, the others continuous.
    auto box = photonsFrom(50000, [&] { return u(rng); });
    for (size_t i = 0; i < box.size(); ++i) box[i].pos[i % 3] = few(rng) < 2 ? 0.0f : 5.5f;
    auto tree = buildKdTree(box, false);
    EXPECT_EQ(checkKdTree(tree), "");
    EXPECT_EQ(tree, buildKdTree(box, true));
    // Ties are broken by the record, not by the input order: any order, the same tree.
    std::shuffle(box.begin(), box.end(), rng);
    EXPECT_EQ(tree, buildKdTree(box, true));
    std::reverse(box.begin(), box.end());
    EXPECT_EQ(tree, buildKdTree(box, false));
}

}  // namespace
}  // namespace rp::pmap
