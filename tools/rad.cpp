// rad: RADIANCE's executive for oconv, mkillum, mkpmap, rpict, rvu and pfilt (see
// src/rad/rad_run.h).
//   rad [-w][-s][-n|-N npr][-t][-e][-V][-v view][-o dev] rfile [VAR=value ..]
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "rad/rad_run.h"
#include "util/warnings.h"

namespace {

// The commands rad runs find radphoton's tools first: the folder of this program goes
// ahead of PATH (a RADIANCE installation later on PATH is not mixed in).
void putOwnFolderFirstOnPath() {
    std::vector<char> buf(4096);
    const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0) return;
    std::string self(buf.data(), std::size_t(n));
    const std::size_t slash = self.rfind('/');
    if (slash == std::string::npos) return;
    const char* path = std::getenv("PATH");
    const std::string value = self.substr(0, slash) + (path ? ":" + std::string(path) : "");
    ::setenv("PATH", value.c_str(), 1);
}

}  // namespace

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, std::string("rad ") + rp::rad::radUsage() + "\n"))
        return 0;
    try {
        const rp::rad::RadCommand cmd =
            rp::rad::parseRadArgs(std::vector<std::string>(argv + 1, argv + argc));
        rp::setWarningSink(
            [](const std::string& m) { std::cerr << "rad: warning - " << m << '\n'; });
        putOwnFolderFirstOnPath();
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
