// -version and -defaults for the tools whose option tables (util/options.h) do not stop
// at them: one place, so every tool prints the same version line (util/version.h).
// rtrace, rpict, rvu, rcontrib and mkpmap get both from their tables, at any option
// position, and print the same line.
#pragma once

#include <iostream>
#include <string_view>

#include "util/version.h"

namespace rp::tools {

// If any argument is -version (so at any option position, whichever the tool's are:
// generators take theirs after the positional arguments), prints the version line; if
// argv[1] is -defaults and the tool passes its `defaults` (its option table's
// formatDefaults(), or for a generator its synopsis), prints them. Returns true when it printed
// (the tool then exits 0); false leaves the arguments to the tool.
inline bool printedInfo(int argc, char** argv, std::string_view defaults) {
    if (argc < 2) return false;
    bool version = false;
    for (int i = 1; i < argc; ++i) version = version || std::string_view(argv[i]) == "-version";
    const std::string_view a = argv[1];
    if (version) {
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
