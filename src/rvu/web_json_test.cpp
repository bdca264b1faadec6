// The web display's JSON and query parsing: strings always come out as valid JSON with
// valid UTF-8 (escapes for quotes, backslashes and control characters, U+FFFD for bad
// bytes), objects keep their order and write non-finite numbers as null, /command answers
// have the documented shapes, and malformed "since"/"cursor" values are rejected
// without touching the caller's data.
#include "rvu/web_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace rp::rvu {
namespace {

using namespace std::string_literals;

bool isAscii(const std::string& s) {
    for (unsigned char c : s)
        if (c >= 0x80) return false;
    return true;
}

TEST(WebJsonString, EscapesQuotesBackslashesAndNewlines) {
    EXPECT_EQ(jsonString(""), R"("")");
    EXPECT_EQ(jsonString("plain text"), R"("plain text")");
    EXPECT_EQ(jsonString(R"(say "hi")"), R"("say \"hi\"")");
    EXPECT_EQ(jsonString(R"(C:\dir\)"), R"("C:\\dir\\")");
    EXPECT_EQ(jsonString("a\nb"), R"("a\nb")");
    EXPECT_EQ(jsonString("/ ' <>"), R"("/ ' <>")");  // nothing else escaped
}

TEST(WebJsonString, ControlCharactersAndDelAsUnicodeEscapes) {
    EXPECT_EQ(jsonString("\t"), R"("\u0009")");
    EXPECT_EQ(jsonString("\r"), R"("\u000d")");
    EXPECT_EQ(jsonString("\x1f"), R"("\u001f")");
    EXPECT_EQ(jsonString("\x7f"), R"("\u007f")");
    EXPECT_EQ(jsonString("a\0b"s), R"("a\u0000b")");
    EXPECT_EQ(jsonString(" ~"), R"(" ~")");  // 0x20 and 0x7e are plain
}

TEST(WebJsonString, ValidUtf8IsKept) {
    for (const std::string s :
         {"\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "\xef\xbf\xbf", "\xf4\x8f\xbf\xbf",
          "caf\xc3\xa9 \xe2\x82\xac"
          "5"})
        EXPECT_EQ(jsonString(s), "\"" + s + "\"") << s;
}

TEST(WebJsonString, InvalidAndTruncatedBytesBecomeReplacement) {
    EXPECT_EQ(jsonString("\x80"), R"("\ufffd")");  // lone continuation
    EXPECT_EQ(jsonString("a\xff"
                         "b"),
              R"("a\ufffdb")");  // never valid
    EXPECT_EQ(jsonString("\xf8\x88\x80\x80\x80"), R"("\ufffd\ufffd\ufffd\ufffd\ufffd")");
    EXPECT_EQ(jsonString("\xe2\x82"), R"("\ufffd\ufffd")");  // truncated at the end
    EXPECT_EQ(jsonString("\xe2\x82"
                         "A"),
              R"("\ufffd\ufffdA")");
    EXPECT_EQ(jsonString("\xf0\x9f\x98"), R"("\ufffd\ufffd\ufffd")");
    EXPECT_EQ(jsonString("\xc3"
                         "\""),
              R"("\ufffd\"")");  // a quote is never swallowed
}

TEST(WebJsonString, SequencesOutsideUtf8AreReplaced) {
    // RFC 3629: overlong forms, UTF-16 surrogates and code points above U+10FFFF are not
    // valid UTF-8 even though their bytes have the right high bits.
    for (const std::string s : {"\xc0\xaf", "\xc1\xbf", "\xe0\x80\xaf", "\xed\xa0\x80",
                                "\xf0\x80\x80\xaf", "\xf4\x90\x80\x80", "\xf5\x80\x80\x80"}) {
        const std::string j = jsonString(s);
        EXPECT_TRUE(isAscii(j)) << j;
        EXPECT_NE(j.find("\\ufffd"), std::string::npos) << j;
    }
}

TEST(WebJsonObject, KeepsOrderWithCommas) {
    EXPECT_EQ(JsonObject().text(), "{}");
    JsonObject j;
    j.add("b", "x");
    j.add("a", 1.0);
    j.add("c", true);
    j.add("d", false);
    j.add("e", std::string("q\""));
    EXPECT_EQ(j.text(), R"({"b":"x","a":1,"c":true,"d":false,"e":"q\""})");
    JsonObject k;
    k.add("we\"ird\n", "v");
    EXPECT_EQ(k.text(), R"({"we\"ird\n":"v"})");
}

TEST(WebJsonObject, NumbersShortestRoundTripAndNonFiniteNull) {
    auto one = [](double v) {
        JsonObject j;
        j.add("n", v);
        return j.text();
    };
    EXPECT_EQ(one(0), R"({"n":0})");
    EXPECT_EQ(one(42), R"({"n":42})");
    EXPECT_EQ(one(-2.5), R"({"n":-2.5})");
    EXPECT_EQ(one(0.1), R"({"n":0.1})");
    EXPECT_EQ(std::stod(one(1.0 / 3).substr(5)), 1.0 / 3);  // round trips
    EXPECT_EQ(one(std::numeric_limits<double>::quiet_NaN()), R"({"n":null})");
    EXPECT_EQ(one(std::numeric_limits<double>::infinity()), R"({"n":null})");
    EXPECT_EQ(one(-std::numeric_limits<double>::infinity()), R"({"n":null})");
    const std::string big = one(1e300);
    EXPECT_EQ(big.find_first_not_of("{}\"n:0123456789.e+-"), std::string::npos) << big;
}

TEST(WebJsonCommand, Shapes) {
    CommandResult ok;
    EXPECT_EQ(commandJson(ok), R"({"ok":true,"output":""})");
    ok.output = "VIEW= -vtv\n";
    EXPECT_EQ(commandJson(ok), R"({"ok":true,"output":"VIEW= -vtv\n"})");
    CommandResult err;
    err.ok = false;
    err.error = "bad \"x\"";
    EXPECT_EQ(commandJson(err), R"({"ok":false,"error":"bad \"x\""})");
    err.output = "partial";
    EXPECT_EQ(commandJson(err), R"({"ok":false,"output":"partial","error":"bad \"x\""})");
    CommandResult pick;
    pick.pick = "Pick view center";
    pick.points = 2;
    EXPECT_EQ(commandJson(pick), R"({"ok":true,"output":"","pick":"Pick view center","points":2})");
    CommandResult quit;
    quit.quit = true;
    EXPECT_EQ(commandJson(quit), R"({"ok":true,"output":"","quit":true})");
    EXPECT_EQ(errorJson("no\nway"), R"({"ok":false,"error":"no\nway"})");
}

TEST(WebJsonGeneration, DecimalOrZero) {
    EXPECT_EQ(parseGeneration("0"), 0u);
    EXPECT_EQ(parseGeneration("42"), 42u);
    EXPECT_EQ(parseGeneration("18446744073709551615"), 18446744073709551615ull);
    EXPECT_EQ(parseGeneration("18446744073709551616"), 0u);  // overflow
    EXPECT_EQ(parseGeneration("-1"), 0u);
    EXPECT_EQ(parseGeneration(""), 0u);
    EXPECT_EQ(parseGeneration("12x"), 0u);
    EXPECT_EQ(parseGeneration("x12"), 0u);
    EXPECT_EQ(parseGeneration("1.5"), 0u);
    EXPECT_EQ(parseGeneration("0x10"), 0u);
}

TEST(WebJsonGeneration, DigitsOnly) {
    // "a decimal generation; anything else counts as 0": strtoull's leading blanks and
    // '+' are not digits. " -1" (since=+-1 in a query) must not wrap to 2^64 - 1, which
    // would make /state wait its full 10 s instead of answering at once.
    EXPECT_EQ(parseGeneration(" 12"), 0u);
    EXPECT_EQ(parseGeneration("+12"), 0u);
    EXPECT_EQ(parseGeneration(" -1"), 0u);
}

TEST(WebJsonCursor, TwoOrFourIntegers) {
    std::vector<Cursor> out{{9, 9}, {9, 9}, {9, 9}};
    ASSERT_TRUE(parseCursor("12,34", out));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].x, 12);
    EXPECT_EQ(out[0].y, 34);
    ASSERT_TRUE(parseCursor("1,2,-3,4", out));
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].x, 1);
    EXPECT_EQ(out[0].y, 2);
    EXPECT_EQ(out[1].x, -3);
    EXPECT_EQ(out[1].y, 4);
    ASSERT_TRUE(parseCursor("1000000,-1000000", out));
    EXPECT_EQ(out[0].x, 1000000);
    EXPECT_EQ(out[0].y, -1000000);
}

TEST(WebJsonCursor, RejectsMalformedAndLeavesOutputAlone) {
    for (const char* bad :
         {"", "1", "1,2,3", "1,2,3,4,5", "1,,2", "1,2,", ",1,2", "a,b", "1;2", "1,2x", "1.5,2",
          "1000001,0", "0,-1000001", "99999999999999999999,1", "1,2,3,4,"}) {
        std::vector<Cursor> out{{7, 8}};
        EXPECT_FALSE(parseCursor(bad, out)) << '"' << bad << '"';
        ASSERT_EQ(out.size(), 1u) << bad;
        EXPECT_EQ(out[0].x, 7) << bad;
        EXPECT_EQ(out[0].y, 8) << bad;
    }
}

TEST(WebJsonCursor, RejectsBlanks) {
    // "integers; false otherwise": strtol's leading blanks are not part of an integer.
    for (const char* bad : {" 1,2", "1, 2", "1,2, 3,4", "\t1,2"}) {
        std::vector<Cursor> out;
        EXPECT_FALSE(parseCursor(bad, out)) << '"' << bad << '"';
        EXPECT_TRUE(out.empty()) << bad;
    }
}

}  // namespace
}  // namespace rp::rvu
