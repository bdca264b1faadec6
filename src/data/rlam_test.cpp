#include "data/rlam.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "util/error.h"

namespace rp::data {
namespace {

// Laminates in-memory inputs; returns the output and sets *premature.
std::string lam(std::vector<std::string> contents, const std::vector<RlamInput>& inputs,
                long limit = 0, bool* premature = nullptr) {
    std::vector<RlamStream> streams;
    for (size_t i = 0; i < inputs.size(); ++i)
        streams.push_back({fmemopen(contents[i].data(), contents[i].size(), "r"), &inputs[i]});
    char* buf = nullptr;
    size_t size = 0;
    std::FILE* out = open_memstream(&buf, &size);
    const RlamResult r = laminate(streams, limit, false, out);
    std::fclose(out);
    for (auto& s : streams) std::fclose(s.file);
    std::string result(buf, size);
    std::free(buf);
    if (premature) *premature = r.premature;
    return result;
}

TEST(Rlam, JoinsLinesWithEachInputsSeparator) {
    EXPECT_EQ(lam({"a\nb\n", "1\n2\n", "x\ny\n"}, {{"", "\t", 0}, {"", ",", 0}, {"", "::", 0}}),
              "a,1::x\nb,2::y\n");
}

TEST(Rlam, StopsInTheRecordWhereAnInputEnds) {
    // RADIANCE compat: the first input's third line is written, then the output ends.
    EXPECT_EQ(lam({"a\nb\nc\n", "1\n2\n"}, {{"", "\t", 0}, {"", "\t", 0}}), "a\t1\nb\t2\nc");
}

TEST(Rlam, UnterminatedLastLineLosesItsLastCharacter) {
    EXPECT_EQ(lam({"ab\ncd"}, {{"", "\t", 0}}), "ab\nc\n");
}

TEST(Rlam, SeveralLinesPerRecord) {
    EXPECT_EQ(lam({"1\n2\n3\n4\n", "a\nb\n"}, {{"", " ", -2}, {"", "|", 0}}), "1 2|a\n3 4|b\n");
}

TEST(Rlam, BinaryRecordsAndLimit) {
    RlamState s;
    s.setFormat("w2");
    EXPECT_EQ(s.recordBytes, 4);
    EXPECT_EQ(s.separator, "");
    bool premature = false;
    EXPECT_EQ(lam({"abcdefgh", "12"}, {{"", "", 4}, {"", "", 1}}, 0, &premature), "abcd1efgh2");
    EXPECT_FALSE(premature);
    EXPECT_EQ(lam({"abcdefgh"}, {{"", "", 4}}, 3, &premature), "abcdefgh");
    EXPECT_TRUE(premature);
    EXPECT_EQ(lam({"abcdefgh"}, {{"", "", 4}}, 1, &premature), "abcd");
    EXPECT_FALSE(premature);
}

TEST(Rlam, Formats) {
    RlamState s;
    s.setFormat("a3");
    EXPECT_EQ(s.recordBytes, -3);
    EXPECT_EQ(s.separator, "\t");
    s.setFormat("a1");
    EXPECT_EQ(s.recordBytes, 0);
    s.setFormat("d3");
    EXPECT_EQ(s.recordBytes, 24);
    s.setFormat("a");  // the separator stays cleared, as in RADIANCE
    EXPECT_EQ(s.separator, "");
    s.setSeparator("");
    EXPECT_EQ(s.separator, "\n");
    EXPECT_THROW(s.setFormat("q"), InputError);
    EXPECT_THROW(s.setFormat("d9000"), InputError);
}

TEST(Rlam, MissingFileIsAnError) {
    try {
        rlam({{"no/such/file", "\t", 0}}, 0, false, stdout);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "no/such/file: cannot open file");
    }
    EXPECT_THROW(rlam({}, 0, false, stdout), InputError);
}

}  // namespace
}  // namespace rp::data
