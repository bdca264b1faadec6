// genblinds: a RADIANCE venetian blind description (see src/gen/genblinds.h).
#include "gen/genblinds.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "genblinds mat name depth width height nslats angle [-r|+r rcurv]\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "genblinds";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::string out;
    try {
        out = rp::gen::genblinds(args);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "genblinds: " << e.line << '\n';
        return e.exitCode;
    }
    std::cout << out;
    std::cout.flush();
    return std::cout ? 0 : 1;
}
