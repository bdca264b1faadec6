// RADIANCE's general component matrix (rmatrix.h RMATRIX) and the operations rmtxop
// applies to it: transpose, product, element-wise product and quotient, sum, scaling
// and component transforms. Each operation also keeps the "info" header text the way
// rmatrix.c does, since rmtxop writes it out. Files are matrix_io.h's business.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "matrix/matrix_format.h"

namespace rp::matrix {

struct Matrix {
    int rows = 0, cols = 0, comps = 0;
    DataType type = DataType::Double;  // the input's format, which picks the output's
    std::string info;                  // header lines to copy (each ends in '\n')
    std::vector<double> values;        // row by row, element by element, component last

    Matrix() = default;
    Matrix(int r, int c, int n)
        : rows(r), cols(c), comps(n), values(static_cast<size_t>(r) * c * n, 0.0) {}

    double& at(int r, int c, int k) {
        return values[(static_cast<size_t>(r) * cols + c) * comps + k];
    }
    double at(int r, int c, int k) const {
        return values[(static_cast<size_t>(r) * cols + c) * comps + k];
    }
    // "146x145" or "146x145x3": for messages.
    std::string sizeText() const;
};

// RADIANCE compat (rmatrix.c): what the operations append to the info text.
constexpr const char* kTypeMismatchInfo = "WARNING: data type mismatch\n";
constexpr const char* kZeroDivideInfo = "WARNING: zero divide(s) corrupted results\n";

// rmx_transpose: a vector keeps its info as it is; otherwise "Transposed rows and
// columns" is added to info that exists.
Matrix transposed(const Matrix& m);
// rmx_multiply: a.cols == b.rows and a.comps == b.comps (checked by the caller). The sums
// run in long double from the last term to the first, as RADIANCE's do; the result has
// no info but the mismatch warning.
Matrix product(const Matrix& a, const Matrix& b);
// rmx_elemult: same size, and b with 1 or a.comps components. Division by a zero element
// sets the result to 0; returns the number of such divisions (then kZeroDivideInfo is in
// a's info).
int multiplyElements(Matrix& a, const Matrix& b, bool divide);
// rmx_sum: same size and components.
void addTo(Matrix& sum, const Matrix& add);
// rmx_scale: one factor per component; "Applied scalar" is added to info that exists.
void scale(Matrix& m, const std::vector<double>& perComponent);
// rmx_transform: coef.size() / m.comps new components, each a weighted sum of the old.
Matrix transformComponents(const Matrix& m, const std::vector<double>& coef);

}  // namespace rp::matrix
