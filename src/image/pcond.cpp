// pcond's options, header and the run from picture to conditioned picture (RADIANCE's
// pcond.c and nextscan); see pcond.h.
#include "image/pcond.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include "image/pcond_internal.h"
#include "image/picture.h"
#include "image/view.h"
#include "util/error.h"

namespace rp {
namespace {

using namespace pcond_detail;

constexpr const char* kUsage =
    "Usage: pcond [-{h|a|v|s|c|l|w}[+-]][-I|-i ffrac][-e ev][-p xr yr xg yg xb yb xw yw|-f "
    "mbf.cal|-m rgb.cwp][-u Ldmax][-d Lddyn][-x mapfile] inpic [outpic]";

std::string withUsage(const std::string& message) { return message + " (" + kUsage + ")"; }

// A RADIANCE switch (check_bool): alone it toggles each of its flags, with + y Y t T 1
// it sets them, with - n N f F 0 it clears them.
OptionSpec switchOption(const std::string& name, std::vector<bool*> flags) {
    return customOption(prefix(name, 3), name, [flags](OptionReader& r) {
        const std::string& w = r.option();
        const char c = w.size() > 2 ? w[2] : '\0';
        for (bool* f : flags) {
            if (c == '\0')
                *f = !*f;
            else if (std::string("yYtT+1").find(c) != std::string::npos)
                *f = true;
            else if (std::string("nNfF-0").find(c) != std::string::npos)
                *f = false;
            else
                throw InputError(withUsage("unknown option '" + w + "'"));
        }
    });
}

// -e: a multiplier, or f-stops when it starts with + or - (RADIANCE reads it with atof).
double readExposure(OptionReader& r) {
    const std::string& w = r.word();
    const std::optional<double> v = parseReal(w);
    if (!v) r.bad(w, ValueKind::kReal);
    const double e = (w[0] == '+' || w[0] == '-') ? std::pow(2.0, *v) : *v;
    r.require(e >= 0 && std::isfinite(e), "must be a multiplier >= 0 or +/-stops");
    return e;
}

std::function<std::string()> line(const char* s) {
    return [s] { return std::string(s); };
}

// The header RADIANCE's pcond writes before EXPOSURE= and FORMAT=: the input's lines
// without FORMAT=, EXPOSURE= and PRIMARIES=, the command line, and the output
// primaries when -p names them.
Header outputHeader(const Header& in, const std::string& history, const PcondOptions& opt) {
    Header h;
    for (const std::string& l : in.lines)
        if (l.rfind("EXPOSURE=", 0) != 0 && l.rfind("PRIMARIES=", 0) != 0) h.lines.push_back(l);
    h.lines.push_back(history);
    if (opt.primaries && opt.macbethFile.empty()) {
        const auto& p = *opt.primaries;
        char buf[160];
        std::snprintf(buf, sizeof buf, "PRIMARIES= %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f", p[0],
                      p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
        h.lines.push_back(buf);
    }
    return h;
}

// The picture's view, or RADIANCE's stand-in (a 40-degree perspective view on the
// longer side) for pictures without a usable one; sets c.view, c.hn and c.vn.
void setView(Context& c, const Picture& probe, const std::string& what) {
    std::optional<View> v;
    try {
        v = viewFromHeader(probe.header);
    } catch (const InputError&) {
        // a VIEW= line we cannot read counts as none
    }
    if (!v || v->type == ViewType::kParallel || v->horizontal <= 5. || v->vertical <= 5.) {
        const double aspect = probe.pixelAspect();
        const double xr = c.res.xres, yr = c.res.yres;
        v = View{};
        // .3639702 = tan(20 degrees): 40 degrees on the longer side.
        if (aspect * yr < xr) {
            v->horizontal = 40.0;
            v->vertical = 2. * 180. / M_PI * std::atan(.3639702 * aspect * yr / xr);
        } else {
            v->vertical = 40.0;
            v->horizontal = 2. * 180. / M_PI * std::atan(.3639702 * xr / aspect / yr);
        }
    }
    try {
        c.view.emplace(*v);
    } catch (const InputError& e) {
        throw InputError("view error in picture \"" + what + "\": " + e.message());
    }
    const ImagePlaneSize size = imagePlaneSize(*v);
    c.hn = size.horizontal;
    c.vn = size.vertical;
}

std::optional<Primaries> inputPrimaries(const Picture& probe) {
    const std::optional<std::array<double, 8>> p = probe.primaries();
    if (!p) return std::nullopt;
    Primaries f;
    for (int i = 0; i < 8; ++i) f[i] = static_cast<float>((*p)[i]);
    return f;
}

void readScanlines(std::istream& in, const std::string& what, Context& c) {
    c.pixels.resize(static_cast<size_t>(c.len) * c.count);
    std::vector<Colr> packed(c.len);
    for (int s = 0; s < c.count; ++s) {
        const std::string why = decodeScanline(*in.rdbuf(), packed.data(), c.len);
        if (!why.empty())
            throw InputError(SourceLoc{what, 0}, why + " (scanline " + std::to_string(s + 1) +
                                                     " of " + std::to_string(c.count) + ")");
        for (int p = 0; p < c.len; ++p)
            c.pixels[static_cast<size_t>(s) * c.len + p] = toPixel(packed[p]);
    }
}

Context makeContext(const PcondOptions& opt, const PictureInfo& info, const std::string& what) {
    Context c;
    c.what.acuity = opt.acuity;
    c.what.veil = opt.veil;
    c.what.sensitivity = opt.sensitivity;
    c.what.color = opt.color;
    c.what.centerWeight = opt.centerWeight;
    c.what.fixations = opt.fixations();
    c.what.preHistogram = opt.preHistogram;
    c.what.linear = opt.linear;
    c.fixationShare = opt.fixationShare;
    c.scale = opt.exposure;
    c.displayMax = opt.displayMax;
    c.displayRange = opt.displayRange;
    c.bldmin = brightness(opt.displayMax / opt.displayRange);
    c.bldmax = brightness(opt.displayMax);
    c.xyz = info.format == PictureFormat::kXyze;
    c.res = info.resolution;
    c.len = c.res.scanlineLength();
    c.count = c.res.scanlineCount();
    Picture probe;
    probe.header = info.header;
    c.inputExposure = probe.exposure();
    if (c.xyz && !opt.macbethFile.empty())
        throw InputError("macbethcal only works with RGB pictures");
    c.inputPrimaries = inputPrimaries(probe);
    if (!c.xyz) c.rgbToXyz = rgbToXyzBalanced(c.inputPrimaries);
    setView(c, probe, what);
    return c;
}

// Conditions each scanline and writes the picture (RADIANCE's nextscan): acuity
// resampling or the file's pixels, veil, colour loss, the tone map, output colours.
// The output colours: a macbethcal calibration, or a matrix to the output primaries
// when they differ from the input's, as the header and -p name them.
struct OutputColor {
    std::optional<Macbeth> macbeth;
    std::optional<ColorMatrix> matrix;
};

OutputColor outputColor(const Context& c, const PcondOptions& opt) {
    OutputColor oc;
    if (!opt.macbethFile.empty()) {
        std::ifstream f(opt.macbethFile);
        if (!f) throw InputError(SourceLoc{opt.macbethFile, 0}, "cannot open macbethcal file");
        oc.macbeth = readMacbeth(f, opt.macbethFile);
    } else if (c.xyz) {
        oc.matrix = xyzToRgbBalanced(opt.primaries);
    } else if (c.inputPrimaries || opt.primaries) {
        // RADIANCE compat: an input PRIMARIES= line converts to the standard primaries
        // (or -p's): pcond.c sets outprims from inprims before it has read the header.
        oc.matrix = rgbToRgbBalanced(c.inputPrimaries, opt.primaries);
    }
    return oc;
}

void writeScanlines(Context& c, const OutputColor& color, Header header, std::ostream& out) {
    header.lines.push_back(std::string("FORMAT=") + kRgbeFormat);
    writeHeader(out, header);
    out << formatResolution(c.res) << '\n';
    std::optional<AcuitySampler> sampler;
    if (c.what.acuity) sampler.emplace(c);
    std::vector<Pixel> scan(c.len);
    std::vector<Colr> packed(c.len);
    std::string bytes;
    for (int s = 0; s < c.count; ++s) {
        if (sampler)
            sampler->scanline(scan.data(), s);
        else
            std::copy(c.scan(s), c.scan(s) + c.len, scan.begin());
        if (c.what.veil) addVeil(c, scan.data(), s);
        if (c.what.color) scotopicScan(c, scan.data(), c.len);
        if (c.what.linear) {
            for (Pixel& p : scan)
                for (float& v : p) v = static_cast<float>(v * c.scale);
        } else {
            mapScan(c, scan.data(), c.len);
        }
        if (color.macbeth)
            macbethScan(*color.macbeth, scan.data(), c.len);
        else if (color.matrix)
            matrixScan(*color.matrix, scan.data(), c.len);
        for (int p = 0; p < c.len; ++p) packed[p] = toColr(scan[p]);
        bytes.clear();
        encodeScanline(packed.data(), c.len, bytes);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
}

}  // namespace

OptionTable pcondTable(PcondOptions& o) {
    OptionTable t;
    t.messages.unknown = [](const std::string& a) {
        return withUsage("unknown option '" + a + "'");
    };
    t.messages.missing = [](const std::string& a) {
        return withUsage("missing value for option '" + a + "'");
    };
    t.add(switchOption("-h", {&o.acuity, &o.veil, &o.sensitivity, &o.color}),
          line("-h-\t\t\t\t# human visual response (-a -v -s -c together)\n"));
    t.add(switchOption("-a", {&o.acuity}), line("-a-\t\t\t\t# acuity loss in the dark\n"));
    t.add(switchOption("-v", {&o.veil}), line("-v-\t\t\t\t# veiling glare\n"));
    t.add(switchOption("-s", {&o.sensitivity}), line("-s-\t\t\t\t# human contrast sensitivity\n"));
    t.add(switchOption("-c", {&o.color}), line("-c-\t\t\t\t# mesopic/scotopic colour loss\n"));
    t.add(switchOption("-w", {&o.centerWeight}), line("-w-\t\t\t\t# centre-weighted histogram\n"));
    t.add(switchOption("-l", {&o.linear}), line("-l-\t\t\t\t# linear response\n"));
    t.add(switchOption("-I", {&o.preHistogram}),
          line("-I-\t\t\t\t# histogram from standard input\n"));
    t.add(customOption("-i",
                       [&o](OptionReader& r) {
                           o.fixationShare = r.real();
                           r.require(o.fixationShare <= 1, "must be between 0 and 1");
                       }),
          line("-i 0\t\t\t\t# share of fixations from standard input\n"));
    t.add(customOption("-e",
                       [&o](OptionReader& r) {
                           o.exposure = readExposure(r);
                           o.linear = true;
                       }),
          line("-e 0\t\t\t\t# linear exposure (0: automatic)\n"));
    t.add(customOption("-p",
                       [&o](OptionReader& r) {
                           std::array<float, 8> p;
                           for (float& v : p) v = static_cast<float>(r.real());
                           o.primaries = p;
                       }),
          line("-p std\t\t\t\t# output primaries (RADIANCE's standard)\n"));
    t.add(valueOption("-f", o.macbethFile), line("-f none\t\t\t\t# macbethcal calibration\n"));
    t.add(valueOption("-m", o.colorWarpFile));
    t.add(valueOption(
              "-u", o.displayMax, [](double v) { return v > 1e-6; }, "must be > 0"),
          line("-u 100\t\t\t\t# display maximum luminance (cd/m^2)\n"));
    t.add(valueOption(
              "-d", o.displayRange, [](double v) { return v > 1; }, "must be > 1"),
          line("-d 100\t\t\t\t# display dynamic range\n"));
    t.add(valueOption("-x", o.mapFile), line("-x none\t\t\t\t# mapping output file\n"));
    return t;
}

PcondOptions parsePcondArgs(std::vector<std::string>& args) {
    PcondOptions opt;
    const OptionTable table = pcondTable(opt);
    const size_t i = table.parse(args, 0).next;
    if (opt.fixations() && opt.preHistogram) throw InputError("only one of -i or -I option");
    if (!opt.macbethFile.empty() + !opt.colorWarpFile.empty() + opt.primaries.has_value() > 1)
        throw InputError("only one of -p, -m or -f option supported");
    if (!opt.colorWarpFile.empty())
        throw InputError("colour warp files (-m " + opt.colorWarpFile + ") are not supported");
    if (i >= args.size() || i + 2 < args.size())
        throw InputError(withUsage("expected an input picture and at most one output picture"));
    opt.inputFile = args[i];
    if (i + 1 < args.size()) opt.outputFile = args[i + 1];
    return opt;
}

void runPcond(std::istream& in, const std::string& what, const PcondOptions& opt,
              const std::string& history, std::ostream& out, std::istream* side,
              std::ostream* mapOut) {
    const PictureInfo info = readPictureInfo(in, what);
    Context c = makeContext(opt, info, what);
    readScanlines(in, what, c);
    const OutputColor color = outputColor(c, opt);
    Header header = outputHeader(info.header, history, opt);

    // Adaptation: foveal samples (unless a histogram is given and nothing else needs
    // them), the histogram, and what is worth doing.
    std::istringstream none;
    std::istream& sideIn = side ? *side : none;
    const Flags& w = c.what;
    if (!w.preHistogram || w.veil || w.acuity) computeFovea(c, info.header, info.format, what);
    if (w.preHistogram)
        readHistogram(c, sideIn);
    else if (w.fixations)
        readFixations(c, sideIn);
    computeHistogram(c);
    checkWhatToDo(c);
    if (c.what.veil) computeVeil(c);
    if (!c.what.linear && !makeBrightnessMap(c)) c.what.linear = true;
    if (c.what.linear) {
        if (c.scale <= kTiny) {  // mean world brightness to the middle of the display's
            const double mid = luminanceOf(0.5 * (c.bldmax + c.bldmin));
            const double avg = luminanceOf(c.hist.bwavg);
            c.scale =
                c.what.sensitivity ? contrastThreshold(mid) / contrastThreshold(avg) : mid / avg;
            c.scale *= kWhiteEfficacy / (c.inputExposure * c.displayMax);
        }
        char buf[64];
        std::snprintf(buf, sizeof buf, "EXPOSURE=%e", c.inputExposure * c.scale);
        header.lines.push_back(buf);
        if (c.xyz) c.scale /= kWhiteEfficacy;
    }
    writeScanlines(c, color, header, out);
    if (mapOut) writeMapping(c, *mapOut);
}

}  // namespace rp
