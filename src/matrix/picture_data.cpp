// Picture pixels as matrix data (see picture_data.h).
#include "matrix/picture_data.h"

#include <streambuf>
#include <string>

#include "image/rgbe.h"
#include "util/error.h"

namespace rp::matrix {

namespace {

// A read-only view of the reader's remaining bytes for the scanline decoder.
class ViewBuf : public std::streambuf {
public:
    ViewBuf(const char* b, const char* e) {
        char* p = const_cast<char*>(b);  // never written: no put area, no putback
        setg(p, p, const_cast<char*>(e));
    }
    size_t used() const { return static_cast<size_t>(gptr() - eback()); }
};

}  // namespace

void writePictureData(std::ostream& out, int rows, int cols, const double* rgb) {
    std::string s = "-Y " + std::to_string(rows) + " +X " + std::to_string(cols) + "\n";
    std::vector<Colr> scan(static_cast<size_t>(cols));
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < cols; ++j) {
            const double* p = rgb + (static_cast<size_t>(i) * cols + j) * 3;
            scan[static_cast<size_t>(j)] = toColr(p[0], p[1], p[2]);
        }
        encodeScanline(scan.data(), cols, s);
        out.write(s.data(), static_cast<std::streamsize>(s.size()));
        s.clear();
    }
}

std::vector<Colr> readScanlines(DataReader& r, int rows, int cols, bool flat) {
    checkDeclaredSize(r, rows, cols, 1);
    std::vector<Colr> pixels(static_cast<size_t>(rows) * cols);
    for (int i = 0; i < rows; ++i) {
        Colr* scan = pixels.data() + static_cast<size_t>(i) * cols;
        std::string err;
        if (flat) {
            if (!r.readBytes(scan, sizeof(Colr) * static_cast<size_t>(cols)))
                err = "truncated scanline";
        } else {
            ViewBuf buf(r.cursor(), r.cursor() + r.remaining());
            err = decodeScanline(buf, scan, cols);
            r.seek(r.position() + buf.used());
        }
        if (!err.empty())
            throw InputError(SourceLoc{r.name(), 0}, "picture data, scanline " +
                                                         std::to_string(i + 1) + " of " +
                                                         std::to_string(rows) + ": " + err);
    }
    return pixels;
}

}  // namespace rp::matrix
