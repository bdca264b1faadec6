// pcomb: RADIANCE's picture combiner (see src/image/pcomb.h).
//   pcomb [-h][-w][-x xres][-y yres][-e expr][-f file] [ [-o][-s f][-c r g b] input .. ]
#include "image/pcomb.h"

#include <ctime>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/header.h"
#include "util/paths.h"

int main(int argc, char** argv) {
    rp::PcombOptions defaults;
    if (rp::tools::printedInfo(argc, argv, rp::pcombTable(defaults).formatDefaults())) return 0;
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        const rp::PcombOptions opt = rp::parsePcombArgs(args);
        std::ios::sync_with_stdio(false);
        std::vector<rp::PcombPicture> inputs;
        for (const rp::PcombInput& in : opt.inputs) {
            rp::PcombPicture p;
            p.input = in;
            if (in.name == "-") {
                p.name = "<stdin>";
                p.picture = rp::readPicture(std::cin, p.name);
            } else {
                p.name = in.name;
                std::ifstream f(in.name, std::ios::binary);
                if (!f) throw rp::InputError(rp::SourceLoc{in.name, 0}, "cannot open picture");
                p.picture = rp::readPicture(f, in.name);
            }
            inputs.push_back(std::move(p));
        }
        const rp::Picture out =
            rp::runPcomb(inputs, opt, rp::commandLine(argc, argv), std::time(nullptr),
                         rp::calc::defaultSearchPath(rp::projectLibDir()));
        rp::writePicture(std::cout, out);
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "pcomb: " << e.line << '\n';
        return e.exitCode;
    }
}
