// cnt: the odometer's lines, RADIANCE's leading tab, and its zero and negative counts.
#include "data/cnt.h"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace rp::data {
namespace {

std::string counts(std::vector<int> n) {
    std::ostringstream out;
    writeCounts(n, out);
    return out.str();
}

TEST(Cnt, LastCounterTurnsFastest) {
    EXPECT_EQ(counts({2, 3}), "\t0\t0\n\t0\t1\n\t0\t2\n\t1\t0\n\t1\t1\n\t1\t2\n");
    EXPECT_EQ(counts({3}), "\t0\n\t1\n\t2\n");
}

TEST(Cnt, ZeroEndsTheListNegativeGivesNothing) {
    EXPECT_EQ(counts({}), "\n");
    EXPECT_EQ(counts({2, 0, 3}), "\t0\n\t1\n");
    EXPECT_EQ(counts({-2, 3}), "");
}

}  // namespace
}  // namespace rp::data
