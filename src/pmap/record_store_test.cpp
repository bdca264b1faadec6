// RecordStore: records come back in order from memory and from the spill file; a store
// spills once the shared budget is spent and gives its memory back; nothing is ever named
// in the folder.
#include "pmap/record_store.h"

#include <gtest/gtest.h>

#include <vector>

#include "pmap/photon.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

Photon numbered(uint32_t i) {
    Photon p;
    p.pos[0] = float(i);
    p.primary = i;
    return p;
}

template <class Store>
std::vector<uint32_t> idsOf(const Store& s) {
    std::vector<uint32_t> ids;
    s.forEachBlock([&](std::span<const Photon> b) {
        for (const Photon& p : b) ids.push_back(p.primary);
    });
    return ids;
}

std::vector<uint32_t> iota(uint32_t n) {
    std::vector<uint32_t> v(n);
    for (uint32_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

TEST(RecordStore, InMemoryKeepsOrder) {
    RecordStore<Photon> s;
    const uint32_t n = uint32_t(3 * RecordStore<Photon>::kMaxChunkRecords + 17);
    for (uint32_t i = 0; i < n; ++i) s.append(numbered(i));
    EXPECT_FALSE(s.spilled());
    EXPECT_EQ(s.size(), n);
    EXPECT_EQ(idsOf(s), iota(n));
    auto all = s.takeAll();
    ASSERT_EQ(all.size(), n);
    for (uint32_t i = 0; i < n; ++i) ASSERT_EQ(all[i].primary, i);
    EXPECT_EQ(s.size(), 0u);
}

TEST(RecordStore, SpillsPastTheBudgetAndKeepsOrder) {
    TempDir dir;
    MemoryBudget budget(1000 * sizeof(Photon));
    {
        RecordStore<Photon> s(&budget, dir.path().string(), "g.pm");
        for (uint32_t i = 0; i < 500; ++i) s.append(numbered(i));
        EXPECT_FALSE(s.spilled());
        EXPECT_GT(budget.used(), 0u);
        for (uint32_t i = 500; i < 20000; ++i) s.append(numbered(i));
        EXPECT_TRUE(s.spilled());
        EXPECT_LE(budget.used(), budget.limit());
        EXPECT_EQ(dir.count(), 0u);  // the spill file has no name
        EXPECT_EQ(idsOf(s), iota(20000));
        std::vector<uint32_t> drained;
        s.drain([&](std::span<const Photon> b) {
            for (const Photon& p : b) drained.push_back(p.primary);
        });
        EXPECT_EQ(drained, iota(20000));
        EXPECT_EQ(s.size(), 0u);
        EXPECT_FALSE(s.spilled());
        // The emptied store collects again (in memory: the budget is free).
        for (uint32_t i = 0; i < 100; ++i) s.append(numbered(i));
        EXPECT_EQ(idsOf(s), iota(100));
    }
    EXPECT_EQ(budget.used(), 0u);
    EXPECT_EQ(dir.count(), 0u);
}

TEST(RecordStore, StoresShareTheBudget) {
    TempDir dir;
    MemoryBudget budget(2000 * sizeof(Photon));
    RecordStore<Photon> a(&budget, dir.path().string(), "a.pm"),
        b(&budget, dir.path().string(), "b.pm");
    for (uint32_t i = 0; i < 1800; ++i) a.append(numbered(i));
    EXPECT_FALSE(a.spilled());
    for (uint32_t i = 0; i < 1000; ++i) b.append(numbered(i));
    EXPECT_TRUE(b.spilled());  // a holds most of the budget
    EXPECT_FALSE(a.spilled());
    TempFile f = b.takeFile();
    EXPECT_EQ(f.size(), 1000 * sizeof(Photon));
    std::vector<Photon> back(1000);
    f.readAt(0, back.data(), f.size());
    for (uint32_t i = 0; i < 1000; ++i) ASSERT_EQ(back[i].primary, i);
    auto all = a.takeAll();
    EXPECT_EQ(all.size(), 1800u);
    EXPECT_EQ(budget.used(), 0u);
}

}  // namespace
}  // namespace rp::pmap
