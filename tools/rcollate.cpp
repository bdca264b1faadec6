// rcollate: RADIANCE's matrix reshaper (see src/matrix/rcollate.h).
//   rcollate [-h[io]][-w][-c][-f[afdb][N]][-t][-ic C][-ir R][-oc C][-or R][-o RxC[xR1xC1..]]
//   [input]
#include "matrix/rcollate.h"

#include <iostream>
#include <string>

#include "info_options.h"
#include "main_errors.h"
#include "matrix/matrix_input.h"
#include "util/error.h"
#include "util/file_read.h"
#include "util/warnings.h"

// -defaults (tools/info_options.h): the synopsis, as for the generators.
constexpr const char* kSynopsis =
    "rcollate [-h[io]][-w][-c][-f[afdb][N]][-t][-ic in_col][-ir in_row][-oc out_col][-or "
    "out_row][-o RxC[xR1xC1..]] [input.dat]\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kSynopsis)) return 0;
    return rp::tools::runFilter("rcollate", "error writing standard output", [&] {
        const rp::matrix::RcollateOptions o = rp::matrix::parseRcollateArgs(argc, argv);
        const rp::matrix::InputData in =
            o.input.empty() ? rp::matrix::readInput("-")
                            : rp::matrix::InputData{o.input, rp::readFileBytes(o.input)};
        rp::matrix::runRcollate(o, in, std::cout);
    });
}
