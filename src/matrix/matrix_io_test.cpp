// Reading and writing rmtxop's matrix files: the formats, byte order, pictures, and one
// test per kind of bad input (each a one-line InputError naming the input).
#include "matrix/matrix_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

#include "matrix/color_matrix.h"
#include "util/error.h"

namespace rp::matrix {
namespace {

Matrix parse(const std::string& text) { return parseMatrix({"m.mtx", text}); }

std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(MatrixIo, AsciiWithHeaderKeepsOtherLinesAsInfo) {
    const Matrix m =
        parse("#?RADIANCE\nNOTE= hi\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 2\n");
    EXPECT_EQ(m.rows, 1);
    EXPECT_EQ(m.cols, 2);
    EXPECT_EQ(m.values, (std::vector<double>{1, 2}));
    EXPECT_EQ(m.info, "NOTE= hi\n");
    EXPECT_EQ(m.type, DataType::Ascii);
}

TEST(MatrixIo, FloatBigEndianIsSwapped) {
    std::string text = "#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=2\nBigEndian=1\nFORMAT=float\n\n";
    const float v[2] = {1.5f, -2.f};
    for (float f : v) {
        char b[4];
        std::memcpy(b, &f, 4);
        text.append({b[3], b[2], b[1], b[0]});  // this machine is little-endian
    }
    const Matrix m = parse(text);
    EXPECT_EQ(m.values, (std::vector<double>{1.5, -2}));
    EXPECT_EQ(m.type, DataType::Float);
}

TEST(MatrixIo, PictureExposureIsUndone) {
    // One flat pixel (1,1,1 in RGBE: 128,128,128 exponent 129) with EXPOSURE=2.
    std::string text = "#?RADIANCE\nEXPOSURE=2\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n";
    text += std::string{'\x80', '\x80', '\x80', '\x81'};
    const Matrix m = parse(text);
    ASSERT_EQ(m.comps, 3);
    EXPECT_NEAR(m.values[0], (128.5 / 128) / 2, 1e-7);
}

TEST(MatrixIo, WritesRadianceAsciiLayout) {
    Matrix m(1, 2, 1);
    m.values = {0.5, 2};
    m.type = DataType::Float;  // float inputs print with 8 digits
    std::ostringstream out;
    writeMatrix(out, m, DataType::Ascii);
    EXPECT_EQ(out.str(),
              "NROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n 5.0000000e-01\t 2.0000000e+00\t\n");
    std::ostringstream bin;
    writeMatrix(bin, m, DataType::Double);
    EXPECT_NE(bin.str().find("BigEndian=0\nFORMAT=double\n\n"), std::string::npos);
    EXPECT_EQ(bin.str().size(), bin.str().find("\n\n") + 2 + 16);
}

TEST(MatrixIo, BadHeader) {
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=1\n"),
              "m.mtx: bad header (no information header ended by an empty line)");
    EXPECT_EQ(errorOf("#?RADIANCE\nFORMAT=text\n\n"), "m.mtx: unknown data format 'text'");
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=1\nNCOLS=1\n\n1 2 3\n"),
              "m.mtx: missing NCOMP= in header");
    EXPECT_EQ(errorOf("#?RADIANCE\nNCOMP=3\n\n1 2 3\n"),
              "m.mtx: missing NROWS= or NCOLS= in header (and no picture resolution)");
}

TEST(MatrixIo, ImpossibleSizeIsRefusedBeforeAllocating) {
    // Fuzzing found it: 455555551 x 3 x 3 doubles (32 GB) for a few bytes of data.
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=455555551\nNCOLS=3\nNCOMP=3\nFORMAT=ascii\n\n1 2 3\n"),
              "m.mtx:7: header declares 455555551x3x3 values, but only 6 bytes of data follow");
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=-2\nNCOLS=3\nNCOMP=3\nFORMAT=ascii\n\n1 2 3\n"),
              "m.mtx: missing NROWS= or NCOLS= in header (and no picture resolution)");
}

TEST(MatrixIo, ImpossibleColumnCountIsRefusedByTheRgbReader) {
    // Fuzzing found it too: dctimestep's reader grew a row of 798 million RGB values.
    try {
        parseColorMatrix({"m.mtx", "#?RADIANCE\nNCOLS=798000000\nNCOMP=3\nFORMAT=ascii\n\n1 2 3\n"},
                         0, 0, DataType::FromHeader);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("header declares"), std::string::npos) << e.what();
    }
}

TEST(MatrixIo, ShortAsciiDataNamesTheLine) {
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=2\nNCOLS=1\nNCOMP=2\n\n1 2\n3\n"),
              "m.mtx:7: unexpected end of data: 3 of 4 values (2x1x2)");
    EXPECT_EQ(errorOf("#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=1\n\nx\n"), "m.mtx:6: bad number 'x'");
}

TEST(MatrixIo, ShortBinaryDataNamesTheRecord) {
    const std::string text = "#?RADIANCE\nNROWS=2\nNCOLS=1\nNCOMP=1\nFORMAT=double\n\n12345678";
    EXPECT_EQ(errorOf(text), "m.mtx: unexpected end of data at record 2 of 2 (2x1, double)");
}

TEST(MatrixIo, PictureOfFourComponentsIsRefused) {
    Matrix m(1, 1, 4);
    std::ostringstream out;
    EXPECT_THROW(writeMatrix(out, m, DataType::Rgbe), InputError);
}

}  // namespace
}  // namespace rp::matrix
