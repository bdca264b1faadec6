// RADIANCE picture files: header fields, resolution strings, scanline I/O (see picture.h).
#include "image/picture.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include "util/error.h"
#include "util/file_write.h"

namespace rp {

namespace {

// Largest picture we accept: 2^31 pixels (a 46k x 46k image); a corrupt resolution
// line must not turn into a 100 GB allocation.
constexpr long long kMaxPixels = 1LL << 31;
// Longest scanline we accept: 2^24 pixels. Readers hold a whole scanline before its data
// is checked, so a short file claiming one very long scanline must not allocate gigabytes
// (found by fuzz_picture: "-Y 1 +X 1666699776" in 50 bytes).
constexpr long long kMaxScanline = 1LL << 24;

std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    size_t e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Exactly n numbers separated by white space, nothing else.
bool parseNumbers(const std::string& s, double* out, int n) {
    const char* p = s.c_str();
    for (int i = 0; i < n; ++i) {
        char* end;
        out[i] = std::strtod(p, &end);
        if (end == p) return false;
        p = end;
    }
    while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
    return *p == '\0';
}

// Calls f(values) for every header line "KEY=..." holding n numbers; throws on a
// malformed one.
template <typename F>
void forEachField(const Header& h, const char* key, int n, F f) {
    std::string prefix = std::string(key) + "=";
    for (const auto& line : h.lines) {
        if (!startsWith(line, prefix.c_str())) continue;
        double v[8];
        if (!parseNumbers(line.substr(prefix.size()), v, n))
            throw InputError("bad header line '" + line + "'");
        f(v);
    }
}

// RADIANCE picture header check: FORMAT= must name one of the two 32-bit formats; a
// header with no FORMAT line is an old RGBE picture. FORMAT lines are removed from h.
PictureFormat takeFormat(Header& h, const std::string& what) {
    std::string fmt = trim(h.format());
    PictureFormat result = PictureFormat::kRgbe;
    if (fmt == kXyzeFormat)
        result = PictureFormat::kXyze;
    else if (fmt == "Radiance_spectra")  // RADIANCE 6's, read by spectral_picture.h
        throw InputError(SourceLoc{what, 0},
                         "spectral picture (FORMAT=Radiance_spectra) where RGB is needed");
    else if (!fmt.empty() && fmt != kRgbeFormat)
        throw InputError(SourceLoc{what, 0}, "not a RADIANCE picture (FORMAT=" + fmt + ")");
    std::erase_if(h.lines, [](const std::string& l) { return startsWith(l, "FORMAT="); });
    return result;
}

PictureInfo readInfo(std::istream& in, const std::string& what) {
    PictureInfo info;
    info.header = readHeader(in, what);
    info.format = takeFormat(info.header, what);
    try {
        Picture probe;  // validate EXPOSURE= etc. once, with the file name in the error
        probe.header = info.header;
        (void)probe.exposure();
        (void)probe.colorCorrection();
        (void)probe.pixelAspect();
        (void)probe.primaries();
    } catch (const InputError& e) {
        throw InputError(SourceLoc{what, 0}, e.message());
    }
    info.resolution = readResolution(in, what);
    return info;
}

}  // namespace

std::string paddedResolution(const Resolution& r) {
    char buf[64];
    const char xs = r.xDecreasing ? '-' : '+', ys = r.yDecreasing ? '-' : '+';
    if (r.yMajor)
        std::snprintf(buf, sizeof buf, "%cY %8d %cX %8d", ys, r.yres, xs, r.xres);
    else
        std::snprintf(buf, sizeof buf, "%cX %8d %cY %8d", xs, r.xres, ys, r.yres);
    return buf;
}

Resolution readResolution(std::istream& in, const std::string& what, std::string* text) {
    std::string line;
    int c;
    while ((c = in.get()) != EOF && c != '\n') {
        line.push_back(static_cast<char>(c));
        if (line.size() > 64) break;
    }
    auto r = parseResolution(line);
    if (!r) {
        if (c == EOF && line.empty())
            throw InputError(SourceLoc{what, 0}, "missing resolution line after header");
        throw InputError(SourceLoc{what, 0}, "bad resolution line");
    }
    if (static_cast<long long>(r->xres) * r->yres > kMaxPixels)
        throw InputError(SourceLoc{what, 0}, "picture too large (" + formatResolution(*r) + ")");
    if (r->scanlineLength() > kMaxScanline)
        throw InputError(SourceLoc{what, 0}, "scanlines too long (" + formatResolution(*r) + ")");
    if (text) *text = line;
    return *r;
}

std::optional<Resolution> parseResolution(const std::string& line) {
    std::istringstream ss(line);
    std::string a1, a2, extra;
    long n1 = 0, n2 = 0;
    if (!(ss >> a1 >> n1 >> a2 >> n2) || (ss >> extra)) return std::nullopt;
    auto axis = [](const std::string& a, char& sign, char& name) {
        if (a.size() != 2 || (a[0] != '+' && a[0] != '-') || (a[1] != 'X' && a[1] != 'Y'))
            return false;
        sign = a[0];
        name = a[1];
        return true;
    };
    char s1, c1, s2, c2;
    if (!axis(a1, s1, c1) || !axis(a2, s2, c2) || c1 == c2) return std::nullopt;
    if (n1 <= 0 || n2 <= 0 || n1 > 0x7fffffff || n2 > 0x7fffffff) return std::nullopt;
    Resolution r;
    r.yMajor = (c1 == 'Y');
    char xs = r.yMajor ? s2 : s1, ys = r.yMajor ? s1 : s2;
    r.xres = static_cast<int>(r.yMajor ? n2 : n1);
    r.yres = static_cast<int>(r.yMajor ? n1 : n2);
    r.xDecreasing = (xs == '-');
    r.yDecreasing = (ys == '-');
    return r;
}

std::string formatResolution(const Resolution& r) {
    char buf[64];
    char xs = r.xDecreasing ? '-' : '+', ys = r.yDecreasing ? '-' : '+';
    if (r.yMajor)
        std::snprintf(buf, sizeof buf, "%cY %d %cX %d", ys, r.yres, xs, r.xres);
    else
        std::snprintf(buf, sizeof buf, "%cX %d %cY %d", xs, r.xres, ys, r.yres);
    return buf;
}

double Picture::exposure() const {
    double e = 1;
    forEachField(header, "EXPOSURE", 1, [&](const double* v) { e *= v[0]; });
    return e;
}

std::array<double, 3> Picture::colorCorrection() const {
    std::array<double, 3> c{1, 1, 1};
    forEachField(header, "COLORCORR", 3, [&](const double* v) {
        for (int i = 0; i < 3; ++i) c[i] *= v[i];
    });
    return c;
}

double Picture::pixelAspect() const {
    double a = 1;
    forEachField(header, "PIXASPECT", 1, [&](const double* v) { a *= v[0]; });
    return a;
}

std::optional<std::array<double, 8>> Picture::primaries() const {
    std::optional<std::array<double, 8>> p;
    forEachField(header, "PRIMARIES", 8, [&](const double* v) {
        p.emplace();
        for (int i = 0; i < 8; ++i) (*p)[i] = v[i];
    });
    return p;
}

void Picture::addExposure(double e) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "EXPOSURE=%e", e);  // RADIANCE's fputexpos format
    header.lines.push_back(buf);
}

PictureInfo readPictureInfo(std::istream& in, const std::string& what) {
    return readInfo(in, what);
}

Picture readPicture(std::istream& in, const std::string& what) {
    PictureInfo info = readInfo(in, what);
    const Resolution& res = info.resolution;
    std::streambuf& buf = *in.rdbuf();
    const int len = res.scanlineLength(), count = res.scanlineCount();

    // Scanlines are collected packed and grown as they arrive, so a truncated file with
    // a huge resolution line fails before a huge float allocation.
    std::vector<Colr> packed;
    for (int s = 0; s < count; ++s) {
        packed.resize(static_cast<size_t>(s + 1) * len);
        std::string why = decodeScanline(buf, packed.data() + static_cast<size_t>(s) * len, len);
        if (!why.empty())
            throw InputError(SourceLoc{what, 0}, why + " (scanline " + std::to_string(s + 1) +
                                                     " of " + std::to_string(count) + ")");
    }

    Picture pic(res.xres, res.yres);
    pic.format = info.format;
    pic.header = std::move(info.header);
    // RADIANCE compat: pix2loc() in image.c maps (position p in scanline, scanline s) to
    // image x (from the left) and y (from the bottom).
    for (int s = 0; s < count; ++s) {
        for (int p = 0; p < len; ++p) {
            int x = res.yMajor ? p : s, y = res.yMajor ? s : p;
            if (res.xDecreasing) x = res.xres - 1 - x;
            if (res.yDecreasing) y = res.yres - 1 - y;
            pic.at(x, res.yres - 1 - y) = toPixel(packed[static_cast<size_t>(s) * len + p]);
        }
    }
    return pic;
}

Picture readPicture(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open picture");
    return readPicture(in, path);
}

namespace {
std::string encodePicture(const Picture& pic) {
    RP_CHECK(pic.width > 0 && pic.height > 0);
    RP_CHECK(pic.pixels.size() == static_cast<size_t>(pic.width) * pic.height);
    std::ostringstream hs;
    Header h = pic.header;
    std::erase_if(h.lines, [](const std::string& l) { return startsWith(l, "FORMAT="); });
    h.lines.push_back(std::string("FORMAT=") +
                      (pic.format == PictureFormat::kXyze ? kXyzeFormat : kRgbeFormat));
    writeHeader(hs, h);
    Resolution r;
    r.xres = pic.width;
    r.yres = pic.height;
    hs << formatResolution(r) << '\n';
    std::string out = hs.str();
    out.reserve(out.size() + static_cast<size_t>(pic.width) * pic.height * 4);
    std::vector<Colr> scan(pic.width);
    for (int y = 0; y < pic.height; ++y) {
        for (int x = 0; x < pic.width; ++x) scan[x] = toColr(pic.at(x, y));
        encodeScanline(scan.data(), pic.width, out);
    }
    return out;
}
}  // namespace

void writePicture(std::ostream& out, const Picture& pic) {
    std::string data = encodePicture(pic);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
}

void writePicture(const std::string& path, const Picture& pic) {
    writeFileAtomically(path, encodePicture(pic));
}

}  // namespace rp
