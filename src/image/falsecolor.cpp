#include "image/falsecolor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>

#include "calc/program.h"
#include "image/legend_font.h"
#include "util/error.h"
#include "util/options.h"

namespace rp {

namespace {

double clip01(double x) { return x > 1 ? 1 : (x > 0 ? x : 0); }

// RADIANCE compat: falsecolor.pl's pc0.cal compares with an epsilon (neq) and tests
// signs the .cal way (if(c, a, b) takes a when c > 0).
constexpr double kEps = 1e-7;
bool differ(double a, double b) { return a - b - kEps > 0 || b - a - kEps > 0; }

// -n, -d, -lw, -lh: a whole number, which falsecolor.pl takes in any real's spelling.
int wholeNumber(OptionReader& r) {
    const double d = r.real();
    if (d != std::floor(d) || std::abs(d) > 1e6)
        throw InputError(r.option() + ": expected an integer, got '" + r.args()[r.next() - 1] +
                         "'");
    return static_cast<int>(d);
}

}  // namespace

// ---- options -------------------------------------------------------------------------

OptionTable falseColorTable(FalseColorOptions& o) {
    OptionTable t;
    t.defaultsStops = false;  // -defaults is the tool's, at argv[1] (tools/info_options.h)
    t.messages.missing = [](const std::string& opt) { return "option " + opt + " needs a value"; };
    t.messages.bad = [](const std::string& opt, const std::string& v, ValueKind) {
        return opt + ": bad number '" + v + "'";
    };
    t.messages.unknown = [](const std::string& opt) { return "bad option '" + opt + "'"; };
    auto whole = [](const char* name, int& v) {
        return customOption(name, [&v](OptionReader& r) { v = wholeNumber(r); });
    };
    auto real = [](const char* name, double& v) {
        return customOption(name, [&v](OptionReader& r) { v = r.real(); });
    };
    auto flag = [](const char* name, std::function<void()> set) {
        return customOption(name, [set = std::move(set)](OptionReader&) { set(); });
    };
    t.add(whole("-lw", o.legendWidth),
          [&o] { return formatLine("-lw %d\t\t\t\t# legend width\n", o.legendWidth); });
    t.add(whole("-lh", o.legendHeight),
          [&o] { return formatLine("-lh %d\t\t\t\t# legend height\n", o.legendHeight); });
    t.add(real("-m", o.multiplier), [&o] {
        return formatLine("-m  %g\t\t\t\t# multiplier (luminous efficacy)\n", o.multiplier);
    });
    t.add(flag("-spec", [] { throw InputError("deprecated option '-spec': use '-pal spec'"); }));
    t.add(customOption("-s",
                       [&o](OptionReader& r) {
                           const std::string& v = r.word();
                           // RADIANCE compat: falsecolor.pl takes any value starting with a
                           // or A as auto.
                           if (!v.empty() && (v[0] == 'a' || v[0] == 'A')) {
                               o.autoScale = true;
                           } else {
                               const std::optional<double> d = parseReal(v);
                               if (!d) r.bad(v, ValueKind::kReal);
                               o.scale = *d;
                           }
                       }),
          [&o] {
              return formatLine("-s  %g\t\t\t# top of the scale (-s a: from the picture)\n",
                                o.scale);
          });
    t.add(whole("-d", o.decimals),
          [&o] { return formatLine("-d  %d\t\t\t\t# decimals in legend numbers\n", o.decimals); });
    t.add(valueOption("-l", o.label),
          [&o] { return formatLine("-l  %s\t\t\t# legend label\n", o.label.c_str()); });
    t.add(real("-log", o.decades),
          [&o] { return formatLine("-log %g\t\t\t\t# decades (0: linear scale)\n", o.decades); });
    t.add(valueOption("-r", o.channelExpr[0]));
    t.add(valueOption("-g", o.channelExpr[1]));
    t.add(valueOption("-b", o.channelExpr[2]));
    t.add(customOption("-pal",
                       [&o](OptionReader& r) {
                           const std::string& v = r.word();
                           auto p = paletteByName(v);
                           if (!p) throw InputError("invalid palette '" + v + "'");
                           o.palette = *p;
                       }),
          [&o] {
              return formatLine("-pal %s\t\t\t# palette\n",
                                paletteNames()[size_t(o.palette)].c_str());
          });
    t.add(valueOption("-i", o.input), [&o] {
        return formatLine("-i  %s\t\t\t\t# input picture (standard input)\n", o.input.c_str());
    });
    t.add(valueOption("-p", o.background));
    t.add(customOption([](const std::string& w) { return w == "-ip" || w == "-pi"; }, "-ip",
                       [&o](OptionReader& r) { o.input = o.background = r.word(); }));
    t.add(whole("-n", o.ndivs),
          [&o] { return formatLine("-n  %d\t\t\t\t# legend divisions\n", o.ndivs); });
    t.add(flag("-cl", [&o] { o.contour = ContourMode::kLines; }));
    t.add(flag("-cb", [&o] { o.contour = ContourMode::kBands; }));
    t.add(flag("-cp", [&o] { o.contour = ContourMode::kPosterize; }));
    t.add(flag("-palettes", [&o] { o.showPalettes = true; }));
    t.add(flag("-e", [&o] { o.extrema = true; }));
    t.setDefaultsOrder({"-i", "-s", "-n", "-l", "-m", "-d", "-log", "-pal", "-lw", "-lh"});
    return t;
}

FalseColorOptions parseFalseColorArgs(const std::vector<std::string>& args) {
    FalseColorOptions o;
    std::vector<std::string> words = args;
    falseColorTable(o).parseAll(words, 0);
    if (o.ndivs < 1) throw InputError("-n: need at least one division");
    if (o.decimals < 0) throw InputError("-d: decimal places must be 0 or more");
    if (!o.autoScale && !(o.scale > 0)) throw InputError("-s: scale must be positive");
    if (o.decades < 0) throw InputError("-log: decades must be 0 or more");
    return o;
}

// ---- value to colour -----------------------------------------------------------------

// -r/-g/-b: each expression becomes a .cal function of v under a name no user text can
// reach by accident, compiled once; palette names are not defined in it (RADIANCE's
// def_red etc. are .cal tables there; here the palettes are C++).
struct FalseColorMap::Custom {
    std::shared_ptr<const calc::Program> program;
    std::unique_ptr<calc::Evaluator> evaluator;
    std::array<std::optional<calc::Function>, 3> functions;
};

FalseColorMap::FalseColorMap(const FalseColorOptions& opt) : opt_(opt) {
    static const char* kOpt[3] = {"-r", "-g", "-b"};
    bool any = false;
    calc::Builder b;
    b.loadString(
        "PI : 3.14159265358979323846; gamma : 2.2;"
        "clip(x) : if(x-1,1,if(x,x,0));",
        "falsecolor prelude", 0);
    for (int c = 0; c < 3; ++c) {
        if (opt.channelExpr[c].empty()) continue;
        any = true;
        b.loadString("C" + std::to_string(c) + "`FC(v) = " + opt.channelExpr[c] + ";",
                     std::string(kOpt[c]) + " '" + opt.channelExpr[c] + "'", 0);
    }
    if (!any) return;
    custom_ = std::make_unique<Custom>();
    custom_->program = b.build();
    for (const std::string& p : custom_->program->problems()) throw InputError(p);
    custom_->evaluator = std::make_unique<calc::Evaluator>(custom_->program);
    static const calc::RayContext kNoRay;
    custom_->evaluator->setRay(kNoRay);
    for (int c = 0; c < 3; ++c)
        if (!opt.channelExpr[c].empty())
            custom_->functions[c] = custom_->program->function("C" + std::to_string(c) + "`FC");
}

FalseColorMap::~FalseColorMap() = default;

double FalseColorMap::position(double x) const {
    if (opt_.decades <= 0) return x;
    return x - std::pow(10.0, -opt_.decades) > 0 ? std::log10(x) / opt_.decades + 1 : 0;
}

std::array<double, 3> FalseColorMap::paletteAt(double w) {
    auto c = paletteColor(opt_.palette, w);
    if (custom_) {
        for (int i = 0; i < 3; ++i)
            if (custom_->functions[i])
                c[i] = clip01(custom_->evaluator->call(*custom_->functions[i],
                                                       std::span<const double>(&w, 1)));
    }
    return c;
}

std::array<double, 3> FalseColorMap::color(double v) {
    double n = opt_.ndivs;
    switch (opt_.contour) {
        case ContourMode::kNone:
            return paletteAt(v);
        case ContourMode::kLines:
        case ContourMode::kBands:
            // The bottom division has no contour, so the palette starts at the first one.
            return paletteAt((v - 1 / n) * n / (n - 1));
        case ContourMode::kPosterize: {
            // falsecolor.pl's seg2(): the middle of v's division, stretched the same way.
            double seg = (std::floor(v * n) + 0.5) / n;
            return paletteAt((seg - 1 / n) * n / (n - 1));
        }
    }
    return {0, 0, 0};
}

bool FalseColorMap::inBand(double v) const {
    double n = opt_.ndivs;
    if (!(v >= 1 / n / 2 && v < 1 + 1 / n / 2)) return false;
    double f = n * v - std::floor(n * v);
    // iscontb = -btwn(.1, f, .9): positive below .1 and above .9 (zero at exactly .9).
    return f < 0.1 || f - 0.9 > 0;
}

bool FalseColorMap::onLine(double v, double left, double right, double above, double below) const {
    double n = opt_.ndivs;
    if (!(v >= 1 / n / 2 && v < 1 + 1 / n / 2)) return false;
    return differ(std::floor(n * left), std::floor(n * right)) ||
           differ(std::floor(n * above), std::floor(n * below));
}

// ---- legend numbers ------------------------------------------------------------------

std::string legendNumber(double value, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.15g", value);  // how Perl prints a number
    std::string s = buf;
    // RADIANCE compat: s/(\.[0-9]{d})[0-9]*/$1/ cuts digits only where at least d follow
    // the point, and keeps a bare "." for -d 0.
    size_t dot = s.find('.');
    if (dot == std::string::npos) return s;
    size_t end = dot + 1;
    while (end < s.size() && std::isdigit(static_cast<unsigned char>(s[end]))) ++end;
    if (end - dot - 1 < static_cast<size_t>(decimals)) return s;
    return s.substr(0, dot + 1 + decimals) + s.substr(end);
}

std::vector<std::string> legendValues(const FalseColorOptions& opt) {
    bool hasZero = opt.contour == ContourMode::kNone;
    int count = opt.ndivs + (hasZero ? 1 : 0);
    std::vector<std::string> out;
    for (int i = 0; i < count; ++i) {
        double imap = static_cast<double>(opt.ndivs - i) / opt.ndivs;
        double value = opt.scale;
        if (opt.decades > 0)
            value *= std::pow(10.0, (imap - 1) * opt.decades);
        else
            value *= imap;
        out.push_back(legendNumber(value, opt.decimals));
    }
    return out;
}

}  // namespace rp
