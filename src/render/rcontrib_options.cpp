// rcontrib command-line parsing and -defaults (RADIANCE rcmain.c main/printdefaults).
#include "render/rcontrib_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render/rtrace_options.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/options.h"

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

}  // namespace

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

// rcontrib's own options, ahead of the shared ones: -e, -f, -o, -t, -x, -y mean other
// things to rtrace. In the order of its -defaults lines (rcmain.c printdefaults) where
// they have one.
void addOwnOptions(OptionTable& t, RcontribOptions& o, pmap::ModifierOptions& m) {
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
    m.addTo(t, true);
    t.add(valueOption("-t", o.reportSeconds));
    t.add(flagOption("-r", o.recover, 3));
}

OptionTable rcontribTable(RcontribOptions& o, pmap::ModifierOptions& m) {
    OptionTable t;
    t.expandArgs = true;
    t.helpIsDefaults = true;
    t.messages.unknown = [](const std::string& opt) {
        return "command line error at '" + opt + "'";
    };
    addOwnOptions(t, o, m);
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
    pmap::ModifierOptions m(o.modifiers, o.definitions, evalCount);
    const OptionParse p = rcontribTable(o, m).parse(args, 1);
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
    pmap::ModifierOptions m(copy.modifiers, copy.definitions, nullptr);
    return rcontribTable(copy, m).formatDefaults();
}

}  // namespace rp::render
