// Matrix files as rmtxop, rcollate and dctimestep read them: RADIANCE headers (NROWS,
// NCOLS, NCOMP, FORMAT, byte order), ASCII and binary data, pictures; then a transpose,
// an ASCII write and the RGB load dctimestep makes.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "matrix/color_matrix.h"
#include "matrix/matrix.h"
#include "matrix/matrix_io.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const rp::matrix::InputData in{"fuzz.mtx",
                                   std::string(reinterpret_cast<const char*>(data), size)};
    try {
        rp::matrix::Matrix m = rp::matrix::parseMatrix(in);
        if (m.values.size() < 100000) {
            std::ostringstream out;
            rp::matrix::writeMatrix(out, m, rp::matrix::DataType::Ascii);
        }
    } catch (const rp::InputError&) {
    }
    try {
        (void)rp::matrix::parseColorMatrix(in, 0, 0, rp::matrix::DataType::FromHeader);
    } catch (const rp::InputError&) {
    }
    return 0;
}
