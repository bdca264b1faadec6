// genssky: RADIANCE 6's spectral sky (see src/gen/genssky.h).
#include "gen/genssky.h"

#include <iostream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/paths.h"

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, {}))
        return 0;  // -version (genssky prints its own -defaults)
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "genssky";  // a fixed name keeps the header path-independent
    std::vector<std::string> warnings;
    std::string out;
    try {
        out = rp::gen::genssky(args, rp::calc::defaultSearchPath(rp::projectLibDir()), &warnings);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "genssky: " << e.line << '\n';
        return e.exitCode;
    }
    for (const std::string& w : warnings) std::cerr << "genssky: " << w << '\n';
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
