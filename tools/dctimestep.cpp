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
    return rp::tools::runFilter("dctimestep", "write error on output", [&] {
        const rp::matrix::DctimestepOptions o = rp::matrix::parseDctimestepArgs(argc, argv);
        rp::matrix::runDctimestep(o, std::cout);
    });
}
