#include "util/data_words.h"

#include <gtest/gtest.h>

namespace rp {
namespace {

TEST(DataWords, CommentsRunToEndOfLineAnywhere) {
    auto w = splitDataWords("# header\n2 0 1 3 # axis\n1.5#peak\n\t-2e-1 #\n#last");
    ASSERT_EQ(w.size(), 6u);
    EXPECT_EQ(w[0].text, "2");
    EXPECT_EQ(w[0].line, 2);
    EXPECT_EQ(w[3].text, "3");
    EXPECT_EQ(w[4].text, "1.5");
    EXPECT_EQ(w[4].line, 3);
    EXPECT_EQ(w[5].text, "-2e-1");
    EXPECT_EQ(w[5].line, 4);
}

TEST(DataWords, EmptyAndCommentOnly) {
    EXPECT_TRUE(splitDataWords("").empty());
    EXPECT_TRUE(splitDataWords("  # only a comment 1 2 3\n\n").empty());
}

}  // namespace
}  // namespace rp
