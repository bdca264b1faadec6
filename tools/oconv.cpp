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
#include <vector>

#include "gen/builtin_commands.h"
#include "info_options.h"
#include "main_errors.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"
#include "util/warnings.h"

namespace {
[[noreturn]] void usage(const char* why) {
    // One line, as every error: "usage: oconv [-f] [-w] [-r maxres] [-n objlim] [-i oct] file ..."
    std::fprintf(stderr, "oconv: %s\n", why);
    std::exit(1);
}

// oconv's options (util/options.h), with its messages; a number is read as RADIANCE's
// atoi/atof would but refusing junk.
rp::OptionTable oconvTable(rp::OconvRequest& request) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.missing = [](const std::string& opt) { return "option " + opt + " needs a value"; };
    t.messages.bad = [](const std::string& opt, const std::string& v, rp::ValueKind) {
        return "option " + opt + " needs a number, not '" + v + "'";
    };
    t.messages.unknown = [](const std::string& opt) { return "unknown option: '" + opt + "'"; };
    t.add(rp::customOption("-f", [&request](rp::OptionReader&) { request.frozen = true; }),
          [&request] {
              return rp::formatLine(
                  "-f%c\t\t\t\t# octree names the scene files (-f: holds the "
                  "objects)\n",
                  request.frozen ? '+' : '-');
          });
    t.add(rp::customOption(
              "-w", [](rp::OptionReader&) { rp::setWarningSink([](const std::string&) {}); }),
          [] { return std::string("-w-\t\t\t\t# warnings on\n"); });
    t.add(rp::customOption("-r",
                           [&request](rp::OptionReader& r) {
                               request.maxres = static_cast<int>(r.real());
                               if (request.maxres < 1)
                                   throw rp::InputError("-r needs a resolution of at least 1");
                           }),
          [&request] {
              return rp::formatLine(
                  "-r  %d\t\t\t# resolution: smallest cell is the cube / "
                  "maxres\n",
                  request.maxres);
          });
    t.add(
        rp::customOption(
            "-n", [&request](rp::OptionReader& r) { request.objlim = static_cast<int>(r.real()); }),
        [&request] {
            return rp::formatLine("-n  %d\t\t\t\t# objects in a leaf before it divides\n",
                                  request.objlim);
        });
    t.add(rp::customOption("-b", [&request](rp::OptionReader& r) {
        std::array<double, 4> b{};
        for (double& v : b) v = r.real();
        request.bounds = b;
    }));
    t.add(rp::valueOption("-i", request.addTo));
    t.setDefaultsOrder({"-n", "-r", "-f", "-w"});
    return t;
}
}  // namespace

int main(int argc, char** argv) {
    rp::OconvRequest request;
    if (rp::tools::printedInfo(argc, argv, oconvTable(request).formatDefaults())) return 0;
    // argv[0] as given, as RADIANCE's printargs() writes it on Unix.
    request.commandLine = rp::commandLine(argc, argv);
    std::vector<std::string> args(argv, argv + argc);
    size_t first = 0;
    try {
        // A lone "-" (standard input) ends the options, as in RADIANCE.
        first = oconvTable(request).parse(args, 1).next;
    } catch (const rp::InputError& e) {
        usage(e.what());
    }
    for (size_t i = first; i < args.size(); ++i) request.files.push_back(args[i]);
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
