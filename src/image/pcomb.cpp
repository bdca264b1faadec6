// pcomb (see pcomb.h), after RADIANCE 5.4's px/pcomb.c. The inputs reach the .cal code
// through the calc module's input channels: the prelude below turns ri(n, dx, dy) and
// the other input functions into one channel number (component, input, offsets) that
// PcombChannels decodes.
#include "image/pcomb.h"

#include <fmt/format.h>

#include <algorithm>

#include "calc/program.h"
#include "calc/ray_context.h"
#include "image/view.h"
#include "util/error.h"

namespace rp {
namespace {

constexpr const char* kUsage =
    "usage: pcomb [-w][-h][-x xr][-y yr][-e expr][-f file] [ [-o][-s f][-c r g b] hdr ..]";
constexpr int kComponents = 9;  // r g b l, exposures r g b l, pixel aspect
constexpr int kYDown = 64;      // RADIANCE's scanline window: y offsets -64 .. 62
constexpr int kYUp = 62;
constexpr double kWhiteEfficacy = 179.0;  // RADIANCE WHTEFFICACY

// RADIANCE bright() with its standard primaries; XYZ pictures use Y.
double brightness(const Pixel& p, bool xyz) {
    if (xyz) return p[1];
    return 0.265074126 * p[0] + 0.670114631 * p[1] + 0.064811243 * p[2];
}

// ri gi bi li (components 0-3) take an input and optional offsets; re ge be le pa (4-8)
// only an input. A bad input number gives channel -1 (value 0, as RADIANCE's EDOM).
constexpr const char* kPrelude = R"(
pc_n(n) = if(n + .5, if(nfiles + .5 - n, floor(n + .5), -1), -1);
pc_r(d) = if(d, floor(d + .5), -floor(.5 - d));
pc_cl(v, lo, hi) = if(lo - v, lo, if(v - hi, hi, v));
pc_k(dx, dy) = if(dx * dx + dy * dy, 1 + pc_cl(dx, -xmax, xmax) + xmax +
                  (2 * xmax + 1) * (pc_cl(dy, -64, 62) + 64), 0);
pc_ch(c, n, dx, dy) = if(pc_n(n) + .5, 1 + c + 9 * (pc_n(n) + (nfiles + 1) *
                         pc_k(pc_r(dx), pc_r(dy))), -1);
pc_in(c, n, a, dx, dy) = in(pc_ch(c, n, if(a - 1.5, dx, 0), if(a - 2.5, dy, 0)));
ri(n) = pc_in(0, n, arg(0), if(arg(0) - 1.5, arg(2), 0), if(arg(0) - 2.5, arg(3), 0));
gi(n) = pc_in(1, n, arg(0), if(arg(0) - 1.5, arg(2), 0), if(arg(0) - 2.5, arg(3), 0));
bi(n) = pc_in(2, n, arg(0), if(arg(0) - 1.5, arg(2), 0), if(arg(0) - 2.5, arg(3), 0));
li(n) = pc_in(3, n, arg(0), if(arg(0) - 1.5, arg(2), 0), if(arg(0) - 2.5, arg(3), 0));
re(n) = in(pc_ch(4, n, 0, 0));
ge(n) = in(pc_ch(5, n, 0, 0));
be(n) = in(pc_ch(6, n, 0, 0));
le(n) = in(pc_ch(7, n, 0, 0));
pa(n) = in(pc_ch(8, n, 0, 0));
)";

struct Source {
    std::vector<Pixel> pixels;  // scaled by the input's coefficients, top row first
    std::array<double, 3> expos{1, 1, 1};
    double aspect = 1;
};

class PcombChannels final : public calc::ChannelSource {
public:
    PcombChannels(const std::vector<Source>& s, int xmax, int ymax, bool xyz)
        : s_(s), xmax_(xmax), ymax_(ymax), xyz_(xyz) {}
    int xscan = 0, yscan = 0;  // input position, y from the bottom

    double channel(int ch) override {
        if (ch < 1) return 0.0;
        long k = ch - 1;
        const int c = static_cast<int>(k % kComponents);
        k /= kComponents;
        const long nf = static_cast<long>(s_.size()) + 1;
        const int n = static_cast<int>(k % nf);
        k /= nf;
        if (n == 0) return static_cast<double>(s_.size());
        const Source& src = s_[n - 1];
        if (c >= 4) {
            if (c < 7) return src.expos[c - 4];
            if (c == 7)
                return brightness({float(src.expos[0]), float(src.expos[1]), float(src.expos[2])},
                                  xyz_);
            return src.aspect;
        }
        int dx = 0, dy = 0;
        if (k > 0) {
            --k;
            dx = static_cast<int>(k % (2 * xmax_ + 1)) - xmax_;
            dy = static_cast<int>(k / (2 * xmax_ + 1)) - kYDown;
        }
        const int xs = std::clamp(xscan + dx, 0, xmax_ - 1);
        const int ys = std::clamp(yscan + dy, 0, ymax_ - 1);
        const Pixel& p = src.pixels[static_cast<size_t>(ymax_ - 1 - ys) * xmax_ + xs];
        return c == 3 ? brightness(p, xyz_) : p[c];
    }
    double channelCount() override { return static_cast<double>(s_.size()); }

private:
    const std::vector<Source>& s_;
    int xmax_, ymax_;
    bool xyz_;
};

std::string stamp(const char* key, const std::tm& t) {
    return fmt::format("{} {:04d}:{:02d}:{:02d} {:02d}:{:02d}:{:02d}", key, t.tm_year + 1900,
                       t.tm_mon + 1, t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec);
}

double parseFactor(const std::string& w, const std::string& option) {
    const auto v = parseReal(w);
    if (!v) throw InputError("bad value '" + w + "' for " + option + " (" + kUsage + ")");
    return *v;
}

}  // namespace

OptionTable pcombTable(PcombOptions& o) {
    OptionTable t;
    t.unknownEnds = true;  // -o -s -c belong to the inputs
    auto line = [](const char* s) { return [s] { return std::string(s); }; };
    t.add(customOption("-h", [&o](OptionReader&) { o.echoHeader = !o.echoHeader; }),
          line("-h  off\t\t\t\t# shorter header: no input headers\n"));
    t.add(customOption("-w", [&o](OptionReader&) { o.warnings = !o.warnings; }),
          line("-w  off\t\t\t\t# no warnings\n"));
    for (const char* name : {"-x", "-y", "-e", "-f"}) {
        const char kind = name[1];
        t.add(customOption(name,
                           [&o, kind](OptionReader& r) { o.sources.emplace_back(kind, r.word()); }),
              line(kind == 'x'   ? "-x  xmax\t\t\t# output x resolution (an expression)\n"
                   : kind == 'y' ? "-y  ymax\t\t\t# output y resolution (an expression)\n"
                   : kind == 'e' ? "-e  none\t\t\t# .cal definitions (ro go bo, or lo)\n"
                                 : "-f  none\t\t\t# .cal file\n"));
    }
    return t;
}

PcombOptions parsePcombArgs(const std::vector<std::string>& argsIn) {
    PcombOptions o;
    std::vector<std::string> args = argsIn;
    const OptionTable table = pcombTable(o);
    size_t a = table.parse(args, 0).next;
    PcombInput cur;
    for (; a < args.size(); ++a) {
        const std::string& w = args[a];
        auto next = [&]() -> const std::string& {
            if (++a >= args.size())
                throw InputError("missing value for " + w + " (" + kUsage + ")");
            return args[a];
        };
        if (w == "-o") {
            cur.original = true;
        } else if (w == "-s") {
            const double f = parseFactor(next(), "-s");
            for (double& c : cur.coef) c *= f;
        } else if (w == "-c") {
            for (double& c : cur.coef) c *= parseFactor(next(), "-c");
        } else if (w.size() > 1 && w[0] == '-') {
            throw InputError("unknown option '" + w + "' (" + kUsage + ")");
        } else if (!w.empty() && w[0] == '!') {
            throw InputError("'!command' inputs are not supported: " + w);
        } else {
            cur.name = w;
            o.inputs.push_back(cur);
            cur = PcombInput{};
        }
    }
    return o;
}

Picture runPcomb(std::vector<PcombPicture>& inputs, const PcombOptions& o,
                 const std::string& commandLine, std::time_t now,
                 const std::vector<std::string>& searchPath) {
    Picture out;
    auto& lines = out.header.lines;
    std::tm local{}, gmt{};
    localtime_r(&now, &local);
    gmtime_r(&now, &gmt);
    lines.push_back(stamp("CAPDATE=", local));
    lines.push_back(stamp("GMT=", gmt));

    int xmax = 0, ymax = 0;
    std::vector<Source> sources(inputs.size());
    std::optional<View> view;
    for (size_t i = 0; i < inputs.size(); ++i) {
        PcombPicture& in = inputs[i];
        Picture& pic = in.picture;
        if (o.echoHeader) {
            lines.push_back(in.name + ":");
            for (const std::string& l : pic.header.lines)
                if (l.rfind("#?", 0) != 0) lines.push_back("\t" + l);
        }
        if (i == 0) {
            xmax = pic.width;
            ymax = pic.height;
            out.format = pic.format;
        } else if (pic.width != xmax || pic.height != ymax) {
            throw InputError(SourceLoc{in.name, 0}, "resolution mismatch");
        }
        if (!view) {
            try {
                view = viewFromHeader(pic.header);
            } catch (const InputError&) {  // an unusable view is no view, as RADIANCE's
            }
        }
        Source& s = sources[i];
        const double e = pic.exposure();
        const auto cc = pic.colorCorrection();
        std::array<double, 3> coef = in.input.coef;
        for (int c = 0; c < 3; ++c) s.expos[c] = e * cc[c];
        if (in.input.original) {
            for (int c = 0; c < 3; ++c) coef[c] /= s.expos[c];
            s.expos = {1, 1, 1};
        }
        s.aspect = pic.pixelAspect();
        s.pixels = std::move(pic.pixels);
        for (Pixel& p : s.pixels)
            for (int c = 0; c < 3; ++c) p[c] *= static_cast<float>(coef[c]);
    }
    const bool xyz = out.format == PictureFormat::kXyze;

    calc::Builder b(searchPath);
    b.enableChannels();
    b.loadString(fmt::format("PI : 3.14159265358979323846; nfiles : {}; xmax : {}; ymax : {};"
                             " WE : {}; xres : xmax; yres : ymax;",
                             inputs.size(), xmax, ymax, xyz ? 1.0 : kWhiteEfficacy),
                 "pcomb");
    b.loadString(kPrelude, "pcomb");
    for (const auto& [kind, text] : o.sources) {
        if (kind == 'e')
            b.loadString(text);
        else if (kind == 'f')
            b.loadFile(text);
        else
            b.loadString(std::string(kind == 'x' ? "xres" : "yres") + " : " + text + ";",
                         std::string("-") + kind);
    }
    b.addExternal("x");
    b.addExternal("y");
    const auto prog = b.build();
    calc::Evaluator ev(prog);
    PcombChannels chans(sources, xmax, ymax, xyz);
    ev.setChannels(&chans);
    const calc::RayContext ray{};
    ev.setRay(ray);
    const double xr = ev.eval(*prog->variable("xres")) + .5;
    const double yr = ev.eval(*prog->variable("yres")) + .5;
    if (!(xr >= 1 && yr >= 1 && xr < 1e8 && yr < 1e8))
        throw InputError("illegal output resolution");
    const int xres = static_cast<int>(xr), yres = static_cast<int>(yr);
    if (xmax == 0 && (xres <= 0 || yres <= 0)) throw InputError("illegal output resolution");

    lines.push_back(commandLine);
    if (view) lines.push_back(viewHeaderLine(*view));

    const auto xv = prog->variable("x"), yv = prog->variable("y");
    std::array<std::optional<calc::Entry>, 3> colour = {prog->variable("ro"), prog->variable("go"),
                                                        prog->variable("bo")};
    const auto grey = prog->variable("lo");
    out.width = xres;
    out.height = yres;
    out.pixels.assign(static_cast<size_t>(xres) * yres, Pixel{});
    for (int ypos = yres - 1; ypos >= 0; --ypos) {
        chans.yscan = static_cast<int>((ypos + .5) * ymax / yres);
        for (int xpos = 0; xpos < xres; ++xpos) {
            chans.xscan = static_cast<int>((xpos + .5) * xmax / xres);
            ev.setRay(ray);
            ev.set(*xv, xpos);
            ev.set(*yv, ypos);
            Pixel& p = out.at(xpos, yres - 1 - ypos);
            if (grey) {
                const double d = std::max(ev.eval(*grey), 0.0);
                p = {float(d), float(d), float(d)};
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                double d = 0;
                if (colour[c]) {
                    d = ev.eval(*colour[c]);
                } else if (xmax > 0) {
                    const size_t at =
                        static_cast<size_t>(ymax - 1 - chans.yscan) * xmax + chans.xscan;
                    for (const Source& s : sources) d += s.pixels[at][c];
                }
                p[c] = static_cast<float>(std::max(d, 0.0));
            }
        }
    }
    return out;
}

}  // namespace rp
