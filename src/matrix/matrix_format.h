// The data formats of RADIANCE's matrix files (cmatrix.h's DTascii..DTdouble) and the
// header lines every writer of them shares: FORMAT=, BigEndian= (CAPDATE=/GMT= are
// util/header.h's). The matrices themselves live in matrix.h (rmtxop's general matrices) and
// color_matrix.h (dctimestep's RGB ones); reading inputs in matrix_input.h.
#pragma once

#include <string>

namespace rp::matrix {

// RADIANCE compat (cmatrix.h): the order matters. When two matrices meet, the result
// keeps the lower of the two (rmatrix.c rmx_newtype): float beats ascii beats double.
enum class DataType { FromHeader = 0, Rgbe, Xyze, Float, Ascii, Double };

// "ascii", "float", "double", "32-bit_rle_rgbe", "32-bit_rle_xyze"; "unknown" for FromHeader.
const char* formatName(DataType t);
// The type a FORMAT= value names; FromHeader for any other value.
DataType parseFormatName(const std::string& name);
bool isPicture(DataType t);
// Bytes per component in a binary file (0 for ascii and pictures).
int componentBytes(DataType t);

// The type of a result made from two matrices (rmx_newtype); FromHeader when a picture
// meets anything but its own kind.
DataType combinedType(DataType a, DataType b);

// "BigEndian=0\n" (or 1): RADIANCE 5.4's byte-order line (header.c fputendian), written
// before FORMAT=float and FORMAT=double.
std::string byteOrderLine();
// True (with `swap` set) when `line` is a BigEndian= line (header.c isbigendian); `swap`
// says whether data written that way must be byte-swapped here.
bool parseByteOrderLine(const std::string& line, bool& swap);

}  // namespace rp::matrix
