// RADIANCE 6 spectral pictures: header, flat SCOLR scanlines, RGB views (see
// spectral_picture.h).
#include "image/spectral_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <optional>
#include <ostream>
#include <sstream>

#include "util/error.h"
#include "util/file_write.h"

namespace rp {

namespace {

constexpr const char* kNcompKey = "NCOMP=";
constexpr const char* kSplitsKey = "WAVELENGTH_SPLITS=";
// RADIANCE's WLPART default, assumed when a header has no WAVELENGTH_SPLITS= line.
constexpr std::array<double, 4> kDefaultSplits = {780, 588, 480, 380};
// As picture.cpp: a corrupt resolution line must not become a huge allocation.
constexpr long long kMaxPixels = 1LL << 31;

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// NCOMP=n: an integer and nothing else (RADIANCE's atoi would read "18x" as 18).
std::optional<int> ncompValue(const std::string& line) {
    const std::string v = trim(line.substr(std::char_traits<char>::length(kNcompKey)));
    char* end = nullptr;
    const long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || n < 0 || n > 1000) return std::nullopt;
    return static_cast<int>(n);
}

// WAVELENGTH_SPLITS= a b c d, read into floats as RADIANCE's wlsplitval does.
std::optional<std::array<double, 4>> splitsValue(const std::string& line) {
    float w[4];
    char extra;
    const char* v = line.c_str() + std::char_traits<char>::length(kSplitsKey);
    if (std::sscanf(v, "%f %f %f %f %c", &w[0], &w[1], &w[2], &w[3], &extra) != 4)
        return std::nullopt;
    for (float f : w)
        if (!std::isfinite(f)) return std::nullopt;
    return std::array<double, 4>{w[0], w[1], w[2], w[3]};
}

// The wavelengths as a header line holds them (floats), for comparing with a file's.
std::array<double, 4> asFloats(const std::array<double, 4>& wl) {
    return {float(wl[0]), float(wl[1]), float(wl[2]), float(wl[3])};
}

std::string ncompLine(int n) { return kNcompKey + std::to_string(n); }

// RADIANCE's fputwlsplit: "%s %g %g %g %g" of the float values.
std::string splitsLine(const std::array<double, 4>& wl) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s %g %g %g %g", kSplitsKey, double(float(wl[0])),
                  double(float(wl[1])), double(float(wl[2])), double(float(wl[3])));
    return buf;
}

// The sampling a header describes; throws InputError naming `what` for bad values.
spectral::Sampling samplingOf(const Header& h, const std::string& what) {
    int n = 3;  // RADIANCE's NCSAMP when no NCOMP= line says otherwise
    std::array<double, 4> wl = kDefaultSplits;
    for (const std::string& line : h.lines) {
        if (startsWith(line, kNcompKey)) {
            auto v = ncompValue(line);
            if (!v || *v < 3 || *v > spectral::kMaxSamples)
                throw InputError(SourceLoc{what, 0}, "bad header line '" + line + "' (3 to " +
                                                         std::to_string(spectral::kMaxSamples) +
                                                         " samples)");
            n = *v;
        } else if (startsWith(line, kSplitsKey)) {
            auto v = splitsValue(line);
            if (!v || !((*v)[0] > (*v)[3]))
                throw InputError(SourceLoc{what, 0}, "bad header line '" + line +
                                                         "' (4 wavelengths, longest first, in nm)");
            wl = *v;
        }
    }
    spectral::Sampling s;
    s.n = n;
    s.wl = wl;
    // CNDX as RADIANCE's setspectrsamp would pick it; pictures only record n and wl.
    if (auto c = spectral::makeSampling(n, wl[0], wl[3])) s.rgb = c->sampling.rgb;
    return s;
}

// Reads one scanline of `len` packed pixels (n+1 bytes each) as RADIANCE's freadscolrs:
// flat for n > 3, any RGBE scanline encoding for n == 3.
std::string readScanline(std::streambuf& in, int n, int len, uint8_t* out) {
    if (n == 3) {
        std::vector<Colr> scan(len);
        std::string why = decodeScanline(in, scan.data(), len);
        if (!why.empty()) return why;
        for (int i = 0; i < len; ++i) std::copy(scan[i].begin(), scan[i].end(), out + 4 * i);
        return {};
    }
    const std::streamsize bytes = static_cast<std::streamsize>(n + 1) * len;
    if (in.sgetn(reinterpret_cast<char*>(out), bytes) != bytes) return "truncated scanline";
    return {};
}

SpectralPicture readAfterHeader(Header header, std::istream& in, const std::string& what) {
    if (!isSpectralFormat(header)) {
        const std::string fmt = trim(header.format());
        throw InputError(SourceLoc{what, 0},
                         "not a spectral picture (" +
                             (fmt.empty() ? std::string("no FORMAT line") : "FORMAT=" + fmt) + ")");
    }
    std::erase_if(header.lines, [](const std::string& l) { return startsWith(l, "FORMAT="); });
    const spectral::Sampling sampling = samplingOf(header, what);
    try {
        Picture probe;  // EXPOSURE= etc. checked once, with the file name in the error
        probe.header = header;
        (void)probe.exposure();
        (void)probe.pixelAspect();
        (void)probe.colorCorrection();
    } catch (const InputError& e) {
        throw InputError(SourceLoc{what, 0}, e.message());
    }
    bool padded = false;
    std::string line;
    const Resolution res = readResolution(in, what, &line);
    padded = line == paddedResolution(res);
    const int n = sampling.n, len = res.scanlineLength(), count = res.scanlineCount();
    const size_t pixelBytes = static_cast<size_t>(n) + 1;

    // Packed scanlines grow as they arrive: a truncated file with a huge resolution line
    // fails before a huge float allocation.
    std::vector<uint8_t> packed;
    std::streambuf& buf = *in.rdbuf();
    for (int s = 0; s < count; ++s) {
        packed.resize(static_cast<size_t>(s + 1) * len * pixelBytes);
        std::string why =
            readScanline(buf, n, len, packed.data() + static_cast<size_t>(s) * len * pixelBytes);
        if (!why.empty())
            throw InputError(SourceLoc{what, 0}, why + " (scanline " + std::to_string(s + 1) +
                                                     " of " + std::to_string(count) + ")");
    }

    SpectralPicture pic(res.xres, res.yres, sampling);
    pic.header = std::move(header);
    pic.paddedResolution = padded;
    // RADIANCE compat: pix2loc() in image.c, as readPicture places pixels.
    for (int s = 0; s < count; ++s) {
        for (int p = 0; p < len; ++p) {
            int x = res.yMajor ? p : s, y = res.yMajor ? s : p;
            if (res.xDecreasing) x = res.xres - 1 - x;
            if (res.yDecreasing) y = res.yres - 1 - y;
            const uint8_t* src = packed.data() + (static_cast<size_t>(s) * len + p) * pixelBytes;
            unpackSpectrum({src, pixelBytes}, pic.at(x, res.yres - 1 - y));
        }
    }
    return pic;
}

// The header lines written: NCOMP= and WAVELENGTH_SPLITS= lines kept where they are when
// they match the sampling, rewritten where they do not, added before FORMAT= when
// missing (WAVELENGTH_SPLITS= then NCOMP=, as rpict writes them; no WAVELENGTH_SPLITS=
// for RADIANCE's default, as rmatrix leaves it out).
Header headerToWrite(const SpectralPicture& pic) {
    Header h;
    const spectral::Sampling& s = pic.sampling;
    bool haveNcomp = false, haveSplits = false;
    for (const std::string& line : pic.header.lines) {
        if (startsWith(line, "FORMAT=")) continue;
        if (startsWith(line, kNcompKey)) {
            auto v = ncompValue(line);
            h.lines.push_back(v && *v == s.n ? line : ncompLine(s.n));
            haveNcomp = true;
        } else if (startsWith(line, kSplitsKey)) {
            auto v = splitsValue(line);
            h.lines.push_back(v && *v == asFloats(s.wl) ? line : splitsLine(s.wl));
            haveSplits = true;
        } else {
            h.lines.push_back(line);
        }
    }
    if (!haveSplits && asFloats(s.wl) != kDefaultSplits) h.lines.push_back(splitsLine(s.wl));
    if (!haveNcomp) h.lines.push_back(ncompLine(s.n));
    h.lines.push_back(std::string("FORMAT=") + kSpectralFormat);
    return h;
}

std::string encodeSpectralPicture(const SpectralPicture& pic) {
    const int n = pic.sampling.n;
    RP_CHECK(pic.width > 0 && pic.height > 0);
    RP_CHECK(n >= 3 && n <= spectral::kMaxSamples);
    RP_CHECK(pic.samples.size() == static_cast<size_t>(pic.width) * pic.height * n);
    std::ostringstream hs;
    writeHeader(hs, headerToWrite(pic));
    Resolution r;
    r.xres = pic.width;
    r.yres = pic.height;
    hs << (pic.paddedResolution ? paddedResolution(r) : formatResolution(r)) << '\n';
    std::string out = hs.str();
    out.reserve(out.size() + static_cast<size_t>(pic.width) * pic.height * (n + 1));
    std::vector<uint8_t> scan(static_cast<size_t>(pic.width) * (n + 1));
    std::vector<Colr> rgbe(n == 3 ? pic.width : 0);
    for (int y = 0; y < pic.height; ++y) {
        for (int x = 0; x < pic.width; ++x)
            packSpectrum(pic.at(x, y), {scan.data() + static_cast<size_t>(x) * (n + 1),
                                        static_cast<size_t>(n) + 1});
        if (n == 3) {
            // RADIANCE compat: fwritescolrs writes 3 samples as an RGBE scanline.
            for (int x = 0; x < pic.width; ++x)
                std::copy_n(scan.data() + 4 * x, 4, rgbe[x].begin());
            encodeScanline(rgbe.data(), pic.width, out);
        } else {
            out.append(reinterpret_cast<const char*>(scan.data()), scan.size());
        }
    }
    return out;
}

// Reads from `head` (text already taken from the stream), then from the stream itself:
// lets a picture whose header was read to learn its kind be read again from the top.
class PrefixedBuf : public std::streambuf {
public:
    PrefixedBuf(std::string head, std::streambuf& rest) : head_(std::move(head)), rest_(rest) {
        setg(head_.data(), head_.data(), head_.data() + head_.size());
    }

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        const std::streamsize got = rest_.sgetn(chunk_, sizeof chunk_);
        if (got <= 0) return traits_type::eof();
        setg(chunk_, chunk_, chunk_ + got);
        return traits_type::to_int_type(*gptr());
    }

private:
    std::string head_;
    std::streambuf& rest_;
    char chunk_[1 << 16];
};

double headerProduct(const Header& h, double (Picture::*field)() const) {
    Picture probe;
    probe.header = h;
    return (probe.*field)();
}

}  // namespace

double SpectralPicture::exposure() const { return headerProduct(header, &Picture::exposure); }

double SpectralPicture::pixelAspect() const { return headerProduct(header, &Picture::pixelAspect); }

bool isSpectralFormat(const Header& h) { return trim(h.format()) == kSpectralFormat; }

void packSpectrum(std::span<const float> in, std::span<uint8_t> out) {
    const size_t n = in.size();
    RP_CHECK(out.size() == n + 1);
    // RADIANCE compat: scolor2scolr() in color.c, in its float arithmetic.
    float p = 0;
    for (float v : in)
        if (v > p) p = v;  // NaN never counts
    if (!(static_cast<double>(p) > 1e-32)) {
        std::fill(out.begin(), out.end(), uint8_t{0});
        return;
    }
    int e;
    const double m = std::frexp(p, &e);
    if (e + 128 > 255 || std::isinf(p)) {
        std::fill(out.begin(), out.end(), uint8_t{255});
        return;
    }
    const float scale = static_cast<float>(m * 256.0 / p);
    for (size_t i = 0; i < n; ++i) {
        const float v = in[i] * scale;
        out[i] = in[i] > 0 ? static_cast<uint8_t>(std::min(255, static_cast<int>(v))) : 0;
    }
    out[n] = static_cast<uint8_t>(e + 128);
}

void unpackSpectrum(std::span<const uint8_t> in, std::span<float> out) {
    const size_t n = out.size();
    RP_CHECK(in.size() == n + 1);
    // RADIANCE compat: scolr2scolor(): cxponent[e] is 2^(e-136) as a float, 0 for e == 0;
    // (m + 0.5) * 2^k is exact in float for every byte.
    const float f = in[n] == 0 ? 0.0f : static_cast<float>(colr_detail::kExpScale[in[n]]);
    for (size_t i = 0; i < n; ++i) out[i] = (static_cast<float>(in[i]) + 0.5f) * f;
}

SpectralPicture readSpectralPicture(std::istream& in, const std::string& what) {
    Header h = readHeader(in, what);
    return readAfterHeader(std::move(h), in, what);
}

SpectralPicture readSpectralPicture(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open picture");
    return readSpectralPicture(in, path);
}

void writeSpectralPicture(std::ostream& out, const SpectralPicture& pic) {
    const std::string data = encodeSpectralPicture(pic);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
}

void writeSpectralPicture(const std::string& path, const SpectralPicture& pic) {
    writeFileAtomically(path, encodeSpectralPicture(pic));
}

Picture toRgbPicture(const SpectralPicture& sp, SpectralToRgb how) {
    Picture pic(sp.width, sp.height);
    pic.format = PictureFormat::kRgbe;
    // RADIANCE compat: ra_rgbe drops NCOMP= and WAVELENGTH_SPLITS= (and FORMAT=) when it
    // turns a spectral picture into RGBE; pvalue does not echo them either.
    for (const std::string& line : sp.header.lines)
        if (!startsWith(line, kNcompKey) && !startsWith(line, kSplitsKey))
            pic.header.lines.push_back(line);
    const int n = sp.sampling.n;
    std::vector<double> s(n);
    for (size_t i = 0; i < pic.pixels.size(); ++i) {
        const float* src = sp.samples.data() + i * n;
        // RADIANCE compat: scolor2color() sums and divides in float; the sums of
        // unpacked samples are exact, and one double division rounded to float is the
        // float quotient, so spectral::bandAverages gives the same floats.
        std::copy(src, src + n, s.begin());
        const Color c = n == 3 ? Color(s[0], s[1], s[2]) : spectral::bandAverages(s, sp.sampling);
        Pixel p{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
        // fread2colrs stores the averages as RGBE (setcolr) before anyone reads them.
        if (how == SpectralToRgb::kBandAveragesRgbe) p = toPixel(toColr(p[0], p[1], p[2]));
        pic.pixels[i] = p;
    }
    return pic;
}

Picture readPictureAsRgb(std::istream& in, const std::string& what, SpectralToRgb how) {
    Header h = readHeader(in, what);
    if (isSpectralFormat(h)) return toRgbPicture(readAfterHeader(std::move(h), in, what), how);
    // Not spectral: readPicture reads it again from the top, the header replayed.
    std::ostringstream head;
    writeHeader(head, h);
    PrefixedBuf buf(head.str(), *in.rdbuf());
    std::istream again(&buf);
    return readPicture(again, what);
}

Picture readPictureAsRgb(const std::string& path, SpectralToRgb how) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open picture");
    return readPictureAsRgb(in, path, how);
}

}  // namespace rp
