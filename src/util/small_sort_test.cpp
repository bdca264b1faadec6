// stableSortSmall against std::stable_sort: the same order, ties included, on both sides
// of the insertion-sort cut-off.
#include "util/small_sort.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

namespace rp {
namespace {

TEST(StableSortSmall, SameOrderAsStableSortWithTies) {
    std::mt19937 rng(3);
    const auto byKey = [](const std::pair<int, int>& a, const std::pair<int, int>& b) {
        return a.first > b.first;  // descending, as the direct calculation sorts
    };
    for (int n = 0; n <= 3 * kSmallSort; ++n)
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<std::pair<int, int>> v(static_cast<size_t>(n));
            for (int i = 0; i < n; ++i) v[size_t(i)] = {int(rng() % 5), i};  // many ties
            auto want = v;
            std::stable_sort(want.begin(), want.end(), byKey);
            stableSortSmall(v.begin(), v.end(), byKey);
            ASSERT_EQ(v, want) << "n " << n;
        }
}

}  // namespace
}  // namespace rp
