// radcompare: RADIANCE's check that two RADIANCE files match within tolerances (see
// src/image/radcompare.h).
//   radcompare [-h][-c#][-s|-w|-v][-rel min_test][-rms epsilon][-max epsilon] reference test
// Exit status 0: the same within tolerance; 1: different; 2: an error (RADIANCE's).
#include "image/radcompare.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

int main(int argc, char** argv) {
    rp::RadcompareOptions defaults;
    if (rp::tools::printedInfo(argc, argv, rp::radcompareTable(defaults).formatDefaults()))
        return 0;
    try {
        std::vector<std::string> args(argv + 1, argv + argc);
        const rp::RadcompareOptions opt = rp::parseRadcompareArgs(args);
        const int rc = rp::runRadcompare(opt, std::cin, std::cout);
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return rc;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "radcompare: " << e.line << '\n';
        return 2;  // RADIANCE's radcompare: 2 for every error, 1 only for a difference
    }
}
