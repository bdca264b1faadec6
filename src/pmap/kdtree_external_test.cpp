// The external kd-tree build against the in-core one: with budgets of a few hundred
// photons, on photon sets with many equal coordinates (photons on the walls of a box),
// repeated records and sizes that are no power of two, the tree is valid and identical to
// buildKdTree's (the same photons, so also the same multiset); every node is written once;
// no temporary file is ever named in the folder, after success or an error.
#include "pmap/kdtree_external.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/kdtree_select.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

// A heap in memory, counting the writes per node.
class MemorySink : public HeapSink {
public:
    explicit MemorySink(size_t n) : heap(n), writes(n) {}
    void write(uint64_t first, std::span<const Photon> photons) override {
        ASSERT_GE(first, 1u);
        ASSERT_LE(first - 1 + photons.size(), heap.size());
        for (size_t i = 0; i < photons.size(); ++i) {
            heap[first - 1 + i] = photons[i];
            ++writes[first - 1 + i];
        }
    }
    std::vector<Photon> heap;
    std::vector<int> writes;
};

// n photons on the six walls of a 4 x 3 x 2.5 room (one coordinate on a wall, the others
// on a coarse grid half the time, so that whole positions repeat), every tenth record a
// copy of an earlier one.
std::vector<Photon> roomPhotons(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float size[3] = {4.0f, 3.0f, 2.5f};
    std::vector<Photon> v(n);
    for (size_t i = 0; i < n; ++i) {
        if (i >= 10 && i % 10 == 0) {
            v[i] = v[i / 2];
            continue;
        }
        Photon& p = v[i];
        for (int a = 0; a < 3; ++a)
            p.pos[a] = u(rng) < 0.5f ? std::floor(u(rng) * 8) * size[a] / 8 : u(rng) * size[a];
        const int wall = int(u(rng) * 6) % 6;
        p.pos[wall / 2] = wall % 2 ? size[wall / 2] : 0.0f;
        p.norm[wall / 2] = wall % 2 ? -127 : 127;
        p.setFlux(u(rng), u(rng), u(rng));
        p.setCaustic(u(rng) < 0.2f);
        p.primary = uint32_t(i % 7);
    }
    return v;
}

TempFile fileOf(const TempDir& dir, const std::vector<Photon>& photons) {
    TempFile f(dir.path().string(), "test.pm");
    f.append(photons.data(), photons.size() * sizeof(Photon));
    return f;
}

std::vector<Photon> externalTree(const TempDir& dir, const std::vector<Photon>& in, uint64_t inCore,
                                 bool parallel) {
    MemorySink sink(in.size());
    float lo[3], hi[3];
    photonBounds(in, lo, hi);
    ExternalBuildSettings s{inCore, dir.path().string(), "test.pm", parallel};
    buildKdTreeExternal(fileOf(dir, in), in.size(), lo, hi, sink, s);
    for (size_t i = 0; i < in.size(); ++i) EXPECT_EQ(sink.writes[i], 1) << "node " << i + 1;
    return sink.heap;
}

bool sameMultiset(std::vector<Photon> a, std::vector<Photon> b) {
    for (auto* v : {&a, &b}) {
        for (Photon& p : *v) p.setDiscr(0);
        std::sort(v->begin(), v->end(),
                  [](const Photon& x, const Photon& y) { return photonKeyLess(x, y, 0); });
    }
    return a == b;
}

TEST(KdTreeExternal, SameTreeAsInCore) {
    TempDir dir;
    for (size_t n : {1u, 2u, 3u, 999u, 1000u, 1001u, 4097u, 25013u}) {
        const auto in = roomPhotons(n, uint32_t(n));
        const auto inCore = buildKdTree(in, false);
        for (uint64_t budget : {uint64_t{1000}, uint64_t{37}}) {
            const auto ext = externalTree(dir, in, budget, n > 5000);
            ASSERT_EQ(checkKdTree(ext), "") << n << " " << budget;
            ASSERT_TRUE(sameMultiset(in, ext)) << n << " " << budget;
            EXPECT_TRUE(std::equal(ext.begin(), ext.end(), inCore.begin(), inCore.end()))
                << n << " " << budget;
        }
        EXPECT_EQ(dir.count(), 0u);
    }
}

TEST(KdTreeExternal, AllPhotonsAtOnePoint) {
    // Only the records' other fields order them (and identical records are shared out).
    TempDir dir;
    std::vector<Photon> in(3001);
    for (size_t i = 0; i < in.size(); ++i) {
        for (float& x : in[i].pos) x = 1.5f;
        in[i].primary = uint32_t(i % 5);
    }
    const auto ext = externalTree(dir, in, 100, true);
    EXPECT_EQ(checkKdTree(ext), "");
    EXPECT_TRUE(sameMultiset(in, ext));
    const auto inCore = buildKdTree(in, true);
    EXPECT_TRUE(std::equal(ext.begin(), ext.end(), inCore.begin(), inCore.end()));
}

TEST(KdTreeExternal, WriteSubtreeHeapIsTheGather) {
    for (size_t n : {1u, 6u, 1000u, 40000u}) {
        auto in = roomPhotons(n, 5);
        const auto heap = buildKdTree(in, false);
        buildKdTreeInOrder(in, false);
        MemorySink sink(n);
        writeSubtreeHeap(in, 1, sink, true);
        EXPECT_TRUE(std::equal(heap.begin(), heap.end(), sink.heap.begin(), sink.heap.end()));
        for (int w : sink.writes) ASSERT_EQ(w, 1);
    }
}

// A sink that fails after a few writes, checking on each that nothing is named in the
// folder while the parts' files are in use.
class FailingSink : public HeapSink {
public:
    FailingSink(const TempDir& dir, int failAt) : dir_(dir), left_(failAt) {}
    void write(uint64_t, std::span<const Photon>) override {
        EXPECT_EQ(dir_.count(), 0u);
        if (--left_ == 0) throw std::runtime_error("disk on fire");
    }

private:
    const TempDir& dir_;
    int left_;
};

TEST(KdTreeExternal, NoTemporaryFileLeftAfterAnError) {
    TempDir dir;
    const auto in = roomPhotons(5000, 9);
    float lo[3], hi[3];
    photonBounds(in, lo, hi);
    ExternalBuildSettings s{200, dir.path().string(), "test.pm", false};
    for (int failAt : {1, 5, 40}) {
        FailingSink sink(dir, failAt);
        EXPECT_THROW(buildKdTreeExternal(fileOf(dir, in), in.size(), lo, hi, sink, s),
                     std::runtime_error);
        EXPECT_EQ(dir.count(), 0u);
    }
}

}  // namespace
}  // namespace rp::pmap
