// Reading and writing RADIANCE matrix files as rmtxop does (rmatrix.c rmx_load and
// rmx_write): a header with NROWS= NCOLS= NCOMP= FORMAT= (ascii, float, double, or a
// picture's 32-bit_rle_rgbe / 32-bit_rle_xyze, whose size comes from the resolution
// string), BigEndian= byte swapping, EXPOSURE=/COLORCORR= undone for pictures; the other
// header lines become the matrix's info. dctimestep's float RGB matrices are in
// color_matrix.h.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "bsdf/bsdf.h"
#include "matrix/matrix.h"
#include "matrix/matrix_input.h"

namespace rp::matrix {

// Loads a matrix from a file, "-" or "!command". Throws InputError naming the input (and
// the line for ASCII data): bad or unterminated header, unknown FORMAT, missing sizes,
// short data. A file named *.xml is a Klems BSDF (RADIANCE rmx_load): `part` of it as
// bsdf::klemsCoefficients gives it, three components, ASCII.
Matrix loadMatrix(const std::string& spec, bsdf::MatrixPart part = bsdf::MatrixPart::Transmission);
// The coefficients of `spec` if it names an XML BSDF file (by its suffix, as RADIANCE
// decides), else nothing.
std::optional<bsdf::CoefficientMatrix> loadBsdfMatrix(const std::string& spec,
                                                      bsdf::MatrixPart part);
// The same from data already read.
Matrix parseMatrix(const InputData& in);

// Writes the info, the size lines (NROWS/NCOLS/NCOMP, except for pictures), BigEndian= for
// binary data, FORMAT= and the empty line, then the data. `type` FromHeader keeps the
// matrix's own; Rgbe becomes Xyze for XYZ data (rmx_write). Throws InputError for a
// picture of neither one nor three components. The caller writes "#?RADIANCE" and the
// command line before.
void writeMatrix(std::ostream& out, const Matrix& m, DataType type);

}  // namespace rp::matrix
