// rtrace command-line parsing and -defaults (RADIANCE rtmain.c main/printdefaults).
#include "render/rtrace_options.h"

#include "calc/search_path.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/options.h"
#include "util/paths.h"

namespace rp::render {

namespace {

// -f[a|f|d][a|f|d|c]: one letter sets both formats, as RADIANCE.
void parseFormat(const std::string& opt, RtraceOptions& o) {
    auto isIn = [](char c) { return c == 'a' || c == 'f' || c == 'd'; };
    if (opt.size() < 3 || opt.size() > 4 || !isIn(opt[2]))
        throw InputError("unknown option '" + opt + "'");
    o.inputFormat = opt[2];
    if (opt.size() == 3) {
        o.outputFormat = opt[2];
        return;
    }
    if (!isIn(opt[3]) && opt[3] != 'c') throw InputError("unknown option '" + opt + "'");
    o.outputFormat = opt[3];
}

const char* specName(char c) {
    switch (c) {
        case 't':
        case 'T':
            return " trace";
        case 'o':
            return " origin";
        case 'd':
            return " direction";
        case 'v':
            return " value";
        case 'V':
            return " contribution";
        case 'l':
            return " length";
        case 'L':
            return " first_length";
        case 'c':
            return " local_coordinates";
        case 'p':
            return " point";
        case 'n':
            return " normal";
        case 'N':
            return " unperturbed_normal";
        case 's':
            return " surface";
        case 'w':
            return " weight";
        case 'W':
            return " coefficient";
        case 'm':
            return " modifier";
        case 'M':
            return " material";
        case 'r':
            return " mirrored_value";
        case 'x':
            return " unmirrored_value";
        case 'R':
            return " mirrored_length";
        case 'X':
            return " unmirrored_length";
        case '~':
            return " tilde";
        default:
            return "";
    }
}

// -ti/-te/-tI/-tE (RADIANCE rtmain.c): a word, or the words of a file.
void readTraceList(OptionReader& r, TraceFilter& t) {
    const std::string& opt = r.option();
    const std::string& v = r.word();
    const bool include = opt[2] == 'i' || opt[2] == 'I';
    const TraceFilter::Mode mode =
        include ? TraceFilter::Mode::kInclude : TraceFilter::Mode::kExclude;
    if (t.mode != mode) {
        t.mode = mode;
        t.modifiers.clear();
    }
    if (opt[2] == 'i' || opt[2] == 'e') {
        t.modifiers.push_back(v);
        return;
    }
    // RADIANCE rtmain.c: wordfile on getpath, so the file is found along RAYPATH.
    for (std::string& w : calc::readWordFile(v, calc::defaultSearchPath(projectLibDir()),
                                             include ? "trace include" : "trace exclude"))
        t.modifiers.push_back(std::move(w));
}

// RADIANCE 6's colour outputs (rtmain.c): primaries or one channel, and -co[+|-].
void addColourOutput(OptionTable& t, ColourOutput& c) {
    using P = ColourOutput::Primaries;
    using C = ColourOutput::Channel;
    t.add(customOption("-pRGB", [&c](OptionReader&) { c.setPrimaries(P::kRgb); }));
    t.add(customOption("-pXYZ", [&c](OptionReader&) { c.setPrimaries(P::kXyz); }));
    t.add(customOption("-pc", [&c](OptionReader& r) {
        std::array<double, 8> p;
        for (double& v : p) v = r.real();
        c.setCustomPrimaries(p);
    }));
    const std::pair<const char*, C> channels[] = {
        {"-pY", C::kPhotopic}, {"-pS", C::kScotopic}, {"-pM", C::kMelanopic}, {"-pA", C::kAverage}};
    for (const auto& [name, ch] : channels)
        t.add(customOption(name, [&c, ch = ch](OptionReader&) { c.setChannel(ch); }));
    t.add(customOption(
        [](const std::string& a) { return a == "-co" || a == "-co+" || a == "-co-"; }, "-co",
        [&c](OptionReader& r) {
            const std::string& a = r.option();
            c.setSpectral(a.size() == 3 ? !c.spectral() : a[3] == '+');
        }));
}

// rtrace's table, in the order of its -defaults lines (rtmain.c printdefaults), then the
// common options.
OptionTable rtraceTable(RtraceOptions& o) {
    OptionTable t;
    t.expandArgs = true;
    t.helpIsDefaults = true;
    t.add(flagOption("-I", o.immediateIrradiance), [&o] {
        return o.immediateIrradiance ? std::string("-I+\t\t\t\t# immediate irradiance on\n")
                                     : std::string();
    });
    // Only positive resolutions make sense; a negative one is a bad value, as before.
    auto resolution = [](const std::string& name, int& v) {
        return customOption(name, [&v](OptionReader& r) { v = int(r.integer(0, 2147483647L)); });
    };
    addRayOptions(t, o.render.threads, {resolution("-x", o.xres), resolution("-y", o.yres)}, o.xres,
                  o.yres, o.limitDistance, o.header, o.inputFormat, o.outputFormat);
    t.add(customOption(prefix("-f"), "-f[io]",
                       [&o](OptionReader& r) { parseFormat(r.option(), o); }));
    t.add(customOption(prefix("-o"), "-o",
                       [&o](OptionReader& r) {
                           o.outputSpec = r.option().substr(2);
                           // 'T' (only a trace letter): shadow rays in the tree too.
                           o.render.treeShadowRays = o.outputSpec.find('T') != std::string::npos;
                       }),
          [&o] {
              std::string line = formatLine("-o%-9s\t\t\t# output", o.outputSpec.c_str());
              for (char c : o.outputSpec) line += specName(c);
              return line + '\n';
          });
    t.add(warningsOption(o.render.warnings));
    addColourOutput(t, o.colours);
    for (const char* name : {"-ti", "-te", "-tI", "-tE"})
        t.add(customOption(name, [&o](OptionReader& r) { readTraceList(r, o.trace); }));
    addRenderOptions(t, o.render);
    return t;
}

}  // namespace

const char* formatName(char format) {
    switch (format) {
        case 'a':
            return "ascii";
        case 'f':
            return "float";
        case 'd':
            return "double";
        case 'c':
            return "32-bit_rle_rgbe";
        default:
            return "unknown";
    }
}

RtraceOptions rtraceDefaults() {
    RtraceOptions o;
    o.render.uncorrelated = true;
    o.render.limits.maxDepth = -10;
    o.render.limits.minWeight = 2e-3;
    return o;
}

RtraceOptions parseRtraceArgs(int argc, const char* const* argv) {
    return parseRtraceArgs(argVector(argc, argv));
}

RtraceOptions parseRtraceArgs(std::vector<std::string> args) {
    RtraceOptions o = rtraceDefaults();
    const OptionParse p = rtraceTable(o).parse(args, 1);
    o.optionCount = p.next;
    o.printVersion = p.stop == OptionStop::kVersion;
    o.printDefaults = p.stop == OptionStop::kDefaults;
    if (p.stop == OptionStop::kEnd) o.sceneFile = sceneArgument(args, p.next);
    o.args = std::move(args);
    return o;
}

const std::string& sceneArgument(const std::vector<std::string>& args, size_t i) {
    if (i >= args.size()) throw InputError("missing octree argument");
    if (i + 1 < args.size())
        throw InputError("unexpected argument '" + args[i + 1] + "' after octree '" + args[i] +
                         "'");
    return args[i];
}

void addRayOptions(OptionTable& t, int& threads, std::array<OptionSpec, 2> xy, const int& xres,
                   const int& yres, bool& limitDistance, bool& header, const char& inputFormat,
                   const char& outputFormat, size_t flagLength) {
    // RADIANCE compat: rtmain.c/rcmain.c printdefaults, lines and formats.
    t.add(threadsOption(threads), [&threads] {
        return formatLine("-n %-2d\t\t\t\t# number of rendering processes\n", threads);
    });
    t.add(std::move(xy[0]), [&xres, &yres] {
        return formatLine("-x %-9d\t\t\t# %s\n", xres,
                          xres && yres ? "x resolution" : "flush interval");
    });
    t.add(std::move(xy[1]), [&yres] { return formatLine("-y %-9d\t\t\t# y resolution\n", yres); });
    t.add(flagOption("-ld", limitDistance, flagLength == SIZE_MAX ? SIZE_MAX : flagLength + 1),
          [&limitDistance] {
              return std::string(limitDistance ? "-ld+\t\t\t\t# limit distance on\n"
                                               : "-ld-\t\t\t\t# limit distance off\n");
          });
    t.add(flagOption("-h", header, flagLength), [&header] {
        return formatLine("-h%c\t\t\t\t# %s header\n", header ? '+' : '-',
                          header ? "output" : "no");
    });
    // The format option itself is each tool's (their errors differ); this is its line.
    t.add(customOption([](const std::string&) { return false; }, "-f line", {}),
          [&inputFormat, &outputFormat] {
              return formatLine("-f%c%c\t\t\t\t# format input/output = %s/%s\n", inputFormat,
                                outputFormat, formatName(inputFormat), formatName(outputFormat));
          });
}

std::string formatRtraceDefaults(const RtraceOptions& opt) {
    RtraceOptions copy = opt;
    return rtraceTable(copy).formatDefaults();
}

}  // namespace rp::render
