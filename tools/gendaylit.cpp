// gendaylit: a RADIANCE Perez all-weather sky description (see src/gen/gendaylit.h).
#include "gen/gendaylit.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "gendaylit month day hour [-y year] [-a lat] [-o lon] [-m mer] [-s|-w|-i] [-g grefl] [-O "
    "0|1|2] [-P|-W|-L|-G|-E] ...\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "gendaylit";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::vector<std::string> warnings;
    std::string out;
    try {
        out = rp::gen::gendaylit(args, &warnings);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "gendaylit: " << e.line << '\n';
        return e.exitCode;
    }
    for (const std::string& w : warnings) std::cerr << "gendaylit: " << w << '\n';
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
