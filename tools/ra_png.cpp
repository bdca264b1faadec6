// ra_png: convert a RADIANCE picture to an 8-bit sRGB PNG for viewing
// (see src/image/tonemap.h for the exposure and encoding rules).
//   ra_png [-e exposure|+/-stops] [-g gamma] input.hdr|- output.png
// Without -e the log-average brightness is mapped to mid grey (0.18); without -g the
// sRGB transfer curve is used.
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "image/tonemap.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/options.h"

namespace {
constexpr const char* kUsage =
    "usage: ra_png [-e exposure|+/-stops] [-g gamma] input.hdr|- output.png";
// ra_png's options (util/options.h); a malformed one is reported with the usage.
rp::OptionTable raPngTable(rp::DisplayOptions& opt) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.unknown = [](const std::string& a) {
        return "unknown option '" + a + "' (" + kUsage + ")";
    };
    t.messages.missing = t.messages.unknown;
    // Without -e or -g the picture decides (tonemap.h): the -defaults lines say how.
    t.add(rp::customOption(
              "-e", [&opt](rp::OptionReader& r) { opt.exposure = rp::parseExposureArg(r.word()); }),
          [] {
              return std::string("-e  auto\t\t\t# exposure: log-average brightness to mid grey\n");
          });
    t.add(rp::customOption("-g",
                           [&opt](rp::OptionReader& r) {
                               const std::string& v = r.word();
                               const std::optional<double> g = rp::parseReal(v);
                               if (!g || !(*g > 0))
                                   throw rp::InputError("-g: bad gamma '" + v + "'");
                               opt.gamma = *g;
                           }),
          [] { return std::string("-g  sRGB\t\t\t# gamma: the sRGB transfer curve\n"); });
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    rp::DisplayOptions opt;
    if (rp::tools::printedInfo(argc, argv, raPngTable(opt).formatDefaults())) return 0;
    std::string files[2];
    int nfiles = 0;
    try {
        // Options may stand anywhere among the two file names.
        std::vector<std::string> args(argv, argv + argc);
        const rp::OptionTable table = raPngTable(opt);
        for (size_t i = table.parse(args, 1).next; i < args.size();
             i = table.parse(args, i + 1).next) {
            if (nfiles == 2) throw rp::InputError(kUsage);
            files[nfiles++] = args[i];
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
