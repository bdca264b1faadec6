// RADIANCE data files: regular and listed axes, multilinear interpolation, RADIANCE's
// extrapolation beyond the ends, and file:line errors for malformed input.
#include "calc/data_file.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace rp::calc {
namespace {

std::string errorOf(const std::string& text) {
    try {
        DataFile::parse(text, "bad.dat");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(CalcDataFile, OneDimensionRegular) {
    auto d = DataFile::parse("1\n0 10 3\n1 3 7\n", "a.dat");
    EXPECT_EQ(d.dimensions(), 1);
    auto at = [&](double x) { return d.value(std::vector<double>{x}); };
    EXPECT_DOUBLE_EQ(at(0), 1);
    EXPECT_DOUBLE_EQ(at(2.5), 2);
    EXPECT_DOUBLE_EQ(at(5), 3);
    EXPECT_DOUBLE_EQ(at(7.5), 5);
    EXPECT_DOUBLE_EQ(at(10), 7);
    // One division beyond the end: linear extrapolation (7 + 4 per 5 units).
    EXPECT_DOUBLE_EQ(at(12.5), 9);
    EXPECT_DOUBLE_EQ(at(15), 11);
    // Further out: (2*y1 - y0) / (x - (i-1)) in index units, tapering to zero.
    EXPECT_DOUBLE_EQ(at(20), (2 * 7 - 3) / (4.0 - 0));
    EXPECT_DOUBLE_EQ(at(-5), 1 - 2);
    EXPECT_DOUBLE_EQ(at(-10), (2 * 1 - 3) / 2.0);
    // Far away the taper goes to zero; the sample index is clamped before it becomes an
    // int (it overflowed one before: undefined behaviour, found by fuzz_data_file).
    EXPECT_NEAR(at(1e300), 0, 1e-290);
    EXPECT_NEAR(at(-1e300), 0, 1e-290);
    EXPECT_TRUE(std::isnan(at(std::nan(""))));
}

TEST(CalcDataFile, CommentsWhereverANumberMayStand) {
    // As glass_illR.dat and rect_fixture.dat write them: a header comment, comments
    // after axis lines, between values and glued to a number.
    auto d = DataFile::parse(
        "# from RADIANCE test/renders\n1 # one axis\n0 10 3#regular\n"
        "1 # first\n3#second\n# a line\n7\n# trailing",
        "m.dat");
    EXPECT_EQ(d.dimensions(), 1);
    EXPECT_DOUBLE_EQ(d.value(std::vector<double>{5}), 3);
    EXPECT_DOUBLE_EQ(d.value(std::vector<double>{10}), 7);
}

TEST(CalcDataFile, ListedAxis) {
    auto d = DataFile::parse("1\n0 0 4  0 1 3 7\n0 10 30 70\n", "b.dat");
    auto at = [&](double x) { return d.value(std::vector<double>{x}); };
    EXPECT_DOUBLE_EQ(at(0.5), 5);
    EXPECT_DOUBLE_EQ(at(2), 20);
    EXPECT_DOUBLE_EQ(at(5), 50);
    EXPECT_DOUBLE_EQ(at(7), 70);
    EXPECT_DOUBLE_EQ(at(9), 90);  // one division past the end (width 4)
    // Decreasing coordinates work the same way.
    auto e = DataFile::parse("1\n0 0 3  4 2 0\n40 20 0\n", "c.dat");
    EXPECT_DOUBLE_EQ(e.value(std::vector<double>{3}), 30);
    EXPECT_DOUBLE_EQ(e.value(std::vector<double>{0.5}), 5);
}

TEST(CalcDataFile, TwoAndThreeDimensions) {
    // f(x, y) = x + 10 y on x in {0,1,2}, y in {0, 5}: bilinear reproduces it.
    auto d = DataFile::parse("2\n0 2 3\n0 0 2 0 5\n0 50\n1 51\n2 52\n", "d.dat");
    for (double x : {0.0, 0.3, 1.0, 1.7, 2.0})
        for (double y : {0.0, 1.0, 2.5, 5.0})
            EXPECT_NEAR(d.value(std::vector<double>{x, y}), x + 10 * y, 1e-12);
    // Trilinear: f = x + 2y + 4z on the unit cube corners.
    auto t = DataFile::parse("3\n0 1 2\n0 1 2\n0 1 2\n0 4 2 6 1 5 3 7\n", "t.dat");
    EXPECT_NEAR(t.value(std::vector<double>{0.5, 0.25, 0.75}), 0.5 + 0.5 + 3, 1e-12);
    EXPECT_NEAR(t.value(std::vector<double>{1, 1, 1}), 7, 1e-12);
}

TEST(CalcDataFile, MalformedFiles) {
    EXPECT_EQ(errorOf("x"), "bad.dat:1: expected number of dimensions, found 'x'");
    EXPECT_EQ(errorOf("0"), "bad.dat:1: number of dimensions must be a positive integer");
    EXPECT_EQ(errorOf("1\n0 1 2.5\n1 2 3"),
              "bad.dat:2: axis point count must be a positive integer");
    EXPECT_EQ(errorOf("1\n0 1 3\n1\n2\n"),
              "bad.dat:4: unexpected end of file: expected data value");
    EXPECT_EQ(errorOf("1\n0 1 2\n1 2\n3\n"),
              "bad.dat:4: more data than the axes declare (2 values)");
    EXPECT_EQ(errorOf("1\n0 0 3 0 2 1\n1 2 3"), "bad.dat:2: axis 1 coordinates are not monotonic");
    EXPECT_EQ(errorOf("1\n0 1 2\n1 zz"), "bad.dat:3: expected data value, found 'zz'");
    EXPECT_EQ(errorOf("9\n"), "bad.dat:1: too many dimensions (9, at most 8)");
    EXPECT_EQ(errorOf("# c\n1 # d\n0 1 2\n1 #2\n"),
              "bad.dat:4: unexpected end of file: expected data value");
    EXPECT_EQ(errorOf("1\n0 1 2\n1 2 # end\n#\n3"),
              "bad.dat:5: more data than the axes declare (2 values)");
    // Declaring 2^31 values in a few bytes fails at the end of the text, without
    // reserving 16 GB first (the fuzzer's out-of-memory finding).
    EXPECT_EQ(errorOf("2\n0 1 46341\n0 1 46340\n1 2\n"),
              "bad.dat:4: unexpected end of file: expected data value");
}

TEST(CalcDataFile, MissingFile) { EXPECT_THROW(DataFile::load("/nonexistent/x.dat"), InputError); }

}  // namespace
}  // namespace rp::calc
