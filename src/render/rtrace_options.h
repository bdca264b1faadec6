// rtrace's command line (RADIANCE rtmain.c, rtrace.1): the options struct, its parser and
// the -defaults text. The common render options are parsed by render_options.h; the ray
// input/output formats by rtrace_io.h; the run itself by rtrace_run.h.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "render/colour_output.h"
#include "render/render_options.h"
#include "util/options.h"

namespace rp::render {

// -ti/-te mod (-tI/-tE file): which rays of the ray tree the trace output (-o...t...)
// reports, by the modifier of the surface each ray hits (RADIANCE rtrace.c ourtrace).
// RADIANCE compat (rtmain.c): switching between include and exclude starts a new list;
// repeating the same kind adds to it.
struct TraceFilter {
    enum class Mode { kAll, kInclude, kExclude };
    Mode mode = Mode::kAll;
    std::vector<std::string> modifiers;
};

struct RtraceOptions {
    RenderOptions render;              // -n, -e, -w and every common option live here
    std::string outputSpec = "v";      // -o
    char inputFormat = 'a';            // -f first letter: a f d
    char outputFormat = 'a';           // -f second letter: a f d c
    bool header = true;                // -h
    int xres = 0;                      // -x: flush interval (with -y: picture width)
    int yres = 0;                      // -y
    bool immediateIrradiance = false;  // -I
    TraceFilter trace;                 // -ti -te -tI -tE
    ColourOutput colours;              // -pRGB -pXYZ -pY -pS -pM -pA -co (RADIANCE 6)
    bool limitDistance = false;     // -ld: a ray's distance limit from its input direction's length
    bool printDefaults = false;     // -defaults / -help: print and exit, no scene needed
    bool printVersion = false;      // -version: print the version line and exit
    std::string sceneFile;          // the octree / scene file (last argument)
    std::vector<std::string> args;  // after @file/$EVAR expansion, argv[0] first
    size_t optionCount = 0;         // args[0..optionCount) are program and options (header)
};

// RtraceOptions with rtrace's own defaults: RADIANCE compat (rtmain.c): uncorrelated
// sampling (-u+), -lr -10 and -lw 2e-3.
RtraceOptions rtraceDefaults();

// Parses argv (argv[0] the program). @file and $EVAR arguments are expanded at option
// positions. Throws InputError: "unknown option '-xx'", missing/bad values, "missing octree
// argument", extra arguments after the octree, -fc with specifiers that are not colours,
// -tI/-tE files that cannot be read.
// Stops early (printDefaults set, sceneFile empty) at -defaults or -help.
RtraceOptions parseRtraceArgs(int argc, const char* const* argv);
RtraceOptions parseRtraceArgs(std::vector<std::string> args);

// What `rtrace -defaults` prints (RADIANCE rtmain.c printdefaults, then the common options).
std::string formatRtraceDefaults(const RtraceOptions& opt);

// "ascii", "float", "double" or "32-bit_rle_rgbe" (RADIANCE formstr).
const char* formatName(char format);

// The options RADIANCE's rtrace and rcontrib share, in their -defaults order: -n, the
// given -x and -y specs, -ld, -h, and the -f line (each tool reads -f itself). The
// booleans match words up to `flagLength` characters (-ld one more; SIZE_MAX: any).
void addRayOptions(OptionTable& t, int& threads, std::array<OptionSpec, 2> xy, const int& xres,
                   const int& yres, bool& limitDistance, bool& header, const char& inputFormat,
                   const char& outputFormat, size_t flagLength = SIZE_MAX);

// The octree argument at args[i], which must be the last (rtrace, rcontrib): throws
// InputError "missing octree argument" or for an argument after it.
const std::string& sceneArgument(const std::vector<std::string>& args, size_t i);

}  // namespace rp::render
