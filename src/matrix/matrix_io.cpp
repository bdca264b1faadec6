// Matrix files for rmtxop (see matrix_io.h), following RADIANCE rmatrix.c.
#include "matrix/matrix_io.h"

#include <strings.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "image/rgbe.h"
#include "matrix/picture_data.h"
#include "util/error.h"

namespace rp::matrix {

namespace {

// What the header says (rmatrix.c get_dminfo).
struct HeaderInfo {
    int rows = 0, cols = 0, comps = 0;
    DataType type = DataType::Ascii;  // assumed without FORMAT=
    bool swap = false;
    double colorScale[3] = {1, 1, 1};  // EXPOSURE= and COLORCORR= products
    std::string info;
};

bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

void parseHeaderLine(const std::string& line, HeaderInfo& h, const std::string& name) {
    bool swap;
    if (startsWith(line, "#?")) return;
    if (startsWith(line, "NCOMP=")) {
        h.comps = std::atoi(line.c_str() + 6);
    } else if (startsWith(line, "NROWS=")) {
        h.rows = std::atoi(line.c_str() + 6);
    } else if (startsWith(line, "NCOLS=")) {
        h.cols = std::atoi(line.c_str() + 6);
    } else if (parseByteOrderLine(line, swap)) {
        h.swap = swap;
    } else if (startsWith(line, "EXPOSURE=")) {
        const double e = std::atof(line.c_str() + 9);
        for (double& s : h.colorScale) s *= e;
    } else if (startsWith(line, "COLORCORR=")) {
        double c[3] = {1, 1, 1};
        std::sscanf(line.c_str() + 10, "%lf %lf %lf", &c[0], &c[1], &c[2]);
        for (int k = 0; k < 3; ++k) h.colorScale[k] *= c[k];
    } else if (startsWith(line, "FORMAT=")) {
        char fmt[64] = "";
        std::sscanf(line.c_str() + 7, " %63s", fmt);
        if (!*fmt) {  // RADIANCE compat: an empty FORMAT= is just another line
            h.info += line;
            return;
        }
        h.type = parseFormatName(fmt);
        if (h.type == DataType::FromHeader)
            throw InputError(SourceLoc{name, 0}, std::string("unknown data format '") + fmt + "'");
    } else {
        h.info += line;
    }
}

void readAscii(DataReader& r, Matrix& m) {
    for (size_t i = 0; i < m.values.size(); ++i)
        if (!r.nextDouble(m.values[i]))
            throw InputError(SourceLoc{r.name(), r.lastNumberLine()},
                             "unexpected end of data: " + std::to_string(i) + " of " +
                                 std::to_string(m.values.size()) + " values (" + m.sizeText() +
                                 ")");
}

void readBinary(DataReader& r, Matrix& m, bool swap) {
    const int size = componentBytes(m.type);
    const size_t elements = static_cast<size_t>(m.rows) * m.cols;
    for (size_t e = 0; e < elements; ++e) {
        double* v = &m.values[e * m.comps];
        bool ok;
        if (size == 8) {
            ok = r.readBytes(v, sizeof(double) * m.comps);
            if (ok && swap) swapBytes(v, 8, m.comps);
        } else {
            std::vector<float> f(m.comps);
            ok = r.readBytes(f.data(), sizeof(float) * m.comps);
            if (ok && swap) swapBytes(f.data(), 4, m.comps);
            for (int k = 0; ok && k < m.comps; ++k) v[k] = f[k];
        }
        if (!ok)
            throw InputError(SourceLoc{r.name(), 0},
                             "unexpected end of data at record " + std::to_string(e + 1) + " of " +
                                 std::to_string(elements) + " (" + m.sizeText() + ", " +
                                 formatName(m.type) + ")");
    }
}

void readPicture(DataReader& r, Matrix& m) {
    const std::vector<Colr> pixels = readScanlines(r, m.rows, m.cols, false);
    for (size_t e = 0; e < pixels.size(); ++e) {
        const Pixel p = toPixel(pixels[e]);
        for (int k = 0; k < 3; ++k) m.values[e * 3 + k] = p[k];
    }
}

}  // namespace

Matrix parseMatrix(const InputData& in) {
    DataReader r(in);
    std::vector<std::string> lines;
    if (!r.readHeader(lines))
        throw InputError(SourceLoc{in.name, 0},
                         "bad header (no information header ended by an empty line)");
    HeaderInfo h;
    for (const std::string& l : lines) parseHeaderLine(l, h, in.name);
    if (h.rows <= 0 || h.cols <= 0) {  // a picture: the size is in the resolution string
        if (!r.readResolution(h.cols, h.rows))
            throw InputError(SourceLoc{in.name, 0},
                             "missing NROWS= or NCOLS= in header (and no picture resolution)");
        if (h.comps <= 0)
            h.comps = 3;
        else if (isPicture(h.type) && h.comps != 3)
            throw InputError(SourceLoc{in.name, 0}, "a picture must have NCOMP=3");
    }
    if (h.comps <= 0) throw InputError(SourceLoc{in.name, 0}, "missing NCOMP= in header");
    checkDeclaredSize(r, h.rows, h.cols, h.comps);
    Matrix m(h.rows, h.cols, h.comps);
    m.info = h.info;
    m.type = h.type;
    switch (h.type) {
        case DataType::Ascii:
            readAscii(r, m);
            break;
        case DataType::Float:
        case DataType::Double:
            readBinary(r, m, h.swap);
            break;
        default:
            if (h.comps != 3)
                throw InputError(SourceLoc{in.name, 0}, "a picture must have NCOMP=3");
            readPicture(r, m);
            // RADIANCE compat (rmx_load): undo EXPOSURE= and COLORCORR= ("Applied scalar"
            // goes into info that exists).
            if (h.colorScale[0] != 1 || h.colorScale[1] != 1 || h.colorScale[2] != 1)
                scale(m, {1 / h.colorScale[0], 1 / h.colorScale[1], 1 / h.colorScale[2]});
            break;
    }
    return m;
}

std::optional<bsdf::CoefficientMatrix> loadBsdfMatrix(const std::string& spec,
                                                      bsdf::MatrixPart part) {
    const size_t dot = spec.rfind('.');
    if (spec.empty() || spec[0] == '!' || dot == std::string::npos ||
        strcasecmp(spec.c_str() + dot + 1, "xml") != 0)
        return std::nullopt;
    return bsdf::klemsCoefficients(*bsdf::loadBsdfFile(spec), part);
}

Matrix loadMatrix(const std::string& spec, bsdf::MatrixPart part) {
    if (std::optional<bsdf::CoefficientMatrix> c = loadBsdfMatrix(spec, part)) {
        Matrix m(c->rows, c->cols, 3);
        m.type = DataType::Ascii;  // RADIANCE compat (rmx_load): as if read as text
        for (size_t e = 0; e < c->values.size(); ++e)
            for (int k = 0; k < 3; ++k) m.values[e * 3 + size_t(k)] = c->values[e][k];
        return m;
    }
    return parseMatrix(readInput(spec));
}

}  // namespace rp::matrix
