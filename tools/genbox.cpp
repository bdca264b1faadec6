// genbox: a RADIANCE box description (see src/gen/genbox.h).
#include "gen/genbox.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "genbox mat name xsiz ysiz zsiz [-i] [-r rad | -b bev] [-n nseg]	# -r 0 -b 0 -n 1 (square "
    "edges)\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "genbox";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::vector<std::string> warnings;
    std::string out;
    try {
        out = rp::gen::genbox(args);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "genbox: " << e.line << '\n';
        return e.exitCode;
    }
    for (const std::string& w : warnings) std::cerr << "genbox: " << w << '\n';
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
