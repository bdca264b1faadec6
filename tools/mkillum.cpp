// mkillum: compute illum sources for a RADIANCE scene (RADIANCE mkillum.1): the surfaces
// its `#@mkillum` lines select become illum or light sources whose distributions are
// sampled with our renderer (src/illum/mkillum.h).
//   mkillum [-n N][render options] octree [< file ..]
//   mkillum [render options] -defaults
#include "illum/mkillum.h"

#include <iostream>

#include "main_errors.h"
#include "util/command_args.h"
#include "util/version.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    try {
        const rp::illum::MkillumOptions o = rp::illum::parseMkillumArgs(rp::argVector(argc, argv));
        if (o.printVersion) {
            std::cout << rp::versionLine() << '\n';
            return 0;
        }
        if (o.printDefaults) {
            std::cout << rp::illum::formatMkillumDefaults(o);
            return 0;
        }
        const bool warnings = o.render.warnings;
        rp::setWarningSink([warnings](const std::string& m) {
            if (warnings) std::cerr << "mkillum: warning: " << m << '\n';
        });
        std::ios::sync_with_stdio(false);
        rp::illum::runMkillum(o, std::cin, std::cout);
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "mkillum: " << e.line << '\n';
        return e.exitCode;
    }
}
