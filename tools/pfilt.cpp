// pfilt: RADIANCE's picture filter: exposure, anti-aliasing and resizing (see
// src/image/pfilt.h).
//   pfilt [-x xres|/f][-y yres|/f][-p aspect][-c][-e exp][-1|-2][-r rad|-m thresh|-b]
//         [-n npts][-s spread][-h hotlvl][-a] [picture] > output.hdr
#include "image/pfilt.h"

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/header.h"

int main(int argc, char** argv) {
    rp::PfiltOptions defaults;
    if (rp::tools::printedInfo(argc, argv, rp::pfiltTable(defaults).formatDefaults())) return 0;
    try {
        std::vector<std::string> args(argv + 1, argv + argc);
        size_t optionWords = 0;
        const rp::PfiltOptions opt = rp::parsePfiltArgs(args, optionWords);
        // RADIANCE records the program and its options, not the file.
        const std::string history = rp::commandLine(static_cast<int>(optionWords) + 1, argv);
        std::ios::sync_with_stdio(false);
        const std::string what = opt.inputFile.empty() ? "<stdin>" : opt.inputFile;
        if (opt.inputFile.empty()) {
            rp::runPfilt(std::cin, what, opt, history, std::cout);
        } else {
            std::ifstream in(opt.inputFile, std::ios::binary);
            if (!in) throw rp::InputError(rp::SourceLoc{what, 0}, "cannot open picture");
            rp::runPfilt(in, what, opt, history, std::cout);
        }
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "pfilt: " << e.line << '\n';
        return e.exitCode;
    }
}
