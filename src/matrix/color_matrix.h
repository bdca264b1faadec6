// dctimestep's RGB matrices (RADIANCE cmatrix.h CMATRIX): three float components per
// element, loaded with the sizes and format the caller expects (cm_load), multiplied in
// double (cm_multiply) and written as RADIANCE writes them (cm_write). rmtxop's general
// matrices are matrix.h's.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "matrix/matrix_format.h"
#include "matrix/matrix_input.h"

namespace rp::matrix {

struct ColorMatrix {
    int rows = 0, cols = 0;
    std::vector<float> values;  // rows*cols RGB triples, row by row

    ColorMatrix() = default;
    ColorMatrix(int r, int c) : rows(r), cols(c), values(static_cast<size_t>(r) * c * 3, 0.f) {}
    float* at(int r, int c) { return values.data() + (static_cast<size_t>(r) * cols + c) * 3; }
    const float* at(int r, int c) const {
        return values.data() + (static_cast<size_t>(r) * cols + c) * 3;
    }
    ColorMatrix column(int c) const;  // cm_column
};

// cm_load: `rows`/`cols` 0 for "from the header" (or from the data's length for rows),
// `type` FromHeader to take the header's FORMAT=. The header is read unless both the type
// and the column count are given (dctimestep -n). Throws InputError naming the input for
// a header that contradicts what is expected, NCOMP other than 3, short data.
ColorMatrix loadColorMatrix(const std::string& spec, int rows, int cols, DataType type);
ColorMatrix parseColorMatrix(const InputData& in, int rows, int cols, DataType type);

// cm_multiply: a.cols == b.rows, else InputError naming the two inputs.
ColorMatrix multiply(const ColorMatrix& a, const ColorMatrix& b, const std::string& what);

// cm_write: ASCII "%.6e %.6e %.6e" with tabs between columns, raw floats or doubles, or
// a picture (resolution string and RLE scanlines).
void writeColorMatrix(std::ostream& out, const ColorMatrix& m, DataType type);

}  // namespace rp::matrix
