// dctimestep's work (see dctimestep.h), after RADIANCE dctimestep.c.
#include "matrix/dctimestep.h"

#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>

#include "image/rgbe.h"
#include "matrix/color_matrix.h"
#include "matrix/matrix_io.h"
#include "matrix/picture_data.h"
#include "util/error.h"
#include "util/file_read.h"
#include "util/header.h"
#include "util/warnings.h"

namespace rp::matrix {

namespace {

// A component picture's format and size (cm_getheader and fscnresolu in sum_images).
struct PictureHead {
    DataType type = DataType::FromHeader;
    int width = 0, height = 0;
};

PictureHead readPictureHead(DataReader& r) {
    const SourceLoc at{r.name(), 0};
    std::vector<std::string> lines;
    if (!r.readHeader(lines)) throw InputError(at, "unexpected EOF in header");
    PictureHead h;
    for (const std::string& l : lines) {
        char fmt[64] = "";
        if (l.rfind("NCOMP=", 0) == 0 && std::atoi(l.c_str() + 6) != 3)
            throw InputError(at, "unexpected # components (must be 3)");
        if (l.rfind("FORMAT=", 0) == 0 && std::sscanf(l.c_str() + 7, " %63s", fmt) == 1 &&
            parseFormatName(fmt) != DataType::FromHeader)
            h.type = parseFormatName(fmt);
    }
    if (h.type == DataType::FromHeader)
        throw InputError(at, "missing/unknown data format in header");
    if (!isPicture(h.type) || !r.readResolution(h.width, h.height))
        throw InputError(at, "not a picture");
    return h;
}

// sum_images: the pictures named by `spec` (one per row of the vector), weighted by the
// vector's values, summed and written after a FORMAT= line.
void sumImages(const std::string& spec, const ColorMatrix& v, std::ostream& out) {
    PictureHead first;
    ColorMatrix sum;
    for (int i = 0; i < v.rows; ++i) {
        const float* w = v.at(i, 0);
        // RADIANCE compat: zero weights skip their picture, except that the last one is
        // read when no other was, to learn the size.
        if (w[0] == 0 && w[1] == 0 && w[2] == 0 &&
            (first.type != DataType::FromHeader || i < v.rows - 1))
            continue;
        const std::string name = formatNumber(spec, i);
        const InputData in{name, readFileBytes(name)};
        DataReader r(in);
        const PictureHead h = readPictureHead(r);
        if (first.type == DataType::FromHeader) {
            first = h;
            sum = ColorMatrix(h.height, h.width);
            out << "FORMAT=" << formatName(h.type) << "\n\n";
        } else if (h.type != first.type || h.width != first.width || h.height != first.height) {
            throw InputError(SourceLoc{name, 0}, "picture format/size mismatch");
        }
        const bool flat = r.remaining() == sizeof(Colr) * static_cast<size_t>(h.width) * h.height;
        const std::vector<Colr> px = readScanlines(r, h.height, h.width, flat);
        for (size_t e = 0; e < px.size(); ++e) {
            if (!px[e][3]) continue;
            const Pixel p = toPixel(px[e]);
            for (int k = 0; k < 3; ++k) sum.values[e * 3 + k] += p[k] * w[k];
        }
    }
    writeColorMatrix(out, sum, first.type);
}

// Tmat of the 3-phase form: a matrix, or (RADIANCE compat: dctimestep.c cm_loadBTDF, for
// Tmat alone) a Klems BSDF's transmission, as rmtxop reads it.
ColorMatrix loadTransmission(const std::string& spec) {
    const std::optional<bsdf::CoefficientMatrix> c =
        loadBsdfMatrix(spec, bsdf::MatrixPart::Transmission);
    if (!c) return loadColorMatrix(spec, 0, 0, DataType::FromHeader);
    ColorMatrix m(c->rows, c->cols);
    for (size_t e = 0; e < c->values.size(); ++e)
        for (int k = 0; k < 3; ++k) m.values[e * 3 + size_t(k)] = float(c->values[e][k]);
    return m;
}

// The sky, or V T D s with the sky: the matrix each time step is a column of.
ColorMatrix skyProduct(const DctimestepOptions& o, int& steps) {
    const std::string skySpec = o.inputs.size() > 3    ? o.inputs[3]
                                : o.inputs.size() == 2 ? o.inputs[1]
                                                       : std::string("-");
    if (o.inputs.size() <= 2) {
        ColorMatrix sky = loadColorMatrix(skySpec, 0, steps, o.skyType);
        steps = sky.cols;
        return sky;
    }
    const ColorMatrix sky = loadColorMatrix(skySpec, 0, steps, o.skyType);
    steps = sky.cols;
    const ColorMatrix t = loadTransmission(o.inputs[1]);
    const ColorMatrix d = loadColorMatrix(o.inputs[2], t.cols, sky.rows, DataType::FromHeader);
    return multiply(t, multiply(d, sky, o.inputs[2]), o.inputs[1]);
}

std::string headerStart(const DctimestepOptions& o) {
    return std::string(kHeaderMagic) + "\n" + o.commandLine + "\n" + captureTimeLines();
}

std::string matrixHead(int rows, int cols, DataType type) {
    // RADIANCE compat (dctimestep.c): its BigEndian= test compares the format with 'f' and
    // 'd', never true, so binary results carry no byte-order line.
    return "NROWS=" + std::to_string(rows) + "\nNCOLS=" + std::to_string(cols) +
           "\nNCOMP=3\nFORMAT=" + formatName(type) + "\n\n";
}

std::unique_ptr<std::ofstream> openOutput(const std::string& name) {
    auto f = std::make_unique<std::ofstream>(name, std::ios::binary | std::ios::trunc);
    if (!*f) throw InputError("cannot open '" + name + "' for output");
    return f;
}

void closeOutput(std::ofstream& f, const std::string& name) {
    f.close();
    if (!f) throw InputError("error writing to '" + name + "'");
}

void writePictures(const DctimestepOptions& o, const ColorMatrix& c, int steps,
                   const std::string& spec, std::ostream& out) {
    if (o.outputType != DataType::Rgbe) warn("changing output type to -oc");
    if (spec.empty()) out << headerStart(o);
    if (steps <= 1) {
        sumImages(o.inputs[0], c, out);
        return;
    }
    for (int i = 0; i < steps; ++i) {
        std::unique_ptr<std::ofstream> f;
        const std::string name = spec.empty() ? std::string() : formatNumber(spec, i);
        if (f = spec.empty() ? nullptr : openOutput(name); f) *f << headerStart(o);
        std::ostream& dst = f ? *f : out;
        dst << "FRAME=" << i << "\n";
        sumImages(o.inputs[0], c.column(i), dst);
        if (f) closeOutput(*f, name);
    }
}

void writeResults(const DctimestepOptions& o, const ColorMatrix& c, int steps,
                  const std::string& spec, std::ostream& out) {
    const ColorMatrix v = loadColorMatrix(o.inputs[0], 0, c.rows, DataType::FromHeader);
    const ColorMatrix r = multiply(v, c, o.inputs[0]);
    if (spec.empty()) {
        if (o.header) out << headerStart(o) << matrixHead(r.rows, r.cols, o.outputType);
        writeColorMatrix(out, r, o.outputType);
        return;
    }
    for (int i = 0; i < steps; ++i) {  // one file per time step
        const std::string name = formatNumber(spec, i);
        const auto f = openOutput(name);
        if (o.header)
            *f << headerStart(o) << "FRAME=" << i << "\n" << matrixHead(r.rows, 1, o.outputType);
        writeColorMatrix(*f, r.column(i), o.outputType);
        closeOutput(*f, name);
    }
}

}  // namespace

void runDctimestep(const DctimestepOptions& o, std::ostream& out) {
    int steps = o.steps;
    const ColorMatrix c = skyProduct(o, steps);
    std::string spec = o.outputSpec;
    // RADIANCE compat: a one-step run names its file with step 1 (the others count from 0).
    if (!spec.empty() && steps == 1 && hasNumberFormat(spec)) spec = formatNumber(spec, 1);
    std::unique_ptr<std::ofstream> file;
    if (!spec.empty() && !hasNumberFormat(spec)) {
        file = openOutput(spec);
        spec.clear();
    }
    std::ostream& dst = file ? *file : out;
    if (hasNumberFormat(o.inputs[0]))
        writePictures(o, c, steps, spec, dst);
    else
        writeResults(o, c, steps, spec, dst);
    if (file) closeOutput(*file, o.outputSpec);
}

}  // namespace rp::matrix
