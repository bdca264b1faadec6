// dctimestep's RGB matrices and file-name patterns: loading with expected sizes, products
// in RADIANCE's precision, and the errors for headers that contradict the expectation.
#include "matrix/color_matrix.h"

#include <gtest/gtest.h>

#include <sstream>

#include "matrix/dctimestep.h"
#include "util/error.h"

namespace rp::matrix {
namespace {

const std::string kSky = "#?RADIANCE\nNROWS=2\nNCOLS=1\nNCOMP=3\nFORMAT=ascii\n\n1 2 3\n4 5 6\n";

std::string errorOf(const std::string& text, int rows, int cols, DataType t) {
    try {
        parseColorMatrix({"s.mtx", text}, rows, cols, t);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(ColorMatrix, LoadsAndMultiplies) {
    const ColorMatrix s = parseColorMatrix({"s", kSky}, 0, 0, DataType::FromHeader);
    ASSERT_EQ(s.rows, 2);
    const ColorMatrix v = parseColorMatrix({"v", "1 1 1 2 2 2\n"}, 1, 2, DataType::Ascii);
    const ColorMatrix r = multiply(v, s, "v");
    EXPECT_EQ(r.values, (std::vector<float>{9, 12, 15}));
    std::ostringstream out;
    writeColorMatrix(out, r, DataType::Ascii);
    EXPECT_EQ(out.str(), "9.000000e+00 1.200000e+01 1.500000e+01\n");
}

TEST(ColorMatrix, UnknownRowCountReadsToTheEnd) {
    const ColorMatrix m = parseColorMatrix({"x", "1 2 3\n4 5 6\n7 8 9\n"}, 0, 1, DataType::Ascii);
    EXPECT_EQ(m.rows, 3);
}

TEST(ColorMatrix, HeaderContradictions) {
    EXPECT_EQ(errorOf(kSky, 3, 0, DataType::FromHeader),
              "s.mtx: unexpected row count in header (2, expected 3)");
    EXPECT_EQ(errorOf(kSky, 0, 0, DataType::Float),
              "s.mtx: unexpected data format in header (ascii, expected float)");
    EXPECT_EQ(errorOf("#?RADIANCE\nNCOMP=1\n\n", 0, 0, DataType::FromHeader),
              "s.mtx: unexpected # components (must be 3)");
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=1\n\n", 0, 0, DataType::FromHeader),
              "s.mtx: missing/unknown data format in header");
    EXPECT_EQ(errorOf("1 2 3\n4 5\n", 2, 1, DataType::Ascii),
              "s.mtx:2: unexpected EOF: 1 of 2 RGB values");
}

TEST(ColorMatrix, MismatchedProduct) {
    const ColorMatrix a(2, 3), b(2, 1);
    EXPECT_THROW(multiply(a, b, "a.mtx"), InputError);
}

TEST(Dctimestep, NumberPatterns) {
    EXPECT_TRUE(hasNumberFormat("dc%03d.hdr"));
    EXPECT_FALSE(hasNumberFormat("100%%.hdr"));
    EXPECT_FALSE(hasNumberFormat("name%s"));
    EXPECT_EQ(formatNumber("dc%03d.hdr", 7), "dc007.hdr");
    EXPECT_EQ(formatNumber("a%%%x", 255), "a%ff");
    EXPECT_THROW(formatNumber("%s%d", 1), InputError);
}

}  // namespace
}  // namespace rp::matrix
