// The pixel part of Radiance pictures read and written as matrices: the standard
// resolution string and RLE scanlines (image/rgbe.h's codecs) from and to memory. The
// header is the matrix code's.
#pragma once

#include <ostream>
#include <vector>

#include "matrix/matrix_input.h"
#include "util/colr.h"

namespace rp::matrix {

// "-Y rows +X cols\n", then each row as RADIANCE's fwritecolrs (setcolr of the doubles).
// `rgb` holds rows*cols triples, top row first.
void writePictureData(std::ostream& out, int rows, int cols, const double* rgb);

// rows scanlines of cols pixels at the reader's position, as freadcolrs, or flat
// 4-byte pixels when `flat` (dctimestep's check for old flat files). Throws InputError
// naming the input and scanline for short or corrupt data.
std::vector<Colr> readScanlines(DataReader& r, int rows, int cols, bool flat);

}  // namespace rp::matrix
