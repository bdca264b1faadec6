// getbbox: the bounding box of RADIANCE scene descriptions (see src/scene/scene_bbox.h).
//   getbbox [ -w ][ -h ] [ input .. ]
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "gen/builtin_commands.h"
#include "info_options.h"
#include "main_errors.h"
#include "scene/scene_bbox.h"
#include "util/error.h"
#include "util/options.h"
#include "util/warnings.h"

namespace {

// RADIANCE compat (getbbox.c): a word starting with '-' other than -w... and -h... ends
// the options and is the first input.
rp::OptionTable getbboxTable(bool& header) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.unknownEnds = true;
    t.add(rp::customOption(rp::prefix("-w"), "-w", [](rp::OptionReader&) {
        rp::setWarningSink([](const std::string&) {});
    }));
    t.add(
        rp::customOption(rp::prefix("-h"), "-h", [&header](rp::OptionReader&) { header = false; }));
    return t;
}

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-w-\t\t\t\t# warnings on\n"
    "-h-\t\t\t\t# header line \"xmin xmax ymin ymax zmin zmax\" printed\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    try {
        std::vector<std::string> args(argv, argv + argc);
        bool header = true;
        const std::size_t first = getbboxTable(header).parse(args, 1).next;
        std::vector<std::string> inputs(args.begin() + long(first), args.end());
        if (inputs.empty()) inputs.push_back("-");
        const rp::BoundingBox box = rp::sceneBoundingBox(inputs, rp::gen::builtinLoadOptions());
        const std::string out = rp::formatBoundingBox(box, header);
        if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size() ||
            std::fflush(stdout) != 0)
            throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "getbbox: " << e.line << '\n';
        return e.exitCode;
    }
}
