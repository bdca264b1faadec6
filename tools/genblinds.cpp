// genblinds: a RADIANCE venetian blind description (see src/gen/genblinds.h).
#include "gen/genblinds.h"

#include <iostream>
#include <string>
#include <vector>

#include "util/error.h"
#include "main_errors.h"

int main(int argc, char** argv) {
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
