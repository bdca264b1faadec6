// genrev: a RADIANCE genrev(1) description (see src/gen/genrev.h). -f files are found along
// RAYPATH (default ".").
#include <iostream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "gen/genrev.h"
#include "util/error.h"
#include "main_errors.h"

int main(int argc, char** argv) {
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
