// xform: transform a RADIANCE scene description (see src/gen/xform_scene.h, xform(1)).
#include <iostream>

#include "gen/builtin_commands.h"
#include "gen/xform_scene.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/warnings.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "xform [-c|-e][-I][-m mat][-n name][-s scale][-t x y z][-rx|-ry|-rz deg][-mx|-my|-mz][-i N "
    "...][-a N ...] file ..\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::ios::sync_with_stdio(false);
    rp::setWarningSink([](const std::string& m) { std::cerr << "xform: warning: " << m << '\n'; });
    try {
        rp::XformOptions opts = rp::parseXformArgs(argc, argv, &std::cin);
        // The generators embedded in the files run in-process, in their files' folders.
        opts.commandHook = rp::gen::builtinCommandHook();
        std::cout << rp::xformScene(opts, std::cin);
        std::cout.flush();
        return std::cout ? 0 : 1;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "xform: " << e.line << '\n';
        return e.exitCode;
    }
}
