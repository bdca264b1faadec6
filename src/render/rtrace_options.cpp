// rtrace command-line parsing and -defaults (RADIANCE rtmain.c main/printdefaults).
#include "render/rtrace_options.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include "calc/search_path.h"
#include "render/command_args.h"
#include "util/error.h"
#include "util/paths.h"

namespace rp::render {

namespace {

int intValue(const std::vector<std::string>& args, size_t& i) {
    const std::string& opt = args[i];
    if (i + 1 >= args.size()) throw InputError("missing value for option '" + opt + "'");
    const std::string& v = args[++i];
    char* end = nullptr;
    errno = 0;
    long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno != 0 || n < 0 || n > 2147483647L)
        throw InputError("bad value '" + v + "' for option '" + opt + "'");
    return int(n);
}

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

// -ti/-te/-tI/-tE at args[i] (RADIANCE rtmain.c): a word, or the words of a file.
void parseTraceList(const std::vector<std::string>& args, size_t& i, TraceFilter& t) {
    const std::string& opt = args[i];
    if (i + 1 >= args.size()) throw InputError("missing value for option '" + opt + "'");
    const std::string& v = args[++i];
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
    size_t i = 1;
    for (; i < args.size(); ++i) {
        expandArgAt(args, i);
        if (i >= args.size() || args[i].size() < 2 || args[i][0] != '-') break;
        const std::string opt = args[i];
        if (opt == "-defaults" || opt == "-help" || opt == "-version") {
            (opt == "-version" ? o.printVersion : o.printDefaults) = true;
            o.args = std::move(args);
            o.optionCount = i;
            return o;
        }
        if (parseRenderOption(args, i, o.render)) {
            --i;  // parseRenderOption moved past the option; the loop adds one
            continue;
        }
        if (opt == "-x")
            o.xres = intValue(args, i);
        else if (opt == "-y")
            o.yres = intValue(args, i);
        else if (opt == "-ti" || opt == "-te" || opt == "-tI" || opt == "-tE")
            parseTraceList(args, i, o.trace);
        else if (opt.rfind("-ld", 0) == 0)
            o.limitDistance = boolSuffix(opt, 3, o.limitDistance);
        else if (opt.rfind("-I", 0) == 0)
            o.immediateIrradiance = boolSuffix(opt, 2, o.immediateIrradiance);
        else if (opt.rfind("-h", 0) == 0)
            o.header = boolSuffix(opt, 2, o.header);
        else if (opt.rfind("-f", 0) == 0)
            parseFormat(opt, o);
        else if (opt.rfind("-o", 0) == 0)
            o.outputSpec = opt.substr(2);
        else
            throw InputError("unknown option '" + opt + "'");
    }
    o.optionCount = std::min(i, args.size());
    o.sceneFile = sceneArgument(args, i);
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

std::string formatRayDefaults(int threads, int xres, int yres, bool limitDistance, bool header,
                              char inputFormat, char outputFormat) {
    std::string out;
    char line[256];
    auto put = [&](const char* fmt, auto... a) {
        std::snprintf(line, sizeof line, fmt, a...);
        out += line;
    };
    put("-n %-2d\t\t\t\t# number of rendering processes\n", threads);
    put("-x %-9d\t\t\t# %s\n", xres, xres && yres ? "x resolution" : "flush interval");
    put("-y %-9d\t\t\t# y resolution\n", yres);
    out +=
        limitDistance ? "-ld+\t\t\t\t# limit distance on\n" : "-ld-\t\t\t\t# limit distance off\n";
    put("-h%c\t\t\t\t# %s header\n", header ? '+' : '-', header ? "output" : "no");
    put("-f%c%c\t\t\t\t# format input/output = %s/%s\n", inputFormat, outputFormat,
        formatName(inputFormat), formatName(outputFormat));
    return out;
}

std::string formatRtraceDefaults(const RtraceOptions& o) {
    std::string out;
    char line[256];
    auto put = [&](const char* fmt, auto... a) {
        std::snprintf(line, sizeof line, fmt, a...);
        out += line;
    };
    // RADIANCE compat: rtmain.c printdefaults, lines and formats.
    if (o.immediateIrradiance) out += "-I+\t\t\t\t# immediate irradiance on\n";
    out += formatRayDefaults(o.render.threads, o.xres, o.yres, o.limitDistance, o.header,
                             o.inputFormat, o.outputFormat);
    put("-o%-9s\t\t\t# output", o.outputSpec.c_str());
    for (char c : o.outputSpec) out += specName(c);
    out += '\n';
    out += o.render.warnings ? "-w+\t\t\t\t# warning messages on\n"
                             : "-w-\t\t\t\t# warning messages off\n";
    out += formatRenderDefaults(o.render);
    return out;
}

}  // namespace rp::render
