// dctimestep's RGB matrices (see color_matrix.h), after RADIANCE cmatrix.c.
#include "matrix/color_matrix.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "image/rgbe.h"
#include "matrix/picture_data.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::matrix {

namespace {

struct ColorHeader {
    DataType type = DataType::FromHeader;
    int rows = 0, cols = 0;
    bool swap = false;
    float exposure[3] = {1, 1, 1};
};

bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// cmatrix.c cm_getheader: reads the header and checks it against what the caller expects.
void readColorHeader(DataReader& r, int& rows, int& cols, DataType& type, ColorHeader& h) {
    const SourceLoc at{r.name(), 0};
    std::vector<std::string> lines;
    if (!r.readHeader(lines)) throw InputError(at, "unexpected EOF in header");
    for (const std::string& l : lines) {
        bool swap;
        char fmt[64] = "";
        if (startsWith(l, "NCOMP=") && std::atoi(l.c_str() + 6) != 3)
            throw InputError(at, "unexpected # components (must be 3)");
        if (startsWith(l, "NROWS="))
            h.rows = std::atoi(l.c_str() + 6);
        else if (startsWith(l, "NCOLS="))
            h.cols = std::atoi(l.c_str() + 6);
        else if (parseByteOrderLine(l, swap))
            h.swap = swap;
        else if (startsWith(l, "EXPOSURE="))
            for (float& e : h.exposure) e *= static_cast<float>(std::atof(l.c_str() + 9));
        else if (startsWith(l, "COLORCORR=")) {
            double c[3] = {1, 1, 1};
            std::sscanf(l.c_str() + 10, "%lf %lf %lf", &c[0], &c[1], &c[2]);
            for (int k = 0; k < 3; ++k) h.exposure[k] *= static_cast<float>(c[k]);
        } else if (startsWith(l, "FORMAT=") && std::sscanf(l.c_str() + 7, " %63s", fmt) == 1 &&
                   parseFormatName(fmt) != DataType::FromHeader)
            h.type = parseFormatName(fmt);  // RADIANCE compat: unknown formats are ignored
    }
    if (h.type == DataType::FromHeader) {
        if (type == DataType::FromHeader)
            throw InputError(at, "missing/unknown data format in header");
    } else if (type == DataType::FromHeader) {
        type = h.type;
    } else if (type != h.type) {
        throw InputError(at, std::string("unexpected data format in header (") +
                                 formatName(h.type) + ", expected " + formatName(type) + ")");
    }
    if (rows <= 0)
        rows = h.rows;
    else if (h.rows > 0 && rows != h.rows)
        throw InputError(at, "unexpected row count in header (" + std::to_string(h.rows) +
                                 ", expected " + std::to_string(rows) + ")");
    if (cols <= 0)
        cols = h.cols;
    else if (h.cols > 0 && cols != h.cols)
        throw InputError(at, "unexpected column count in header (" + std::to_string(h.cols) +
                                 ", expected " + std::to_string(cols) + ")");
}

// `want` 0: the row count is not known, `perRow` says what a row needs.
InputError endOfData(const DataReader& r, size_t got, size_t want, size_t perRow, bool text) {
    std::string what = "unexpected EOF: " + std::to_string(got) + " of ";
    what += want ? std::to_string(want) + " RGB values"
                 : "a whole number of rows of " + std::to_string(perRow) + " RGB values";
    return InputError(SourceLoc{r.name(), text ? r.lastNumberLine() : 0}, what);
}

ColorMatrix readAsciiColors(DataReader& r, int rows, int cols) {
    // RADIANCE compat (cm_load): without a row count, rows are read to the end of the
    // data, 32000 at most.
    const int maxRows = rows > 0 ? rows : 32000;
    checkDeclaredSize(r, rows > 0 ? rows : 1, cols, 3);
    ColorMatrix m(0, cols);
    for (int row = 0; row < maxRows; ++row) {
        m.values.resize(static_cast<size_t>(row + 1) * cols * 3);
        for (int c = 0; c < cols; ++c) {
            float* v = m.at(row, c);
            if (!r.nextFloat(v[0]) || !r.nextFloat(v[1]) || !r.nextFloat(v[2])) {
                if (rows <= 0 && row > 0 && c == 0) {
                    m.values.resize(static_cast<size_t>(row) * cols * 3);
                    m.rows = row;
                    return m;
                }
                throw endOfData(r, static_cast<size_t>(row) * cols + c,
                                rows > 0 ? static_cast<size_t>(rows) * cols : 0,
                                static_cast<size_t>(cols), true);
            }
        }
        m.rows = row + 1;
    }
    if (!r.atEndIgnoringSpace()) warn("unexpected data at end of ascii input '" + r.name() + "'");
    return m;
}

ColorMatrix readBinaryColors(DataReader& r, int rows, int cols, DataType type, bool swap) {
    const size_t size = static_cast<size_t>(componentBytes(type));
    const size_t rowBytes = static_cast<size_t>(cols) * 3 * size;
    if (rows <= 0) {  // from the data's length (RADIANCE: the file's size)
        if (r.remaining() % rowBytes || r.remaining() == 0)
            throw InputError(SourceLoc{r.name(), 0},
                             "improper length for binary file (" + std::to_string(r.remaining()) +
                                 " bytes, " + std::to_string(rowBytes) + " a row)");
        rows = static_cast<int>(r.remaining() / rowBytes);
    }
    checkDeclaredSize(r, rows, cols, 3);
    ColorMatrix m(rows, cols);
    const size_t n = m.values.size();
    if (r.remaining() < n * size)
        throw endOfData(r, r.remaining() / (3 * size), n / 3, static_cast<size_t>(cols), false);
    if (size == 4) {
        r.readBytes(m.values.data(), n * 4);
        if (swap) swapBytes(m.values.data(), 4, n);
    } else {
        std::vector<double> d(n);
        r.readBytes(d.data(), n * 8);
        if (swap) swapBytes(d.data(), 8, n);
        for (size_t i = 0; i < n; ++i) m.values[i] = static_cast<float>(d[i]);
    }
    if (r.remaining()) warn("unexpected data at end of binary input '" + r.name() + "'");
    return m;
}

}  // namespace

ColorMatrix ColorMatrix::column(int c) const {
    ColorMatrix v(rows, 1);
    for (int r = 0; r < rows; ++r) std::memcpy(v.at(r, 0), at(r, c), 3 * sizeof(float));
    return v;
}

ColorMatrix parseColorMatrix(const InputData& in, int rows, int cols, DataType type) {
    DataReader r(in);
    ColorHeader h;
    if (type == DataType::FromHeader || cols == 0) readColorHeader(r, rows, cols, type, h);
    if (cols <= 0 && !r.readResolution(cols, rows))
        throw InputError(SourceLoc{in.name, 0}, "unspecified number of columns");
    if (isPicture(type)) {
        const std::vector<Colr> px = readScanlines(r, rows, cols, false);
        ColorMatrix m(rows, cols);
        // RADIANCE compat (cm_load_rgbe): exposure is undone only when it is not near 1.
        bool undo = false;
        float s[3];
        for (int k = 0; k < 3; ++k) {
            s[k] = 1.f / h.exposure[k];
            undo = undo || s[k] < .99f || s[k] > 1.01f;
        }
        for (size_t e = 0; e < px.size(); ++e) {
            const Pixel p = toPixel(px[e]);
            for (int k = 0; k < 3; ++k) m.values[e * 3 + k] = undo ? p[k] * s[k] : p[k];
        }
        return m;
    }
    if (type == DataType::Ascii) return readAsciiColors(r, rows, cols);
    if (type == DataType::Float || type == DataType::Double)
        return readBinaryColors(r, rows, cols, type, h.swap);
    throw InputError(SourceLoc{in.name, 0}, "unexpected data type");
}

ColorMatrix loadColorMatrix(const std::string& spec, int rows, int cols, DataType type) {
    return parseColorMatrix(readInput(spec), rows, cols, type);
}

}  // namespace rp::matrix
