// rmtxop's matrix operations: sizes, values and the info lines RADIANCE's rmatrix.c adds.
// Expected values are plain arithmetic of the inputs.
#include "matrix/matrix.h"

#include <gtest/gtest.h>

#include "matrix/rmtxop.h"
#include "util/error.h"

namespace rp::matrix {
namespace {

Matrix make(int r, int c, int n, std::vector<double> v, std::string info = "") {
    Matrix m(r, c, n);
    m.values = std::move(v);
    m.info = std::move(info);
    m.type = DataType::Ascii;
    return m;
}

TEST(Matrix, TransposeAddsInfoOnlyToMatricesWithInfo) {
    const Matrix m = make(2, 3, 1, {1, 2, 3, 4, 5, 6}, "NOTE= x\n");
    const Matrix t = transposed(m);
    EXPECT_EQ(t.rows, 3);
    EXPECT_EQ(t.cols, 2);
    EXPECT_EQ(t.values, (std::vector<double>{1, 4, 2, 5, 3, 6}));
    EXPECT_EQ(t.info, "NOTE= x\nTransposed rows and columns\n");
    const Matrix v = transposed(make(1, 3, 1, {1, 2, 3}, "NOTE= v\n"));
    EXPECT_EQ(v.info, "NOTE= v\n");  // a vector only swaps its sizes
    EXPECT_EQ(transposed(make(2, 2, 1, {1, 2, 3, 4})).info, "");
}

TEST(Matrix, ProductPerComponentWithoutInfo) {
    const Matrix a = make(1, 2, 2, {1, 2, 3, 4}, "NOTE= a\n");
    Matrix b = make(2, 1, 2, {5, 6, 7, 8});
    b.type = DataType::Float;
    const Matrix p = product(a, b);
    EXPECT_EQ(p.values, (std::vector<double>{1 * 5 + 3 * 7, 2 * 6 + 4 * 8}));
    EXPECT_EQ(p.info, "");
    EXPECT_EQ(p.type, DataType::Float);  // float beats ascii
}

TEST(Matrix, TypesCombineAsRadianceRanksThem) {
    EXPECT_EQ(combinedType(DataType::Ascii, DataType::Double), DataType::Ascii);
    EXPECT_EQ(combinedType(DataType::Double, DataType::Float), DataType::Float);
    EXPECT_EQ(combinedType(DataType::Rgbe, DataType::Rgbe), DataType::Rgbe);
    EXPECT_EQ(combinedType(DataType::Rgbe, DataType::Ascii), DataType::FromHeader);
    Matrix a = make(1, 1, 3, {1, 2, 3});
    a.type = DataType::Rgbe;
    addTo(a, make(1, 1, 3, {1, 1, 1}));
    EXPECT_EQ(a.info, kTypeMismatchInfo);
    EXPECT_EQ(a.type, DataType::Rgbe);
}

TEST(Matrix, DivisionByZeroZeroesAndWarnsInInfo) {
    Matrix a = make(1, 2, 3, {2, 4, 6, 1, 1, 1});
    EXPECT_EQ(multiplyElements(a, make(1, 2, 1, {2, 0}), true), 1);
    EXPECT_EQ(a.values, (std::vector<double>{1, 2, 3, 0, 0, 0}));
    EXPECT_EQ(a.info, kZeroDivideInfo);
    Matrix b = make(1, 1, 3, {2, 4, 6});
    EXPECT_EQ(multiplyElements(b, make(1, 1, 3, {2, 2, 0.5}), false), 0);
    EXPECT_EQ(b.values, (std::vector<double>{4, 8, 3}));
}

TEST(Matrix, ScaleAndComponentTransform) {
    Matrix a = make(1, 2, 2, {1, 2, 3, 4}, "NOTE= a\n");
    scale(a, {10, 100});
    EXPECT_EQ(a.values, (std::vector<double>{10, 200, 30, 400}));
    EXPECT_EQ(a.info, "NOTE= a\nApplied scalar\n");
    const Matrix t = transformComponents(make(1, 1, 2, {1, 2}, "N\n"), {1, 1, 2, 0, 0, 3});
    EXPECT_EQ(t.comps, 3);
    EXPECT_EQ(t.values, (std::vector<double>{3, 2, 6}));
    EXPECT_EQ(t.info, "N\nApplied 3x2 component transform\n");
}

// rmtxop -rf / -rb (RADIANCE compat): the next operand, if an XML BSDF, is read as its
// front or back reflection; the choice does not carry over to the operand after it.
TEST(Rmtxop, ReflectionChoiceBelongsToTheNextOperand) {
    RmtxopCommand c = parseRmtxopArgs({"-rf", "a.xml", "b.xml", "-rb", "-t", "c.xml"});
    ASSERT_EQ(c.operands.size(), 3u);
    EXPECT_EQ(c.operands[0].part, bsdf::MatrixPart::ReflectionFront);
    EXPECT_EQ(c.operands[1].part, bsdf::MatrixPart::Transmission);
    EXPECT_EQ(c.operands[2].part, bsdf::MatrixPart::ReflectionBack);
    EXPECT_TRUE(c.operands[2].ops.transpose);
    EXPECT_THROW(parseRmtxopArgs({"-rx", "a.xml"}), InputError);
}

}  // namespace
}  // namespace rp::matrix
