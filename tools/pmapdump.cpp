// pmapdump: dump photon maps as a RADIANCE scene, an ASCII point list or a binary PLY point
// cloud on standard output (photon-map manual section 7; see src/pmap/dump.h).
#include <unistd.h>

#include <iostream>

#include "info_options.h"
#include "main_errors.h"
#include "pmap/dump.h"
#include "util/error.h"
#include "util/header.h"

namespace {

void usage(const char* prog) {
    std::cerr << "Dump photon maps as RADIANCE scene description, ASCII point list or PLY\n\n"
              << "Usage: " << prog
              << " [-a[+|-]] [-P[+|-]] [-n num] [-r radscale] [-f[+|-] | -c r g b] pmap1"
                 " [options] pmap2 ...\n";
}

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-a-\t\t\t\t# RADIANCE scene output (-a+: ASCII point list)\n"
    "-P-\t\t\t\t# binary PLY output off\n"
    "-n  10000\t\t\t# photons dumped per map\n"
    "-r  1.0\t\t\t\t# sphere radius scale\n"
    "-f-\t\t\t\t# colour by map type (-f+: by photon flux)\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    if (argc < 2) {
        usage(argv[0]);
        return 1;
    }
    try {
        const auto requests = rp::pmap::parseDumpArgs(argc, argv);
        if (requests.front().options.ply && ::isatty(STDOUT_FILENO))
            throw rp::InputError(
                "refusing to write a binary PLY file to a terminal; "
                "redirect standard output");
        std::ios::sync_with_stdio(false);
        rp::pmap::runPmapdump(requests, rp::commandLine(argc, argv), std::cout);
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "pmapdump: " << e.line << '\n';
        return e.exitCode;
    }
}
