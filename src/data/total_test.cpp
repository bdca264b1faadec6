// total: sums, products, extremes, means, batches at blank lines and every N records.
// Expected values are the arithmetic of the inputs (total(1)).
#include "data/total.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

namespace rp::data {
namespace {

std::string run(TotalOptions o, const std::string& input) {
    Total t(o);
    std::istringstream in(input);
    std::ostringstream out;
    t.run(in, out);
    return out.str();
}

TEST(Total, SumsColumnsOfRaggedRecords) {
    EXPECT_EQ(run({}, "1\t2\n3\n0.5 0.25 7\n"), "4.5\t2.25\t7\n");
}

TEST(Total, BlankLineEndsABatchTwoEndTheFile) {
    EXPECT_EQ(run({}, "1\n2\n\n5\n\n\n9\n"), "3\n5\n");
}

TEST(Total, ProductMaxMinAndMeans) {
    TotalOptions o;
    o.func = TotalOptions::Func::Multiply;
    EXPECT_EQ(run(o, "2\t-3\n4\t0\n"), "8\t0\n");
    o.mean = true;  // geometric mean
    EXPECT_EQ(run(o, "2\n8\n"), "4\n");
    o = {};
    o.func = TotalOptions::Func::Max;
    EXPECT_EQ(run(o, "2\t-3\n4\t-5\n"), "4\t-3\n");
    o.func = TotalOptions::Func::Min;
    EXPECT_EQ(run(o, "2\t-3\n4\t-5\n"), "2\t-5\n");
    o = {};
    o.power = 2;  // root mean square
    o.mean = true;
    EXPECT_EQ(run(o, "3\n-4\n3\n-4\n"), "3.53553391\n");
}

TEST(Total, CountAndRunningTotals) {
    TotalOptions o;
    o.count = 2;
    EXPECT_EQ(run(o, "1\n2\n3\n4\n5\n"), "3\n7\n5\n");
    o.subtotal = true;
    EXPECT_EQ(run(o, "1\n2\n3\n4\n5\n"), "3\n10\n15\n");
}

TEST(Total, EmptyFieldsWithASeparator) {
    TotalOptions o;
    o.separator = ',';
    EXPECT_EQ(run(o, "1,,3\n,2,\n"), "1,2,3\n");
}

TEST(Total, BinaryFloatsInDoublesOut) {
    TotalOptions o;
    o.binaryColumns = -2;
    o.binaryOutput = 1;
    const float in[4] = {1, 2, 3, 4};
    std::string out = run(o, std::string(reinterpret_cast<const char*>(in), sizeof in));
    ASSERT_EQ(out.size(), 2 * sizeof(double));
    double d[2];
    std::memcpy(d, out.data(), sizeof d);
    EXPECT_EQ(d[0], 4.0);
    EXPECT_EQ(d[1], 6.0);
}

TEST(Total, OutputLimitStops) {
    TotalOptions o;
    o.count = 1;
    o.outputLimit = 2;
    Total t(o);
    std::istringstream in("1\n2\n3\n");
    std::ostringstream out;
    EXPECT_FALSE(t.run(in, out));
    EXPECT_EQ(out.str(), "1\n2\n");
    EXPECT_TRUE(t.done());
}

}  // namespace
}  // namespace rp::data
