// rcontrib command-line parsing and -defaults (RADIANCE rcmain.c main/printdefaults).
#include "render/rcontrib_options.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unordered_set>

#include "calc/search_path.h"
#include "render/command_args.h"
#include "render/rtrace_options.h"
#include "util/error.h"
#include "util/paths.h"

namespace rp::render {

namespace {

const std::string& value(const std::vector<std::string>& args, size_t& i) {
    if (i + 1 >= args.size()) throw InputError("missing value for option '" + args[i] + "'");
    return args[++i];
}

int intValue(const std::vector<std::string>& args, size_t& i) {
    const std::string& opt = args[i];
    const std::string& v = value(args, i);
    char* end = nullptr;
    errno = 0;
    long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno != 0 || n < -2147483647L || n > 2147483647L)
        throw InputError("bad value '" + v + "' for option '" + opt + "'");
    return int(n);
}

// -f[a|f|d][a|f|d|c] (rcmain.c setformat): one letter sets both formats.
void parseFormat(const std::string& opt, RcontribOptions& o) {
    auto isIn = [](char c) { return c == 'a' || c == 'f' || c == 'd'; };
    if (opt.size() < 3 || opt.size() > 4 || !isIn(opt[2]) ||
        (opt.size() == 4 && !isIn(opt[3]) && opt[3] != 'c'))
        throw InputError("Illegal i/o format: " + opt);
    o.inputFormat = opt[2];
    o.outputFormat = opt.size() == 4 ? opt[3] : opt[2];
}

// A number, or (RADIANCE rcmain.c: eval) an expression of what -e/-f defined so far.
int binCount(const std::string& text, const RcontribOptions& o, BinCountEval eval) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') {
        if (!eval) throw InputError("bad bin count '" + text + "'");
        v = eval(o.definitions, text);
    }
    if (!std::isfinite(v) || std::fabs(v) > 1e9) throw InputError("bad bin count '" + text + "'");
    return int(v + 0.5);
}

void addModifier(RcontribOptions& o, std::unordered_set<std::string>& seen, const std::string& name,
                 const std::string& out, const std::string& params, const std::string& binExpr,
                 int bins) {
    // RADIANCE compat (rcontrib.c addmodifier): messages and the constant-bin rule.
    if (!seen.insert(name).second) throw InputError("duplicate modifier '" + name + "'");
    if (name == "void") throw InputError("cannot track 'void' modifier");
    ContribModifier m;
    m.name = name;
    m.outSpec = out;
    m.params = params;
    m.binExpr = binExpr.empty() ? "0" : binExpr;
    if (isConstantBin(m.binExpr)) {
        if (int(std::strtod(m.binExpr.c_str(), nullptr) + 1.5) != 1)
            throw InputError("illegal non-zero constant for bin (" + m.binExpr + ")");
        m.bins = 1;
    } else if (bins <= 0) {
        throw InputError("unspecified or illegal bin count for modifier '" + name + "'");
    } else {
        m.bins = bins;
    }
    o.modifiers.push_back(std::move(m));
}

void addModifierFile(RcontribOptions& o, std::unordered_set<std::string>& seen,
                     const std::string& file, const std::string& out, const std::string& params,
                     const std::string& binExpr, int bins) {
    const auto dirs = calc::defaultSearchPath(projectLibDir());
    auto path = calc::findFile(file, dirs);
    if (!path) throw InputError("cannot find modifier file '" + file + "'");
    std::ifstream in(*path);
    if (!in) throw InputError("cannot load modifier file '" + *path + "'");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // RADIANCE fgetword: white-space separated words, quotes allowed.
    for (const std::string& w : splitWords(text))
        addModifier(o, seen, w, out, params, binExpr, bins);
}

}  // namespace

bool isConstantBin(const std::string& e) {
    char* end = nullptr;
    std::strtod(e.c_str(), &end);
    while (*end == ' ' || *end == '\t') ++end;
    return !e.empty() && *end == '\0';
}

RcontribOptions rcontribDefaults() {
    RcontribOptions o;
    RenderOptions& r = o.render;
    r.uncorrelated = true;
    r.contributions = true;
    r.direct.threshold = 0;
    r.direct.certainty = 0.75;
    r.direct.jitter = 0.9;
    r.direct.relays = 3;
    r.specular.threshold = 0.02;
    r.ambient.bounces = 1;
    r.ambient.accuracy = 0;
    r.ambient.divisions = 350;
    r.ambient.supersamples = 0;
    r.limits.maxDepth = -10;
    r.limits.minWeight = 2e-3;
    return o;
}

RcontribOptions parseRcontribArgs(std::vector<std::string> args, BinCountEval evalCount) {
    RcontribOptions o = rcontribDefaults();
    o.commandWords = args;
    if (!o.commandWords.empty()) o.commandWords.pop_back();
    std::unordered_set<std::string> seen;
    std::string out, params, binExpr;
    int bins = 0;
    size_t i = 1;
    for (; i < args.size(); ++i) {
        expandArgAt(args, i);
        if (i >= args.size() || args[i].size() < 2 || args[i][0] != '-') break;
        const std::string opt = args[i];
        if (opt == "-defaults" || opt == "-help" || opt == "-version") {
            (opt == "-version" ? o.printVersion : o.printDefaults) = true;
            break;
        }
        // rcontrib's own first: -e, -f, -o, -t, -x, -y mean other things to rtrace.
        if (opt == "-e")
            o.definitions.push_back({false, value(args, i)});
        else if (opt == "-f")
            o.definitions.push_back({true, value(args, i)});
        else if (opt.rfind("-fo", 0) == 0)
            o.force = boolSuffix(opt, 3, o.force);
        else if (opt.rfind("-f", 0) == 0)
            parseFormat(opt, o);
        else if (opt == "-o")
            out = value(args, i);
        else if (opt == "-p")
            params = value(args, i);
        else if (opt == "-b")
            binExpr = value(args, i);
        else if (opt == "-bn")
            bins = binCount(value(args, i), o, evalCount);
        else if (opt == "-m")
            addModifier(o, seen, value(args, i), out, params, binExpr, bins);
        else if (opt == "-M")
            addModifierFile(o, seen, value(args, i), out, params, binExpr, bins);
        else if (opt == "-c") {
            o.accumulate = intValue(args, i);
        } else if (opt == "-x")
            o.xres = intValue(args, i);
        else if (opt == "-y")
            o.yres = intValue(args, i);
        else if (opt == "-t")
            o.reportSeconds = intValue(args, i);
        else if (opt.rfind("-V", 0) == 0 && opt.size() <= 3)
            o.contributions = boolSuffix(opt, 2, o.contributions);
        else if (opt.rfind("-r", 0) == 0 && opt.size() <= 3)
            o.recover = boolSuffix(opt, 2, o.recover);
        else if (opt.rfind("-h", 0) == 0 && opt.size() <= 3)
            o.header = boolSuffix(opt, 2, o.header);
        else if (opt.rfind("-I", 0) == 0 && opt.size() <= 3)
            o.immediateIrradiance = boolSuffix(opt, 2, o.immediateIrradiance);
        else if (opt.rfind("-ld", 0) == 0 && opt.size() <= 4)
            o.limitDistance = boolSuffix(opt, 3, o.limitDistance);
        else if (parseRenderOption(args, i, o.render))
            --i;  // it moved past the option
        else
            throw InputError("command line error at '" + opt + "'");
    }
    o.optionCount = std::min(i, args.size());
    // RADIANCE compat (rcmain.c override_options): no shadow threshold, no irradiance
    // cache and no ambient super-samples; -c 0 has no flushing.
    o.render.direct.threshold = 0;
    o.render.ambient.accuracy = 0;
    o.render.ambient.supersamples = 0;
    o.render.contributions = true;
    if (o.accumulate <= 0) o.xres = o.yres = 0;
    if (o.printDefaults || o.printVersion) {
        o.args = std::move(args);
        return o;
    }
    if (o.modifiers.empty()) throw InputError("missing required modifier argument");
    o.sceneFile = sceneArgument(args, i);
    o.args = std::move(args);
    return o;
}

std::string formatRcontribDefaults(const RcontribOptions& o) {
    std::string out;
    char line[256];
    auto put = [&](const char* fmt, auto... a) {
        std::snprintf(line, sizeof line, fmt, a...);
        out += line;
    };
    // RADIANCE compat: rcmain.c printdefaults, lines and formats.
    put("-c %-5d\t\t\t# accumulated rays per record\n", o.accumulate);
    put("-V%c\t\t\t\t# output %s\n", o.contributions ? '+' : '-',
        o.contributions ? "contributions" : "coefficients");
    if (o.immediateIrradiance) out += "-I+\t\t\t\t# immediate irradiance on\n";
    out += formatRayDefaults(o.render.threads, o.xres, o.yres, o.limitDistance, o.header,
                             o.inputFormat, o.outputFormat);
    out += o.render.warnings ? "-w+\t\t\t\t# warning messages on\n"
                             : "-w-\t\t\t\t# warning messages off\n";
    out += formatRenderDefaults(o.render);
    return out;
}

}  // namespace rp::render
