// Products and output of dctimestep's RGB matrices (color_matrix.h), after RADIANCE
// cmatrix.c cm_multiply and cm_write.
#include <cstdio>

#include "matrix/color_matrix.h"
#include "matrix/picture_data.h"
#include "util/error.h"

namespace rp::matrix {

ColorMatrix multiply(const ColorMatrix& a, const ColorMatrix& b, const std::string& what) {
    if (a.cols <= 0 || a.cols != b.rows)
        throw InputError(what + ": matrix dimension mismatch (" + std::to_string(a.rows) + "x" +
                         std::to_string(a.cols) + " times " + std::to_string(b.rows) + "x" +
                         std::to_string(b.cols) + ")");
    ColorMatrix r(a.rows, b.cols);
    for (int i = 0; i < r.rows; ++i)
        for (int j = 0; j < r.cols; ++j) {
            // RADIANCE compat (cm_multiply): float terms summed in double, first to last.
            double s[3] = {0, 0, 0};
            for (int h = 0; h < a.cols; ++h) {
                const float* p = a.at(i, h);
                const float* q = b.at(h, j);
                for (int k = 0; k < 3; ++k) s[k] += static_cast<double>(p[k]) * q[k];
            }
            float* d = r.at(i, j);
            for (int k = 0; k < 3; ++k) d[k] = static_cast<float>(s[k]);
        }
    return r;
}

void writeColorMatrix(std::ostream& out, const ColorMatrix& m, DataType type) {
    switch (type) {
        case DataType::Ascii: {
            std::string s;
            char buf[128];
            for (int i = 0; i < m.rows; ++i) {
                for (int j = 0; j < m.cols; ++j) {
                    const float* v = m.at(i, j);
                    s.append(buf, static_cast<size_t>(
                                      std::snprintf(buf, sizeof buf, "%.6e %.6e %.6e%c", v[0], v[1],
                                                    v[2], j >= m.cols - 1 ? '\n' : '\t')));
                }
                out.write(s.data(), static_cast<std::streamsize>(s.size()));
                s.clear();
            }
            break;
        }
        case DataType::Float:
            out.write(reinterpret_cast<const char*>(m.values.data()),
                      static_cast<std::streamsize>(m.values.size() * sizeof(float)));
            break;
        case DataType::Double: {
            const std::vector<double> d(m.values.begin(), m.values.end());
            out.write(reinterpret_cast<const char*>(d.data()),
                      static_cast<std::streamsize>(d.size() * sizeof(double)));
            break;
        }
        default: {
            const std::vector<double> d(m.values.begin(), m.values.end());
            writePictureData(out, m.rows, m.cols, d.data());
            break;
        }
    }
}

}  // namespace rp::matrix
