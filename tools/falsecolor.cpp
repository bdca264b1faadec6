// falsecolor: RADIANCE's false-colour luminance pictures with a legend
// (see src/image/falsecolor.h for the mapping, legend and options).
//   falsecolor [-i input.hdr] [-p picture|-ip picture] [-s scale|a] [-n ndivs] [-l label]
//              [-m mult] [-d decimals] [-log decades] [-pal palette] [-r expr -g expr
//              -b expr] [-cl|-cb|-cp] [-e] [-lw width] [-lh height] [-palettes] > out.hdr
#include "image/falsecolor.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/header.h"

int main(int argc, char** argv) {
    rp::FalseColorOptions defaults;
    if (rp::tools::printedInfo(argc, argv, rp::falseColorTable(defaults).formatDefaults()))
        return 0;
    try {
        std::vector<std::string> args(argv + 1, argv + argc);
        rp::FalseColorOptions opt = rp::parseFalseColorArgs(args);
        std::ios::sync_with_stdio(false);
        rp::runFalseColor(opt, rp::commandLine(argc, argv), std::cin, std::cout);
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "falsecolor: " << e.line << '\n';
        return e.exitCode;
    }
}
