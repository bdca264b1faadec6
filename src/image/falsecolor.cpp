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

namespace rp {

namespace {

double clip01(double x) { return x > 1 ? 1 : (x > 0 ? x : 0); }

// RADIANCE compat: falsecolor.pl's pc0.cal compares with an epsilon (neq) and tests
// signs the .cal way (if(c, a, b) takes a when c > 0).
constexpr double kEps = 1e-7;
bool differ(double a, double b) { return a - b - kEps > 0 || b - a - kEps > 0; }

double parseNumber(const std::string& opt, const std::string& v) {
    char* end = nullptr;
    double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !std::isfinite(d)) throw InputError(opt + ": bad number '" + v + "'");
    return d;
}

int parseInt(const std::string& opt, const std::string& v) {
    double d = parseNumber(opt, v);
    if (d != std::floor(d) || std::abs(d) > 1e6)
        throw InputError(opt + ": expected an integer, got '" + v + "'");
    return static_cast<int>(d);
}

}  // namespace

// ---- options -------------------------------------------------------------------------

FalseColorOptions parseFalseColorArgs(const std::vector<std::string>& args) {
    FalseColorOptions o;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw InputError("option " + a + " needs a value");
            return args[++i];
        };
        if (a == "-lw")
            o.legendWidth = parseInt(a, value());
        else if (a == "-lh")
            o.legendHeight = parseInt(a, value());
        else if (a == "-m")
            o.multiplier = parseNumber(a, value());
        else if (a == "-spec")
            throw InputError("deprecated option '-spec': use '-pal spec'");
        else if (a == "-s") {
            const std::string& v = value();
            // RADIANCE compat: falsecolor.pl takes any value starting with a or A as auto.
            if (!v.empty() && (v[0] == 'a' || v[0] == 'A'))
                o.autoScale = true;
            else
                o.scale = parseNumber(a, v);
        } else if (a == "-d")
            o.decimals = parseInt(a, value());
        else if (a == "-l")
            o.label = value();
        else if (a == "-log")
            o.decades = parseNumber(a, value());
        else if (a == "-r")
            o.channelExpr[0] = value();
        else if (a == "-g")
            o.channelExpr[1] = value();
        else if (a == "-b")
            o.channelExpr[2] = value();
        else if (a == "-pal") {
            const std::string& v = value();
            auto p = paletteByName(v);
            if (!p) throw InputError("invalid palette '" + v + "'");
            o.palette = *p;
        } else if (a == "-i")
            o.input = value();
        else if (a == "-p")
            o.background = value();
        else if (a == "-ip" || a == "-pi")
            o.input = o.background = value();
        else if (a == "-n")
            o.ndivs = parseInt(a, value());
        else if (a == "-cl")
            o.contour = ContourMode::kLines;
        else if (a == "-cb")
            o.contour = ContourMode::kBands;
        else if (a == "-cp")
            o.contour = ContourMode::kPosterize;
        else if (a == "-palettes")
            o.showPalettes = true;
        else if (a == "-e")
            o.extrema = true;
        else
            throw InputError("bad option '" + a + "'");
    }
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
