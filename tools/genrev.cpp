// genrev: a RADIANCE genrev(1) description (see src/gen/genrev.h). -f files are found along
// RAYPATH (default ".").
#include "gen/genrev.h"

#include <iostream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults = "genrev mat name 'z(t)' 'r(t)' nseg [-e expr][-f file][-s]\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "genrev";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::vector<std::string> warnings;
    std::string out;
    try {
        out = rp::gen::genrev(args, rp::calc::defaultSearchPath(""), warnings);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "genrev: " << e.line << '\n';
        return e.exitCode;
    }
    for (const std::string& w : warnings) std::cerr << "genrev: " << w << '\n';
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
