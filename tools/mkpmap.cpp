// mkpmap: generate RADIANCE photon maps (see src/pmap/mkpmap.h).
#include <fstream>
#include <iostream>

#include "gen/builtin_commands.h"
#include "pmap/mkpmap.h"
#include "pmap/mkpmap_options.h"
#include "util/error.h"
#include "util/header.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    std::ostream* diag = &std::cerr;
    std::ofstream diagFile;
    try {
        rp::pmap::MkpmapOptions opt = rp::pmap::parseMkpmapArgs(argc, argv);
        if (!opt.diagnosticsFile.empty()) {
            // RADIANCE mkpmap -e: diagnostics appended to the file.
            diagFile.open(opt.diagnosticsFile, std::ios::app);
            if (!diagFile) {
                std::cerr << "mkpmap: cannot open diagnostics file " << opt.diagnosticsFile
                          << '\n';
                return 2;
            }
            diag = &diagFile;
            *diag << "*** " << rp::commandLine(argc, argv) << '\n';
        }
        rp::setWarningSink([diag](const std::string& m) { *diag << "mkpmap: warning: " << m << '\n'; });
        rp::pmap::runMkpmap(opt, rp::commandLine(argc, argv), *diag,
                            rp::gen::builtinLoadOptions());
        return 0;
    } catch (const rp::InputError& e) {
        *diag << "mkpmap: " << e.what() << '\n';
        if (diag != &std::cerr) std::cerr << "mkpmap: " << e.what() << '\n';
        return 1;
    }
}
