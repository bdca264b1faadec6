// -version and -defaults for the tools that take them before anything else: one place,
// so every tool prints the same version line (util/version.h). rtrace, rpict, rvu,
// rcontrib and mkpmap take both at any option position in their own parsers (as
// RADIANCE's do) and print the same line.
#pragma once

#include <iostream>
#include <string_view>

#include "util/version.h"

namespace rp::tools {

// If argv[1] is -version, prints the version line; if it is -defaults and the tool
// passes its `defaults` (its options with their default values, or for a generator its
// synopsis), prints them. Returns true when it printed (the tool then exits 0); false
// leaves the argument to the tool.
inline bool printedInfo(int argc, char** argv, std::string_view defaults) {
    if (argc < 2) return false;
    const std::string_view a = argv[1];
    if (a == "-version") {
        std::cout << versionLine() << '\n';
    } else if (a == "-defaults" && !defaults.empty()) {
        std::cout << defaults;
        if (defaults.back() != '\n') std::cout << '\n';
    } else {
        return false;
    }
    std::cout.flush();
    return true;
}

}  // namespace rp::tools
