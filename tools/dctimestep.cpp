// dctimestep: RADIANCE's daylight-coefficient time steps (see src/matrix/dctimestep.h).
//   dctimestep [-n nsteps][-h][-o ospec][-i{f|d}][-o{f|d|c}] DCspec [skyf]
//   dctimestep [-n nsteps][-h][-o ospec][-i{f|d}][-o{f|d}] Vspec Tmat Dmat [skyf]
#include "matrix/dctimestep.h"

#include <iostream>
#include <string>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/warnings.h"

// -defaults (tools/info_options.h): the synopsis, as for the generators.
constexpr const char* kSynopsis =
    "dctimestep [-n nsteps][-h][-o ospec][-i{f|d}][-o{f|d|c}] DCspec [skyf]\n"
    "dctimestep [-n nsteps][-h][-o ospec][-i{f|d}][-o{f|d}] Vspec Tmat Dmat [skyf]\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kSynopsis)) return 0;
    try {
        std::ios::sync_with_stdio(false);
        rp::setWarningSink([](const std::string& m) {
            std::cout.flush();
            std::cerr << "dctimestep: warning - " << m << '\n';
        });
        const rp::matrix::DctimestepOptions o = rp::matrix::parseDctimestepArgs(argc, argv);
        rp::matrix::runDctimestep(o, std::cout);
        std::cout.flush();
        if (!std::cout) throw rp::InputError("write error on output");
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "dctimestep: " << e.line << '\n';
        return e.exitCode;
    }
}
