// rfluxmtx: flux-transfer (daylight-coefficient) matrices between a sender and the
// receivers of a scene (RADIANCE rfluxmtx.1), computed by our rcontrib in-process rather
// than by a child rcontrib. The logic lives in src/flux (rfluxmtx.h).
#include "flux/rfluxmtx.h"

#include <iostream>
#include <string>

#include "gen/builtin_commands.h"
#include "main_errors.h"
#include "util/cluster.h"
#include "util/command_args.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    try {
        const rp::flux::RfluxmtxCommand cmd =
            rp::flux::parseRfluxmtxArgs(rp::argVector(argc, argv));
        const bool warnings = cmd.warnings;
        rp::setWarningSink([warnings](const std::string& m) {
            if (warnings) std::cerr << "rfluxmtx: warning: " << m << '\n';
        });
        rp::LocalCluster alone;
        rp::flux::runRfluxmtx(cmd, rp::gen::builtinLoadOptions(), std::cin, std::cout, std::cerr,
                              alone);
        std::cout.flush();
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "rfluxmtx: " << e.line << '\n';
        return e.exitCode;
    }
}
