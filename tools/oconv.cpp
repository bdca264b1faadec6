// oconv: freezes RADIANCE scene descriptions into our scene file on standard output.
//   oconv [-f] [-w] [-r maxres] [-n objlim] [-i scene.oct] file.rad ... > scene.oct
// Output is FORMAT=radphoton_scene, not Radiance_octree: we build the accelerator when
// rendering, so there is no octree to store (scene/scene_file.h).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gen/builtin_commands.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/header.h"
#include "util/warnings.h"
#include "main_errors.h"

namespace {
[[noreturn]] void usage(const char* why) {
    // One line, as every error: "usage: oconv [-f] [-w] [-r maxres] [-n objlim] [-i oct] file ..."
    std::fprintf(stderr, "oconv: %s\n", why);
    std::exit(1);
}
}  // namespace

int main(int argc, char** argv) {
    rp::OconvRequest request;
    request.commandLine = rp::commandLine(argc, argv);
    int i = 1;
    for (; i < argc && argv[i][0] == '-' && argv[i][1] != '\0'; ++i) {
        std::string opt = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage(("option " + opt + " needs a value").c_str());
            return argv[++i];
        };
        if (opt == "-f") {
            // Freeze: our scene file always holds every record, so it is always frozen.
        } else if (opt == "-w") {
            rp::setWarningSink([](const std::string&) {});
        } else if (opt == "-r" || opt == "-n") {
            // Octree resolution and set size: accepted for RADIANCE scripts, no effect,
            // since the accelerator is built (by Embree) when rendering, not here.
            value();
        } else if (opt == "-i") {
            request.addTo = value();
        } else {
            usage(("unknown option: '" + opt + "'").c_str());
        }
    }
    for (; i < argc; ++i) request.files.push_back(argv[i]);
    if (request.files.empty() && request.addTo.empty()) usage("no scene files given");
    try {
        std::string bytes = rp::oconvOutput(request, rp::gen::builtinLoadOptions());
        if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() ||
            std::fflush(stdout) != 0) {
            std::fprintf(stderr, "oconv: write error on standard output\n");
            return 1;
        }
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::fprintf(stderr, "oconv: %s\n", e.line.c_str());
        return e.exitCode;
    }
    return 0;
}
