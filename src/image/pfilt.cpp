// pfilt's options, output size, passes and header (see pfilt.h); the filters themselves
// are in pfilt_filter.cpp.
#include "image/pfilt.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "image/pfilt_filter.h"
#include "image/tonemap.h"  // parseExposureArg
#include "image/view.h"
#include "util/error.h"

namespace rp {
namespace {

constexpr const char* kUsage =
    "usage: pfilt [-x xres|/f][-y yres|/f][-p aspect][-c][-e[rgb] exp|+/-stops][-1|-2]"
    "[-r rad|-m thresh|-b][-n npts][-s spread][-h hotlvl][-a] [picture]";
constexpr double kAverageLevel = 0.5;  // the first pass puts the mean brightness here

// "N" or "/f" for -x and -y.
void readResolution(OptionReader& r, int& count, double& ratio) {
    const std::string& v = r.word();
    if (!v.empty() && v[0] == '/') {
        const std::optional<double> f = parseReal(v.substr(1));
        if (!f || !(*f > 0)) r.bad(v, ValueKind::kReal);
        ratio = 1 / *f;
        count = 0;
    } else {
        const std::optional<long> n = parseInteger(v);
        if (!n || *n <= 0 || *n > 1000000) r.bad(v, ValueKind::kInteger);
        count = static_cast<int>(*n);
    }
}

bool roughlyOne(double a, double b) { return a >= .98 * b && a <= 1.02 * b; }

}  // namespace

OptionTable pfiltTable(PfiltOptions& o) {
    OptionTable t;
    t.messages.unknown = [](const std::string& a) {
        return "unknown option '" + a + "' (" + kUsage + ")";
    };
    auto line = [](const char* s) { return [s] { return std::string(s); }; };
    // RADIANCE compat (pfilt.c): an option is known by its second character, so the
    // renders Makefile's "-pa 1" is -p (-e keeps its -er -eg -eb).
    auto addLoose = [&t](OptionSpec spec, std::function<std::string()> defaults = {}) {
        spec.matches = prefix(spec.name);
        t.add(std::move(spec), std::move(defaults));
    };
    addLoose(customOption("-x", [&o](OptionReader& r) { readResolution(r, o.xres, o.xRatio); }),
             line("-x  same\t\t\t# output x resolution (N, or /f: input divided by f)\n"));
    addLoose(customOption("-y", [&o](OptionReader& r) { readResolution(r, o.yres, o.yRatio); }),
             line("-y  same\t\t\t# output y resolution (N or /f)\n"));
    addLoose(valueOption(
                 "-p", o.pixelAspect, [](double v) { return v >= 0; }, "must be >= 0"),
             line("-p  0\t\t\t\t# output pixel aspect (0: as the sizes give)\n"));
    addLoose(customOption("-c", [&o](OptionReader&) { o.correctAspect = !o.correctAspect; }),
             line("-c  off\t\t\t\t# aspect corrected: no PIXASPECT= line\n"));
    for (int k = -1; k < 3; ++k) {
        static const char* const names[] = {"-er", "-eg", "-eb"};
        const std::string name = k < 0 ? "-e" : names[k];
        t.add(customOption(name,
                           [&o, k](OptionReader& r) {
                               const double d = parseExposureArg(r.word());
                               if (d < 1e-20 || d > 1e20) throw InputError("exposure out of range");
                               for (int c = 0; c < 3; ++c)
                                   if (k < 0 || k == c) o.exposure[c] *= d;
                           }),
              k < 0 ? line("-e  1\t\t\t\t# exposure (times the 0.5 average unless -1)\n")
                    : std::function<std::string()>{});
    }
    addLoose(customOption("-1", [&o](OptionReader&) { o.singlePass = true; }),
             line("-2\t\t\t\t# two passes (-1: one, no automatic exposure)\n"));
    addLoose(customOption("-2", [&o](OptionReader&) { o.singlePass = false; }));
    addLoose(customOption("-n",
                          [&o](OptionReader& r) {
                              o.starPoints = static_cast<int>(r.integer(0, 1000000)) / 2;
                          }),
             line("-n  0\t\t\t\t# star points on hot pixels\n"));
    addLoose(valueOption(
                 "-s", o.spread, [](double v) { return v >= 0; }, "must be >= 0"),
             line("-s  0.0001\t\t\t# star spread\n"));
    addLoose(customOption("-a", [&o](OptionReader&) { o.averageHot = !o.averageHot; }),
             line("-a  off\t\t\t\t# average hot pixels too\n"));
    addLoose(valueOption("-h", o.hotLevel), line("-h  100\t\t\t\t# hot level\n"));
    addLoose(valueOption(
                 "-r", o.radius, [](double v) { return v >= 0; }, "must be >= 0"),
             line("-r  0\t\t\t\t# Gaussian radius (0: box filter)\n"));
    addLoose(customOption("-m",
                          [&o](OptionReader& r) {
                              o.threshold = r.real();
                              r.require(o.threshold >= 0, "must be >= 0");
                              if (o.radius <= 1e-6) o.radius = 0.6;
                          }),
             line("-m  0\t\t\t\t# threshold filter limit\n"));
    addLoose(customOption("-b", [&o](OptionReader&) { o.radius = o.threshold = 0; }));
    return t;
}

PfiltOptions parsePfiltArgs(std::vector<std::string>& args, size_t& optionWords) {
    PfiltOptions opt;
    const OptionTable table = pfiltTable(opt);
    const size_t i = table.parse(args, 0).next;
    optionWords = i;
    if (i + 1 < args.size()) throw InputError(std::string("bad # file arguments (") + kUsage + ")");
    if (i < args.size()) opt.inputFile = args[i];
    return opt;
}

PfiltSize pfiltOutputSize(int xres, int yres, double aspect, const PfiltOptions& opt) {
    PfiltSize s{opt.xres, opt.yres};
    if (s.ncols <= 0) s.ncols = static_cast<int>(opt.xRatio * xres + .5);
    if (s.nrows <= 0) s.nrows = static_cast<int>(opt.yRatio * yres + .5);
    if (opt.pixelAspect > .01) {
        const double d = aspect * yres / xres / opt.pixelAspect;
        if (d * s.ncols > s.nrows)
            s.ncols = static_cast<int>(s.nrows / d);
        else
            s.nrows = static_cast<int>(s.ncols * d);
    }
    if (s.ncols <= 0 || s.nrows <= 0) throw InputError("output picture would be empty");
    return s;
}

long Rand48::next() {
    state_ = (0x5DEECE66DULL * state_ + 0xB) & ((1ULL << 48) - 1);
    return static_cast<long>(state_ >> 17);
}

Picture runPfilt(const Picture& in, const PfiltOptions& opt, const std::string& history,
                 const std::string& what, bool yMajor) {
    PfiltFrame f;
    f.xres = in.width;
    f.yres = in.height;
    f.xyz = in.format == PictureFormat::kXyze;
    std::optional<View> view;
    try {
        view = viewFromHeader(in.header);
    } catch (const InputError&) {
        // a view we cannot read only means no wrapping, as RADIANCE's sscanview failing
    }
    f.wrap =
        yMajor && view && view->type == ViewType::kCylindrical && view->horizontal >= 360. - 1e-6;
    const PfiltSize size =
        pfiltOutputSize(in.width, in.height, yMajor ? in.pixelAspect() : 1 / in.pixelAspect(), opt);
    f.ncols = size.ncols;
    f.nrows = size.nrows;
    f.xRatio = static_cast<double>(f.ncols) / f.xres;
    f.yRatio = static_cast<double>(f.nrows) / f.yres;
    f.radius = opt.radius;
    f.threshold = opt.threshold;

    // First pass: the average brightness below the hot level, and the hot pixels.
    const double hotLevel = opt.hotLevel * in.exposure();
    std::vector<HotPixel> hot;
    double average = kAverageLevel;
    if (!opt.singlePass) {
        double sum = 0;
        long count = 0;
        Rand48 random;
        for (int y = 0; y < f.yres; ++y)
            for (int x = 0; x < f.xres; ++x) {
                const double b = f.brightness(in.at(x, y));
                if (b <= 0) continue;
                if (opt.averageHot || b < hotLevel) {
                    sum += b;
                    ++count;
                }
                if (opt.starPoints && b >= hotLevel) {
                    const long k = random.next() % opt.starPoints;
                    const double slope = std::tan(M_PI * (0.5 - (k + 0.5) / opt.starPoints));
                    hot.push_back({in.at(x, y), x, y, static_cast<float>(slope)});
                }
            }
        if (count == 0) throw InputError(SourceLoc{what, 0}, "picture too dark or too bright");
        average = sum / static_cast<double>(count);
    }
    std::array<double, 3> exposure = opt.exposure;
    for (double& e : exposure) e *= kAverageLevel / average;

    // Second pass: star points, exposure, filter.
    Picture exposed = in;
    if (!hot.empty()) {
        const double spreadFactor =
            opt.spread /
            (hotLevel *
             f.brightness(Pixel{float(exposure[0]), float(exposure[1]), float(exposure[2])})) *
            (double(f.xres) * f.xres + double(f.yres) * f.yres) / 4.0;
        addStarPoints(exposed, hot, spreadFactor);
    }
    for (Pixel& p : exposed.pixels)
        for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(p[c] * exposure[c]);

    Picture out = filterPicture(exposed, f);
    out.format = in.format;
    out.header = in.header;
    out.header.lines.push_back(history);
    char buf[128];
    if (!opt.correctAspect) {
        const double d = yMajor ? f.xRatio / f.yRatio : f.yRatio / f.xRatio;
        if (!roughlyOne(d, 1.0)) {
            std::snprintf(buf, sizeof buf, "PIXASPECT=%f", d);
            out.header.lines.push_back(buf);
        }
    }
    const Pixel ep{float(exposure[0]), float(exposure[1]), float(exposure[2])};
    const double d = f.brightness(ep);
    if (!roughlyOne(d, 1.0)) {
        std::snprintf(buf, sizeof buf, "EXPOSURE=%e", d);
        out.header.lines.push_back(buf);
    }
    const double scale = 1.0 / d;  // the correction in float, as RADIANCE's COLOR
    const float cc[3] = {float(ep[0] * scale), float(ep[1] * scale), float(ep[2] * scale)};
    if (!roughlyOne(cc[0], cc[1]) || !roughlyOne(cc[1], cc[2])) {
        std::snprintf(buf, sizeof buf, "COLORCORR= %f %f %f", cc[0], cc[1], cc[2]);
        out.header.lines.push_back(buf);
    }
    return out;
}

void runPfilt(std::istream& in, const std::string& what, const PfiltOptions& opt,
              const std::string& history, std::ostream& out) {
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::istringstream infoStream(bytes), pictureStream(bytes);
    const Resolution res = readPictureInfo(infoStream, what).resolution;
    const Picture pic = readPicture(pictureStream, what);
    // The picture as its file stores it: row s is scanline s, column p its p-th pixel
    // (the inverse of readPicture's mapping).
    const int len = res.scanlineLength(), count = res.scanlineCount();
    Picture scans(len, count);
    scans.format = pic.format;
    scans.header = pic.header;
    for (int sl = 0; sl < count; ++sl)
        for (int p = 0; p < len; ++p) {
            int x = res.yMajor ? p : sl, y = res.yMajor ? sl : p;
            if (res.xDecreasing) x = res.xres - 1 - x;
            if (res.yDecreasing) y = res.yres - 1 - y;
            scans.at(p, sl) = pic.at(x, res.yres - 1 - y);
        }
    const Picture filtered = runPfilt(scans, opt, history, what, res.yMajor);
    if (res.yMajor && res.yDecreasing && !res.xDecreasing) {
        writePicture(out, filtered);
        return;
    }
    // Written in the input's order, as RADIANCE's pfilt does.
    Header h = filtered.header;
    std::erase_if(h.lines, [](const std::string& l) { return l.rfind("FORMAT=", 0) == 0; });
    h.lines.push_back(std::string("FORMAT=") +
                      (filtered.format == PictureFormat::kXyze ? kXyzeFormat : kRgbeFormat));
    std::ostringstream hs;
    writeHeader(hs, h);
    Resolution r = res;
    r.xres = res.yMajor ? filtered.width : filtered.height;
    r.yres = res.yMajor ? filtered.height : filtered.width;
    hs << formatResolution(r) << '\n';
    std::string data = hs.str();
    std::vector<Colr> scan(filtered.width);
    for (int y = 0; y < filtered.height; ++y) {
        for (int x = 0; x < filtered.width; ++x) scan[x] = toColr(filtered.at(x, y));
        encodeScanline(scan.data(), filtered.width, data);
    }
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
}

}  // namespace rp
