// ra_png: convert a RADIANCE picture to an 8-bit sRGB PNG for viewing
// (see src/image/tonemap.h for the exposure and encoding rules).
//   ra_png [-e exposure|+/-stops] [-g gamma] input.hdr|- output.png
// Without -e the log-average brightness is mapped to mid grey (0.18); without -g the
// sRGB transfer curve is used.
#include <cstdlib>
#include <iostream>
#include <string>

#include "image/tonemap.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

namespace {
constexpr const char* kUsage =
    "usage: ra_png [-e exposure|+/-stops] [-g gamma] input.hdr|- output.png";
}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-e  auto\t\t\t# exposure: log-average brightness to mid grey\n"
    "-g  sRGB\t\t\t# gamma: the sRGB transfer curve\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    rp::DisplayOptions opt;
    std::string files[2];
    int nfiles = 0;
    try {
        for (int i = 1; i < argc; ++i) {
            std::string a = argv[i];
            if ((a == "-e" || a == "-g") && i + 1 < argc) {
                std::string v = argv[++i];
                if (a == "-e") {
                    opt.exposure = rp::parseExposureArg(v);
                } else {
                    char* end;
                    double g = std::strtod(v.c_str(), &end);
                    if (v.empty() || *end || !(g > 0))
                        throw rp::InputError("-g: bad gamma '" + v + "'");
                    opt.gamma = g;
                }
            } else if (a.size() > 1 && a[0] == '-') {
                throw rp::InputError("unknown option '" + a + "' (" + kUsage + ")");
            } else if (nfiles < 2) {
                files[nfiles++] = a;
            } else {
                throw rp::InputError(kUsage);
            }
        }
        if (nfiles != 2) throw rp::InputError(kUsage);
        rp::convertPictureToPng(files[0], files[1], opt);
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "ra_png: " << e.line << '\n';
        return e.exitCode;
    }
}
