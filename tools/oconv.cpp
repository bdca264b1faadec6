// oconv: compiles RADIANCE scene descriptions into a RADIANCE octree on standard output,
// byte for byte as RADIANCE's oconv writes it (FORMAT=Radiance_octree; scene/
// oconv_output.cpp), so that RADIANCE's own tools read it as well as ours.
//   oconv [-f] [-w] [-r maxres] [-n objlim] [-b xmin ymin zmin size | -i octree] file ...
// Without -f the octree names the scene files and readers read them again; with -f it
// holds the objects. Our renderers build their accelerator from the objects, not from the
// octree's tree, which is there for RADIANCE's.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gen/builtin_commands.h"
#include "info_options.h"
#include "main_errors.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/header.h"
#include "util/warnings.h"

namespace {
[[noreturn]] void usage(const char* why) {
    // One line, as every error: "usage: oconv [-f] [-w] [-r maxres] [-n objlim] [-i oct] file ..."
    std::fprintf(stderr, "oconv: %s\n", why);
    std::exit(1);
}

// A number option's value, read as RADIANCE's atoi/atof would but refusing junk.
double number(const std::string& opt, const char* s) {
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0')
        usage(("option " + opt + " needs a number, not '" + s + "'").c_str());
    return v;
}
}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-n  6\t\t\t\t# objects in a leaf before it divides\n"
    "-r  16384\t\t\t# resolution: smallest cell is the cube / maxres\n"
    "-f-\t\t\t\t# octree names the scene files (-f: holds the objects)\n"
    "-w-\t\t\t\t# warnings on\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    rp::OconvRequest request;
    // argv[0] as given, as RADIANCE's printargs() writes it on Unix.
    request.commandLine = rp::commandLine(argc, argv);
    int i = 1;
    // A lone "-" (standard input) ends the options, as in RADIANCE.
    for (; i < argc && argv[i][0] == '-' && argv[i][1] != '\0'; ++i) {
        std::string opt = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage(("option " + opt + " needs a value").c_str());
            return argv[++i];
        };
        if (opt == "-f") {
            request.frozen = true;
        } else if (opt == "-w") {
            rp::setWarningSink([](const std::string&) {});
        } else if (opt == "-r") {
            request.maxres = static_cast<int>(number(opt, value()));
            if (request.maxres < 1) usage("-r needs a resolution of at least 1");
        } else if (opt == "-n") {
            request.objlim = static_cast<int>(number(opt, value()));
        } else if (opt == "-b") {
            std::array<double, 4> b{};
            for (double& v : b) v = number(opt, value());
            request.bounds = b;
        } else if (opt == "-i") {
            request.addTo = value();
        } else {
            usage(("unknown option: '" + opt + "'").c_str());
        }
    }
    for (; i < argc; ++i) request.files.push_back(argv[i]);
    if (request.files.empty() && request.addTo.empty()) usage("no scene files given");
    if (request.bounds && !request.addTo.empty()) usage("only one of '-b' or '-i'");
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
