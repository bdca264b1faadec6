// Matrix file formats and shared header lines (see matrix_format.h).
#include "matrix/matrix_format.h"

#include <bit>
#include <cctype>

namespace rp::matrix {

const char* formatName(DataType t) {
    switch (t) {
        case DataType::Rgbe:
            return "32-bit_rle_rgbe";
        case DataType::Xyze:
            return "32-bit_rle_xyze";
        case DataType::Float:
            return "float";
        case DataType::Ascii:
            return "ascii";
        case DataType::Double:
            return "double";
        case DataType::FromHeader:
            break;
    }
    return "unknown";
}

DataType parseFormatName(const std::string& name) {
    for (DataType t :
         {DataType::Rgbe, DataType::Xyze, DataType::Float, DataType::Ascii, DataType::Double})
        if (name == formatName(t)) return t;
    return DataType::FromHeader;
}

bool isPicture(DataType t) { return t == DataType::Rgbe || t == DataType::Xyze; }

int componentBytes(DataType t) { return t == DataType::Float ? 4 : t == DataType::Double ? 8 : 0; }

DataType combinedType(DataType a, DataType b) {
    if ((isPicture(a) || isPicture(b)) && a != b) return DataType::FromHeader;
    return static_cast<int>(a) < static_cast<int>(b) ? a : b;
}

std::string byteOrderLine() {
    return std::endian::native == std::endian::big ? "BigEndian=1\n" : "BigEndian=0\n";
}

bool parseByteOrderLine(const std::string& line, bool& swap) {
    // RADIANCE compat (header.c isbigendian): white space may surround the '='; any value
    // other than one starting with '1' means little-endian.
    const std::string key = "BigEndian";
    if (line.compare(0, key.size(), key) != 0) return false;
    size_t i = key.size();
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i >= line.size() || line[i] != '=') return false;
    ++i;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const bool big = i < line.size() && line[i] == '1';
    swap = big != (std::endian::native == std::endian::big);
    return true;
}

}  // namespace rp::matrix
