// pmapdump: dump photon maps as a RADIANCE scene, an ASCII point list or a binary PLY point
// cloud on standard output (photon-map manual section 7; see src/pmap/dump.h).
#include <unistd.h>

#include <iostream>

#include "pmap/dump.h"
#include "util/error.h"
#include "util/header.h"
#include "main_errors.h"

namespace {

void usage(const char* prog) {
    std::cerr << "Dump photon maps as RADIANCE scene description, ASCII point list or PLY\n\n"
              << "Usage: " << prog
              << " [-a[+|-]] [-P[+|-]] [-n num] [-r radscale] [-f[+|-] | -c r g b] pmap1"
                 " [options] pmap2 ...\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        usage(argv[0]);
        return 1;
    }
    try {
        const auto requests = rp::pmap::parseDumpArgs(argc, argv);
        if (requests.front().options.ply && ::isatty(STDOUT_FILENO))
            throw rp::InputError("refusing to write a binary PLY file to a terminal; "
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
