// objview: a quick look at RADIANCE objects (see src/rad/objview.h).
//   objview [-u up][-v view][-b][-s][-w][-V][-e][-n nprocs][-o dev][-r picture] [input ..]
#include "rad/objview.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "rad/rad_run.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(
            argc, argv,
            "objview [-u up][-v view][-b][-s][-w][-V][-e][-n nprocs][-o dev][-r picture]"
            "[-ap file [bwidth]] [input ..]\n"))
        return 0;
    try {
        const rp::rad::ObjviewCommand cmd =
            rp::rad::parseObjviewArgs(std::vector<std::string>(argv + 1, argv + argc));
        rp::setWarningSink(
            [](const std::string& m) { std::cerr << "rad: warning - " << m << '\n'; });
        rp::rad::putOwnFolderFirstOnPath();
        rp::rad::runObjview(cmd, std::cin, std::cout,
                            [](const std::string& c) { return std::system(c.c_str()); });
        std::cout.flush();
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "objview: " << e.line << '\n';
        return e.exitCode;
    }
}
