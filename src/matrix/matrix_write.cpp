// Writing rmtxop's matrices (matrix_io.h writeMatrix), following RADIANCE rmatrix.c
// rmx_write.
#include <cstdio>
#include <cstring>

#include "image/rgbe.h"
#include "matrix/matrix_io.h"
#include "matrix/picture_data.h"
#include "util/error.h"

namespace rp::matrix {

namespace {

// RADIANCE compat (rmatrix.c findCIEprims): PRIMARIES= naming the XYZ "primaries" makes
// an RGBE output an XYZE one.
bool hasXyzPrimaries(const std::string& info) {
    const size_t at = info.find("PRIMARIES=");
    if (at == std::string::npos) return false;
    double p[8];
    if (std::sscanf(info.c_str() + at + 10, "%lf %lf %lf %lf %lf %lf %lf %lf", &p[0], &p[1], &p[2],
                    &p[3], &p[4], &p[5], &p[6], &p[7]) != 8)
        return false;
    return p[0] > .99 && p[1] < .01 && p[2] < .01 && p[3] > .99 && p[4] < .01 && p[5] < .01;
}

void writeAscii(std::ostream& out, const Matrix& m) {
    // RADIANCE compat (rmx_write_ascii): the precision follows the matrix's input type,
    // not the output format.
    const char* fmt = m.type == DataType::Float ? " %.7e" : isPicture(m.type) ? " %.3e" : " %.15e";
    std::string s;
    char buf[64];
    for (int i = 0; i < m.rows; ++i) {
        for (int j = 0; j < m.cols; ++j) {
            for (int k = 0; k < m.comps; ++k)
                s.append(buf,
                         static_cast<size_t>(std::snprintf(buf, sizeof buf, fmt, m.at(i, j, k))));
            s += '\t';
        }
        s += '\n';
        out.write(s.data(), static_cast<std::streamsize>(s.size()));
        s.clear();
    }
}

void writeBinary(std::ostream& out, const Matrix& m, DataType type) {
    if (type == DataType::Double) {
        out.write(reinterpret_cast<const char*>(m.values.data()),
                  static_cast<std::streamsize>(m.values.size() * sizeof(double)));
        return;
    }
    std::vector<float> f(m.values.begin(), m.values.end());
    out.write(reinterpret_cast<const char*>(f.data()),
              static_cast<std::streamsize>(f.size() * sizeof(float)));
}

}  // namespace

void writeMatrix(std::ostream& out, const Matrix& m, DataType type) {
    if (type == DataType::FromHeader)
        type = m.type;
    else if (type == DataType::Rgbe && (m.type == DataType::Xyze || hasXyzPrimaries(m.info)))
        type = DataType::Xyze;
    else if (type == DataType::Xyze && m.type == DataType::Rgbe)
        type = DataType::Rgbe;
    if (isPicture(type) && m.comps != 3 && m.comps != 1)
        throw InputError("cannot write a " + std::to_string(m.comps) +
                         "-component matrix as a picture (1 or 3 components only)");
    std::string head = m.info;
    if (!isPicture(type))
        head += "NROWS=" + std::to_string(m.rows) + "\nNCOLS=" + std::to_string(m.cols) +
                "\nNCOMP=" + std::to_string(m.comps) + "\n";
    if (type == DataType::Float || type == DataType::Double) head += byteOrderLine();
    head += std::string("FORMAT=") + formatName(type) + "\n\n";
    out << head;
    switch (type) {
        case DataType::Ascii:
            writeAscii(out, m);
            break;
        case DataType::Float:
        case DataType::Double:
            writeBinary(out, m, type);
            break;
        default: {  // one component: grey
            if (m.comps == 3) {
                writePictureData(out, m.rows, m.cols, m.values.data());
                break;
            }
            std::vector<double> rgb(m.values.size() * 3);
            for (size_t e = 0; e < m.values.size(); ++e)
                rgb[e * 3] = rgb[e * 3 + 1] = rgb[e * 3 + 2] = m.values[e];
            writePictureData(out, m.rows, m.cols, rgb.data());
            break;
        }
    }
}

}  // namespace rp::matrix
