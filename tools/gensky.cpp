// gensky: a RADIANCE CIE sky description (see src/gen/gensky.h).
#include "gen/gensky.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, {}))
        return 0;  // -version (gensky prints its own -defaults)
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "gensky";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::vector<std::string> warnings;
    std::string out;
    try {
        out = rp::gen::gensky(args, &warnings);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "gensky: " << e.line << '\n';
        return e.exitCode;
    }
    for (const std::string& w : warnings) std::cerr << "gensky: " << w << '\n';
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
