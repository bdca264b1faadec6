// epw2wea: an EnergyPlus weather file to a DAYSIM weather tape (see src/gen/epw.h).
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "gen/epw.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

namespace {

constexpr const char* kDefaults = "epw2wea file_name.epw file_name.wea\n";

void run(const std::vector<std::string>& args) {
    if (args.size() < 3)
        throw rp::InputError(
            "wrong number of arguments; start program with: epw2wea <file-name.epw> "
            "<file-name.wea>");
    // RADIANCE compat (epw2wea.c): words after the two files that start with '-' are
    // ignored; anything else is refused (RADIANCE says so on the standard output and
    // exits 0; we exit 1).
    for (size_t i = 3; i < args.size(); ++i)
        if (args[i].empty() || args[i][0] != '-')
            throw rp::InputError(args[i] + " bad option for input arguments");
    std::ifstream in(args[1], std::ios::binary);
    if (!in)
        throw rp::InputError("cannot open '" + args[1] + "' for input: " + std::strerror(errno));
    const rp::gen::EpwConversion c = rp::gen::epwToWea(in, args[1]);
    std::ofstream out(args[2], std::ios::binary);
    if (!out)
        throw rp::InputError("cannot open '" + args[2] + "' for output: " + std::strerror(errno));
    out << c.wea;
    out.flush();
    if (!out) throw rp::InputError("write error on '" + args[2] + "'");
    std::cout << c.console;
}

}  // namespace

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    try {
        run(std::vector<std::string>(argv, argv + argc));
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "epw2wea: " << e.line << '\n';
        return e.exitCode;
    }
    std::cout.flush();
    return std::cout ? 0 : 1;
}
