// pvalue: RADIANCE's picture <-> pixel values converter (see src/image/pvalue.h).
//   pvalue [-h][-H][-o][-b][-d|-da|-df|-dd|+d..][-e exposure] [picture] > values
//   pvalue -r [-h][-H][-b][-d..][-e exposure][-y N +x M] [values] > picture.hdr
#include "image/pvalue.h"

#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/header.h"

int main(int argc, char** argv) {
    rp::PvalueOptions defaults;
    rp::PvalueSize size;
    if (rp::tools::printedInfo(argc, argv, rp::pvalueTable(defaults, size).formatDefaults()))
        return 0;
    try {
        std::vector<std::string> args(argv + 1, argv + argc);
        rp::PvalueOptions opt = rp::parsePvalueArgs(args);
        std::ios::sync_with_stdio(false);
        rp::runPvalue(opt, rp::commandLine(argc, argv), std::cin, std::cout);
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "pvalue: " << e.line << '\n';
        return e.exitCode;
    }
}
