// rcontrib command-line parsing and -defaults (RADIANCE rcmain.c main/printdefaults).
#include "render/rcontrib_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unordered_set>

#include "calc/search_path.h"
#include "render/rtrace_options.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/options.h"
#include "util/paths.h"

namespace rp::render {

namespace {

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
    const std::optional<double> number = parseReal(text);
    double v = number ? *number : 0;
    if (!number) {
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

namespace {

// Where each -m/-M stands: the most recent -o, -p, -b and -bn to its left.
struct ModifierContext {
    std::unordered_set<std::string> seen;
    std::string out, params, binExpr;
    int bins = 0;
};

// rcontrib's own options, ahead of the shared ones: -e, -f, -o, -t, -x, -y mean other
// things to rtrace. In the order of its -defaults lines (rcmain.c printdefaults) where
// they have one.
void addOwnOptions(OptionTable& t, RcontribOptions& o, ModifierContext& m, BinCountEval eval) {
    t.add(valueOption("-c", o.accumulate), [&o] {
        return formatLine("-c %-5d\t\t\t# accumulated rays per record\n", o.accumulate);
    });
    t.add(flagOption("-V", o.contributions, 3), [&o] {
        return formatLine("-V%c\t\t\t\t# output %s\n", o.contributions ? '+' : '-',
                          o.contributions ? "contributions" : "coefficients");
    });
    t.add(flagOption("-I", o.immediateIrradiance, 3), [&o] {
        return std::string(o.immediateIrradiance ? "-I+\t\t\t\t# immediate irradiance on\n" : "");
    });
    addRayOptions(t, o.render.threads, {valueOption("-x", o.xres), valueOption("-y", o.yres)},
                  o.xres, o.yres, o.limitDistance, o.header, o.inputFormat, o.outputFormat, 3);
    t.add(warningsOption(o.render.warnings));
    t.add(customOption("-e", [&o](OptionReader& r) {
        o.definitions.push_back({false, r.word()});
    }));
    t.add(customOption("-f", [&o](OptionReader& r) { o.definitions.push_back({true, r.word()}); }));
    t.add(flagOption("-fo", o.force));
    t.add(customOption(prefix("-f"), "-f[io]",
                       [&o](OptionReader& r) { parseFormat(r.option(), o); }));
    t.add(valueOption("-o", m.out));
    t.add(valueOption("-p", m.params));
    t.add(valueOption("-b", m.binExpr));
    t.add(customOption("-bn",
                       [&o, &m, eval](OptionReader& r) { m.bins = binCount(r.word(), o, eval); }));
    t.add(customOption("-m", [&o, &m](OptionReader& r) {
        addModifier(o, m.seen, r.word(), m.out, m.params, m.binExpr, m.bins);
    }));
    t.add(customOption("-M", [&o, &m](OptionReader& r) {
        addModifierFile(o, m.seen, r.word(), m.out, m.params, m.binExpr, m.bins);
    }));
    t.add(valueOption("-t", o.reportSeconds));
    t.add(flagOption("-r", o.recover, 3));
}

OptionTable rcontribTable(RcontribOptions& o, ModifierContext& m, BinCountEval eval) {
    OptionTable t;
    t.expandArgs = true;
    t.helpIsDefaults = true;
    t.messages.unknown = [](const std::string& opt) {
        return "command line error at '" + opt + "'";
    };
    addOwnOptions(t, o, m, eval);
    addRenderOptions(t, o.render);
    return t;
}

// RADIANCE compat (rcmain.c override_options): no shadow threshold, no irradiance cache
// and no ambient super-samples; -c 0 has no flushing.
void overrideOptions(RcontribOptions& o) {
    o.render.direct.threshold = 0;
    o.render.ambient.accuracy = 0;
    o.render.ambient.supersamples = 0;
    o.render.contributions = true;
    if (o.accumulate <= 0) o.xres = o.yres = 0;
}

}  // namespace

RcontribOptions parseRcontribArgs(std::vector<std::string> args, BinCountEval evalCount) {
    RcontribOptions o = rcontribDefaults();
    o.commandWords = args;
    if (!o.commandWords.empty()) o.commandWords.pop_back();
    ModifierContext m;
    const OptionParse p = rcontribTable(o, m, evalCount).parse(args, 1);
    o.optionCount = p.next;
    o.printVersion = p.stop == OptionStop::kVersion;
    o.printDefaults = p.stop == OptionStop::kDefaults;
    overrideOptions(o);
    if (o.printDefaults || o.printVersion) {
        o.args = std::move(args);
        return o;
    }
    if (o.modifiers.empty()) throw InputError("missing required modifier argument");
    o.sceneFile = sceneArgument(args, p.next);
    o.args = std::move(args);
    return o;
}

std::string formatRcontribDefaults(const RcontribOptions& opt) {
    RcontribOptions copy = opt;
    ModifierContext m;
    return rcontribTable(copy, m, nullptr).formatDefaults();
}

}  // namespace rp::render
