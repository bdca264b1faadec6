// rcalc's engine: columns in, channels out, cond/recno/outno, formats and binary forms.
// Expected texts follow from rcalc(1)'s rules (tab-separated "%.9g", one line a record).
#include "calc/rcalc.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

namespace rp::calc {
namespace {

std::string run(RcalcOptions o, const std::string& input) {
    Rcalc r(o, {});
    std::istringstream in(input);
    std::ostringstream out;
    r.run(in, "test", out);
    return out.str();
}

RcalcOptions withExpr(const std::string& e) {
    RcalcOptions o;
    o.sources.emplace_back(false, e);
    return o;
}

TEST(Rcalc, ColumnsToChannels) {
    EXPECT_EQ(run(withExpr("$1=$2*2;$3=$1+recno"), "1\t2\n10\t0.5\n"), "4\t\t2\n1\t\t12\n");
}

TEST(Rcalc, CondSkipsRecordsAndOutnoCountsOutputs) {
    EXPECT_EQ(run(withExpr("cond=$1-1;$1=recno;$2=outno"), "1\n2\n0\n5\n"), "2\t1\n4\t2\n");
}

TEST(Rcalc, InCountsColumnsAndNonNumbersReadAsZero) {
    EXPECT_EQ(run(withExpr("$1=in(0);$2=$2;$3=$9"), "1 abc\t3\n"), "3\t0\t0\n");
}

TEST(Rcalc, InputAndOutputLimits) {
    RcalcOptions o = withExpr("$1=$1");
    o.inputLimit = 2;
    EXPECT_EQ(run(o, "1\n2\n3\n"), "1\n2\n");
    o = withExpr("cond=$1-1;$1=$1");
    o.outputLimit = 1;
    EXPECT_EQ(run(o, "1\n2\n3\n"), "2\n");
}

TEST(Rcalc, NoInputGivesOneRecord) {
    RcalcOptions o = withExpr("$2=PI");
    o.noInput = true;
    Rcalc r(o, {});
    std::ostringstream out;
    r.runNoInput(out);
    EXPECT_EQ(out.str(), "\t3.14159265\n");
}

TEST(Rcalc, BinaryDoublesInFloatsOut) {
    RcalcOptions o = withExpr("$1=$2;$2=in(0);$3=$4");
    o.inputType = 'd';
    o.binaryColumns = 2;
    o.outputType = 'f';
    const double in[4] = {1, 2, 3, 4};
    std::string bytes(reinterpret_cast<const char*>(in), sizeof in);
    std::string out = run(o, bytes + "xyz");  // a short last record is not read
    ASSERT_EQ(out.size(), 6 * sizeof(float));
    float f[6];
    std::memcpy(f, out.data(), sizeof f);
    EXPECT_EQ(f[0], 2.f);
    EXPECT_EQ(f[1], 2.f);
    EXPECT_EQ(f[2], 0.f);  // channel 4 beyond the record
    EXPECT_EQ(f[3], 4.f);
}

TEST(Rcalc, FormatsMatchSkipAndPrint) {
    RcalcOptions o;
    o.inputFormat = "v=${v} s=$(s)";
    o.hasInputFormat = true;
    o.outputFormat = "$(s) ${v*2}";
    o.hasOutputFormat = true;
    // "$(s)" is 4 wide: the string is right-adjusted; numbers fill "${v*2}" (6) by %6g.
    EXPECT_EQ(run(o, "v=1.5 s=ab\nnoise\nv=4 s=c\n"), "  ab      3\n   c      8\n");
    o.passive = true;  // the unmatched line goes through
    EXPECT_EQ(run(o, "v=1.5 s=ab\nnoise\n"), "  ab      3\nnoise\n");
}

TEST(Rcalc, StringPresetSelectsRecords) {
    RcalcOptions o;
    o.inputFormat = "${v} $(s)";
    o.hasInputFormat = true;
    o.outputFormat = "${v}";
    o.hasOutputFormat = true;
    o.presets.push_back("s=yes");
    EXPECT_EQ(run(o, "1 yes\n2 no\n3 yes\n"), "   1\n   3\n");  // "${v}" is 4 wide
}

TEST(Rcalc, ErrorsNameTheInputAndRecord) {
    try {
        run(withExpr("$1=$1+nothing"), "1\n");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "test: record 1: line 1: undefined variable 'nothing'");
    }
    RcalcOptions o;
    o.inputFormat = "a $x";
    o.hasInputFormat = true;
    EXPECT_THROW(Rcalc(o, {}), InputError);
}

TEST(RecordFormat, FieldsWidthsAndFinalNewline) {
    // "$$" is one dollar sign; the text after it stays literal up to the next '$'.
    auto f = parseRecordFormat("a$$b ${ x + 1 }$(s)", false);
    ASSERT_EQ(f.size(), 5u);
    EXPECT_EQ(f[0].text, "a");
    EXPECT_EQ(f[1].text, "$b ");
    EXPECT_EQ(f[1].width, 3);
    EXPECT_EQ(f[2].type, FormatField::Type::Number);
    EXPECT_EQ(f[2].text, "x+1");
    EXPECT_EQ(f[2].width, 10);  // "${ x + 1 }"
    EXPECT_EQ(f[3].type, FormatField::Type::String);
    EXPECT_EQ(f[4].text, "\n");
    EXPECT_EQ(parseRecordFormat("${x}", true).size(), 1u);  // -l: no newline added
}

}  // namespace
}  // namespace rp::calc
