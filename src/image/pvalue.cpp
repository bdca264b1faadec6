#include "image/pvalue.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include "image/spectral_picture.h"
#include "util/error.h"
#include "util/options.h"

namespace rp {
namespace {

const char* formatName(ValueFormat f) {
    switch (f) {
        case ValueFormat::kFloat:
            return "float";
        case ValueFormat::kDouble:
            return "double";
        default:
            return "ascii";
    }
}

// Positive integer option value; anything else names the option.
// -x, -y and their capital and '+' forms: a picture size.
int sizeValue(OptionReader& r) {
    const std::string& v = r.word();
    const std::optional<long> n = parseInteger(v);
    if (!n || *n <= 0 || *n > (1 << 24))
        throw InputError("bad size '" + v + "' for option '" + r.option() + "'");
    return static_cast<int>(*n);
}

bool parseNumber(const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return !s.empty() && *end == '\0';
}

// Picture position (x from the left, y from the top) of the p-th pixel of scanline s,
// as pix2loc() in RADIANCE's image.c orders a resolution string's pixels.
void scanToPicture(const Resolution& r, int s, int p, int& x, int& yTop) {
    int x0 = r.yMajor ? p : s, y0 = r.yMajor ? s : p;
    if (r.xDecreasing) x0 = r.xres - 1 - x0;
    if (r.yDecreasing) y0 = r.yres - 1 - y0;
    x = x0;
    yTop = r.yres - 1 - y0;  // y0 counts from the bottom
}

template <typename T>
void putBinary(std::ostream& out, double v) {
    T t = static_cast<T>(v);
    out.write(reinterpret_cast<const char*>(&t), sizeof t);
}

// One pixel's values (coordinates first, RADIANCE's image coordinates: y from the
// bottom) in the chosen format; ASCII as pvalue.c's "%7d %7d " and "%15.3e".
void putPixel(std::ostream& out, const PvalueOptions& opt, int x, int yUp, const double* v, int n) {
    if (opt.format == ValueFormat::kAscii) {
        char buf[64];
        if (opt.coordinates) {
            std::snprintf(buf, sizeof buf, "%7d %7d ", x, yUp);
            out << buf;
        }
        for (int i = 0; i < n; ++i) {
            std::snprintf(buf, sizeof buf, i + 1 < n ? "%15.3e " : "%15.3e\n", v[i]);
            out << buf;
        }
        return;
    }
    auto put = opt.format == ValueFormat::kFloat ? putBinary<float> : putBinary<double>;
    // Binary coordinates use the value type too, so every record is n+2 equal fields.
    if (opt.coordinates) {
        put(out, x);
        put(out, yUp);
    }
    for (int i = 0; i < n; ++i) put(out, v[i]);
}

// Fills pixels from a stream of records: each is (x, y)? then 1 or 3 values. Coordinates
// place the pixel (so any order works); without them records come in scanline order.
class PixelSink {
public:
    PixelSink(Picture& pic, const Resolution& res, const PvalueOptions& opt,
              const std::string& what)
        : pic_(pic), res_(res), opt_(opt), what_(what) {}

    int fieldsPerPixel() const { return (opt_.coordinates ? 2 : 0) + (opt_.brightness ? 1 : 3); }
    long long count() const { return count_; }
    std::string resolution() const { return formatResolution(res_); }
    long long needed() const { return static_cast<long long>(res_.xres) * res_.yres; }

    void add(const double* f, int line) {
        if (count_ >= needed())
            throw InputError(SourceLoc{what_, line}, "more pixels than the resolution " +
                                                         formatResolution(res_) + " holds (" +
                                                         std::to_string(needed()) + ")");
        int x, yTop;
        const double* v = f;
        if (opt_.coordinates) {
            double cx = f[0], cy = f[1];
            if (cx != std::floor(cx) || cy != std::floor(cy) || cx < 0 || cy < 0 ||
                cx >= res_.xres || cy >= res_.yres)
                throw InputError(SourceLoc{what_, line}, "coordinates (" + fmtNum(cx) + ", " +
                                                             fmtNum(cy) + ") outside the picture " +
                                                             formatResolution(res_));
            x = static_cast<int>(cx);
            yTop = res_.yres - 1 - static_cast<int>(cy);
            v += 2;
        } else {
            scanToPicture(res_, static_cast<int>(count_ / res_.scanlineLength()),
                          static_cast<int>(count_ % res_.scanlineLength()), x, yTop);
        }
        double e = opt_.exposure;
        Pixel& p = pic_.at(x, yTop);
        if (opt_.brightness) {
            p = {float(v[0] * e), float(v[0] * e), float(v[0] * e)};
        } else {
            p = {float(v[0] * e), float(v[1] * e), float(v[2] * e)};
        }
        ++count_;
    }

    void finish(int line) const {
        if (count_ < needed())
            throw InputError(SourceLoc{what_, line}, "input ends after " + std::to_string(count_) +
                                                         " of " + std::to_string(needed()) +
                                                         " pixels for the resolution " +
                                                         formatResolution(res_));
    }

private:
    static std::string fmtNum(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }
    Picture& pic_;
    const Resolution& res_;
    const PvalueOptions& opt_;
    const std::string& what_;
    long long count_ = 0;
};

// ASCII input is read a line at a time so errors can name the line; each non-blank line
// is one pixel, as pvalue and rtrace write them.
void readAsciiPixels(std::istream& in, PixelSink& sink, const std::string& what, int line) {
    const int n = sink.fieldsPerPixel();
    std::string text, tok;
    std::vector<double> f(n);
    while (std::getline(in, text)) {
        ++line;
        std::istringstream ls(text);
        int k = 0;
        while (ls >> tok) {
            double v;
            if (!parseNumber(tok, v))
                throw InputError(SourceLoc{what, line}, "'" + tok + "' is not a number");
            if (k < n) f[k] = v;
            ++k;
        }
        if (k == 0) continue;
        if (k != n)
            throw InputError(SourceLoc{what, line}, std::to_string(k) + " value" +
                                                        (k == 1 ? "" : "s") + " on the line, " +
                                                        std::to_string(n) + " expected");
        sink.add(f.data(), line);
    }
    sink.finish(line);
}

template <typename T>
void readBinaryPixels(std::istream& in, PixelSink& sink, const std::string& what) {
    const int n = sink.fieldsPerPixel();
    std::vector<T> raw(n);
    std::vector<double> f(n);
    while (sink.count() < sink.needed()) {
        if (!in.read(reinterpret_cast<char*>(raw.data()), sizeof(T) * n)) sink.finish(0);
        for (int i = 0; i < n; ++i) f[i] = raw[i];
        sink.add(f.data(), 0);
    }
    if (in.peek() != std::char_traits<char>::eof())
        throw InputError(SourceLoc{what, 0},
                         "more data than the resolution " + sink.resolution() + " holds");
}

}  // namespace

OptionTable pvalueTable(PvalueOptions& opt, PvalueSize& size) {
    OptionTable t;
    t.defaultsStops = false;  // -defaults is the tool's, at argv[1] (tools/info_options.h)
    t.plusWords = true;
    t.messages.unknown = [](const std::string& a) { return "bad option '" + a + "'"; };
    // Every option is "-x" or "+x"; `read` gets whether it was '-'.
    auto both = [&t](std::vector<std::string> names, std::function<void(OptionReader&, bool)> read,
                     std::function<std::string()> defaults = {}) {
        auto matches = [names](const std::string& w) {
            for (const std::string& n : names)
                if (w.size() == n.size() + 1 && (w[0] == '-' || w[0] == '+') && w.substr(1) == n)
                    return true;
            return false;
        };
        t.add(customOption(
                  matches, "-" + names[0],
                  [read = std::move(read)](OptionReader& r) { read(r, r.option()[0] == '-'); }),
              std::move(defaults));
    };
    auto sign = [](bool plus) { return plus ? '+' : '-'; };
    both(
        {"h"}, [&opt](OptionReader&, bool minus) { opt.header = !minus; },
        [&opt, sign] { return formatLine("-h%c\t\t\t\t# header\n", sign(opt.header)); });
    both(
        {"H"}, [&opt](OptionReader&, bool minus) { opt.resolution = !minus; },
        [&opt, sign] {
            return formatLine("-H%c\t\t\t\t# resolution string\n", sign(opt.resolution));
        });
    both(
        {"o"}, [&opt](OptionReader&, bool minus) { opt.original = minus; },
        [&opt, sign] {
            return formatLine("-o%c\t\t\t\t# values after exposure\n", sign(opt.original));
        });
    both(
        {"b"}, [&opt](OptionReader&, bool minus) { opt.brightness = minus; },
        [&opt, sign] {
            return formatLine("-b%c\t\t\t\t# three values per pixel (-b+: brightness)\n",
                              sign(opt.brightness));
        });
    both({"r"}, [&opt](OptionReader&, bool minus) { opt.reverse = minus; });
    // As pvalue.c: "-d?" drops the coordinates, "+d?" keeps them; ? picks the type.
    both(
        {"d", "da", "df", "dd"},
        [&opt](OptionReader& r, bool minus) {
            opt.coordinates = !minus;
            const std::string& a = r.option();
            opt.format = a == "-df" || a == "+df"   ? ValueFormat::kFloat
                         : a == "-dd" || a == "+dd" ? ValueFormat::kDouble
                                                    : ValueFormat::kAscii;
        },
        [&opt, sign] {
            const char type = opt.format == ValueFormat::kFloat    ? 'f'
                              : opt.format == ValueFormat::kDouble ? 'd'
                                                                   : 'a';
            return formatLine("%cd%c\t\t\t\t# ASCII values with pixel coordinates\n",
                              sign(opt.coordinates), type);
        });
    both(
        {"e"},
        [&opt](OptionReader& r, bool) {
            if (!r.hasNext()) throw InputError("missing value for option '-e'");
            const std::string& v = r.word();
            double e;
            if (!parseNumber(v, e)) throw InputError("bad exposure '" + v + "' for option '-e'");
            // RADIANCE: a signed exposure is in f-stops, an unsigned one a multiplier.
            opt.exposure = (v[0] == '+' || v[0] == '-') ? std::pow(2.0, e) : e;
            if (!(opt.exposure > 0)) throw InputError("bad exposure '" + v + "' for option '-e'");
        },
        [&opt] { return formatLine("-e  %g\t\t\t\t# exposure\n", opt.exposure); });
    // The first of x and y given is the major (scanline) one.
    both({"x", "X"}, [&size](OptionReader& r, bool minus) {
        size.x = sizeValue(r);
        size.res.xDecreasing = minus;
        if (size.first) size.res.yMajor = false;
        size.first = false;
    });
    both({"y", "Y"}, [&size](OptionReader& r, bool minus) {
        size.y = sizeValue(r);
        size.res.yDecreasing = minus;
        if (size.first) size.res.yMajor = true;
        size.first = false;
    });
    return t;
}

PvalueOptions parsePvalueArgs(const std::vector<std::string>& args) {
    PvalueOptions opt;
    PvalueSize size;
    const OptionTable table = pvalueTable(opt, size);
    bool haveInput = false;
    // Options may stand on either side of the input file.
    std::vector<std::string> words = args;
    for (size_t i = table.parse(words, 0).next; i < words.size();
         i = table.parse(words, i + 1).next) {
        if (words[i] == "-version") throw InputError("bad option '-version'");
        if (haveInput) throw InputError("more than one input file ('" + words[i] + "')");
        opt.input = words[i];
        haveInput = true;
    }
    const int xres = size.x, yres = size.y;
    Resolution res = size.res;
    if ((xres > 0) != (yres > 0)) throw InputError("give both the x and the y resolution");
    if (xres > 0) {
        res.xres = xres;
        res.yres = yres;
        opt.size = res;
    }
    return opt;
}

void writeValues(std::ostream& out, const Picture& pic, const PvalueOptions& opt,
                 const std::string& commandLine) {
    if (opt.header) {
        Header h = pic.header;
        h.lines.push_back(commandLine);
        h.lines.push_back(std::string("FORMAT=") + formatName(opt.format));
        writeHeader(out, h);
    }
    if (opt.resolution) {
        Resolution r;
        r.xres = pic.width;
        r.yres = pic.height;
        out << formatResolution(r) << '\n';
    }
    std::array<double, 3> scale{opt.exposure, opt.exposure, opt.exposure};
    if (opt.original) {
        // The file's values carry EXPOSURE and COLORCORR; -o takes them back out.
        const double e = pic.exposure();
        const auto cc = pic.colorCorrection();
        for (int c = 0; c < 3; ++c) scale[c] /= e * cc[c];
    }
    const bool xyz = pic.format == PictureFormat::kXyze;
    for (int y = 0; y < pic.height; ++y) {
        for (int x = 0; x < pic.width; ++x) {
            const Pixel& p = pic.at(x, y);
            double v[3] = {p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]};
            if (opt.brightness)
                v[0] = xyz ? v[1] : brightness({float(v[0]), float(v[1]), float(v[2])});
            putPixel(out, opt, x, pic.height - 1 - y, v, opt.brightness ? 1 : 3);
        }
    }
}

Picture readValues(std::istream& in, const std::string& what, const PvalueOptions& opt,
                   const std::string& commandLine) {
    Header header;
    int line = 0;
    if (opt.header) {
        header = readHeader(in, what);
        line += static_cast<int>(header.lines.size()) + 2;
        const std::string fmt = header.format();
        if (!fmt.empty() && fmt != formatName(opt.format))
            throw InputError(SourceLoc{what, 0}, "FORMAT=" + fmt + " in the header, expected " +
                                                     formatName(opt.format));
    }
    std::optional<Resolution> res = opt.size;
    if (opt.resolution) {
        std::string text;
        ++line;
        if (!std::getline(in, text))
            throw InputError(SourceLoc{what, line}, "missing resolution string");
        auto r = parseResolution(text);
        if (!r) throw InputError(SourceLoc{what, line}, "bad resolution string '" + text + "'");
        if (!res) res = r;  // the command line's size wins, as given explicitly
    }
    if (!res)
        throw InputError(SourceLoc{what, 0},
                         "no resolution: give -y N +x M or a resolution string (without -H)");

    Picture pic(res->xres, res->yres);
    for (const auto& l : header.lines)
        if (l.rfind("FORMAT=", 0) != 0) pic.header.lines.push_back(l);
    pic.header.lines.push_back(commandLine);
    if (opt.exposure != 1) pic.addExposure(opt.exposure);

    PixelSink sink(pic, *res, opt, what);
    switch (opt.format) {
        case ValueFormat::kAscii:
            readAsciiPixels(in, sink, what, line);
            break;
        case ValueFormat::kFloat:
            readBinaryPixels<float>(in, sink, what);
            break;
        case ValueFormat::kDouble:
            readBinaryPixels<double>(in, sink, what);
            break;
    }
    return pic;
}

void runPvalue(const PvalueOptions& opt, const std::string& commandLine, std::istream& in,
               std::ostream& out) {
    std::ifstream file;
    std::istream* src = &in;
    std::string what = "standard input";
    if (opt.input != "-") {
        what = opt.input;
        file.open(opt.input, std::ios::binary);
        if (!file) throw InputError(SourceLoc{what, 0}, "cannot open input");
        src = &file;
    }
    if (opt.reverse) {
        writePicture(out, readValues(*src, what, opt, commandLine));
    } else {
        // RADIANCE compat: pvalue reads a spectral picture with fread2scan(), each pixel
        // its band averages (scolr2color), and does not echo NCOMP=/WAVELENGTH_SPLITS=.
        writeValues(out, readPictureAsRgb(*src, what, SpectralToRgb::kBandAverages), opt,
                    commandLine);
    }
}

}  // namespace rp
