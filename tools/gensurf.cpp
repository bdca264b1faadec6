// gensurf: a RADIANCE gensurf(1) description (see src/gen/gensurf.h). -f files are found along
// RAYPATH (default ".").
#include "gen/gensurf.h"

#include <iostream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "gensurf mat name 'x(s,t)' 'y(s,t)' 'z(s,t)' m n [-e expr][-f file][-s][-o]\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "gensurf";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::vector<std::string> warnings;
    std::string out;
    try {
        out = rp::gen::gensurf(args, rp::calc::defaultSearchPath(""), std::cin, warnings);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "gensurf: " << e.line << '\n';
        return e.exitCode;
    }
    for (const std::string& w : warnings) std::cerr << "gensurf: " << w << '\n';
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
