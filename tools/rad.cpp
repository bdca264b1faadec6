// rad: RADIANCE's executive for oconv, mkillum, mkpmap, rpict, rvu and pfilt (see
// src/rad/rad_run.h).
//   rad [-w][-s][-n|-N npr][-t][-e][-V][-v view][-o dev] rfile [VAR=value ..]
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "rad/rad_run.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, std::string("rad ") + rp::rad::radUsage() + "\n"))
        return 0;
    try {
        const rp::rad::RadCommand cmd =
            rp::rad::parseRadArgs(std::vector<std::string>(argv + 1, argv + argc));
        rp::setWarningSink(
            [](const std::string& m) { std::cerr << "rad: warning - " << m << '\n'; });
        rp::rad::putOwnFolderFirstOnPath();
        rp::rad::runRad(cmd, std::cout,
                        [](const std::string& c) { return std::system(c.c_str()); });
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "rad: " << e.line << '\n';
        return e.exitCode;
    }
}
