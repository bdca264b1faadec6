// pcond: condition a RADIANCE picture for display, mimicking human visual response
// (see src/image/pcond.h).
//   pcond [-{h|a|v|s|c|l|w}[+-]][-I|-i ffrac][-e ev][-p xr yr xg yg xb yb xw yw|-f mbf.cal]
//         [-u Ldmax][-d Lddyn][-x mapfile] inpic [outpic]
#include "image/pcond.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/header.h"

namespace {

// RADIANCE compat: files pcond cannot open are system errors (syserror: exit 2).
int systemError(const std::string& file) {
    std::cerr << "pcond: " << file << ": " << std::strerror(errno) << '\n';
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    rp::PcondOptions defaults;
    if (rp::tools::printedInfo(argc, argv, rp::pcondTable(defaults).formatDefaults())) return 0;
    try {
        std::vector<std::string> args(argv + 1, argv + argc);
        const rp::PcondOptions opt = rp::parsePcondArgs(args);
        std::ofstream map;
        if (!opt.mapFile.empty()) {
            map.open(opt.mapFile);
            if (!map)
                throw rp::InputError(rp::SourceLoc{opt.mapFile, 0}, "cannot open for writing");
        }
        std::ifstream in(opt.inputFile, std::ios::binary);
        if (!in) return systemError(opt.inputFile);
        std::ofstream file;
        if (!opt.outputFile.empty()) {
            file.open(opt.outputFile, std::ios::binary);
            if (!file) return systemError(opt.outputFile);
        }
        if (!opt.macbethFile.empty() && !std::ifstream(opt.macbethFile))
            return systemError(opt.macbethFile);
        std::ostream& out = opt.outputFile.empty() ? std::cout : file;
        std::ios::sync_with_stdio(false);
        // RADIANCE records every argument, the file names too.
        const std::string history = rp::commandLine(argc, argv);
        rp::runPcond(in, opt.inputFile, opt, history, out, &std::cin,
                     opt.mapFile.empty() ? nullptr : &map);
        out.flush();
        if (!out) throw rp::InputError("error writing the output picture");
        if (map.is_open() && !map.flush()) throw rp::InputError("error writing " + opt.mapFile);
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "pcond: " << e.line << '\n';
        return e.exitCode;
    }
}
