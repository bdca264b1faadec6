#include "util/cluster.h"

#include <gtest/gtest.h>

#include "util/thread_cluster_for_tests.h"

namespace rp {
namespace {

TEST(Cluster, SlicesCoverInOrderAndDifferByOneAtMost) {
    for (size_t n : {0u, 1u, 2u, 7u, 100u, 101u})
        for (int size = 1; size <= 5; ++size) {
            size_t next = 0, lo = n, hi = 0;
            for (int r = 0; r < size; ++r) {
                const Slice s = sliceOf(n, r, size);
                EXPECT_EQ(s.begin, next) << n << " " << size << " " << r;
                next = s.end;
                lo = std::min(lo, s.end - s.begin);
                hi = std::max(hi, s.end - s.begin);
            }
            EXPECT_EQ(next, n);
            EXPECT_LE(hi - lo, 1u);
        }
}

TEST(Cluster, BytesRoundTrip) {
    ByteWriter w;
    w.put(uint64_t(42));
    w.putVector(std::vector<float>{1.5f, -2.f});
    w.putString("rays\n");
    w.put(true);
    ByteReader r(w.bytes());
    EXPECT_EQ(r.get<uint64_t>(), 42u);
    std::vector<float> v;
    r.getVector(v);
    EXPECT_EQ(v, (std::vector<float>{1.5f, -2.f}));
    EXPECT_EQ(r.getString(), "rays\n");
    EXPECT_TRUE(r.get<bool>());
    EXPECT_TRUE(r.done());
}

TEST(Cluster, LocalClusterIsOneRank) {
    LocalCluster c;
    EXPECT_EQ(c.size(), 1);
    EXPECT_TRUE(c.isRoot());
    EXPECT_FALSE(distributed(&c));
    EXPECT_FALSE(distributed(nullptr));
    std::vector<size_t> sizes;
    const std::byte b[2] = {std::byte(1), std::byte(2)};
    EXPECT_EQ(c.gather(b, sizes).size(), 2u);
    EXPECT_EQ(sizes, std::vector<size_t>{2});
    EXPECT_EQ(broadcastValue(&c, 7), 7);
}

TEST(Cluster, ThreadClusterGathersInRankOrder) {
    testing::runRanks(3, [](Cluster& c) {
        EXPECT_EQ(broadcastValue(&c, c.isRoot() ? 99 : -1), 99);
        ByteWriter w;
        w.put(c.rank());
        std::vector<size_t> sizes;
        const Bytes all = c.allGather(w.bytes(), sizes);
        ASSERT_EQ(sizes.size(), 3u);
        ByteReader r(all);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(r.get<int>(), k);
    });
}

}  // namespace
}  // namespace rp
