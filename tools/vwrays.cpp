// vwrays: the rays through the pixels of a view or picture (see src/rays/vwrays.h).
//   vwrays [ -i -u -f{a|f|d} -c rept | -d ] { view opts .. | picture [zbuf] }
#include "rays/vwrays.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/options.h"

namespace {

constexpr const char* kUsage =
    "usage: vwrays [ -i -u -f{a|f|d} -c rept | -d ] { view opts .. | picture [zbuf] }";

// RADIANCE's vwrays reads its numbers with atoi/atof; ours refuse junk.
rp::OptionTable vwraysTable(rp::rays::VwraysOptions& o, bool& dimensions) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.unknown = [](const std::string& opt) {
        return "bad option '" + opt + "'; " + kUsage;
    };
    t.add(rp::customOption(rp::prefix("-f"), "-f", [&o](rp::OptionReader& r) {
        const char c = r.option().c_str()[2];
        if (c != 'a' && c != 'f' && c != 'd')
            throw rp::InputError("bad option '" + r.option() + "'; " + kUsage);
        o.format = c;
    }));
    t.add(rp::viewOptionSpec(o.view));
    t.add(rp::customOption(rp::prefix("-d"), "-d",
                           [&dimensions](rp::OptionReader&) { dimensions = true; }));
    t.add(rp::customOption(rp::prefix("-x"), "-x", [&o](rp::OptionReader& r) {
        o.xres = int(r.integer());
        if (o.xres <= 0) throw rp::InputError("bad x resolution");
    }));
    t.add(rp::customOption(rp::prefix("-y"), "-y", [&o](rp::OptionReader& r) {
        o.yres = int(r.integer());
        if (o.yres <= 0) throw rp::InputError("bad y resolution");
    }));
    t.add(rp::customOption(rp::prefix("-c"), "-c",
                           [&o](rp::OptionReader& r) { o.repeat = int(r.integer()); }));
    t.add(rp::customOption(rp::prefix("-p"), "-p", [&o](rp::OptionReader& r) {
        const char c = r.option().c_str()[2];
        double* v = c == 'a'   ? &o.pixelAspect
                    : c == 'j' ? &o.jitter
                    : c == 'd' ? &o.aperture
                               : nullptr;
        if (!v) throw rp::InputError("bad option '" + r.option() + "'; " + kUsage);
        *v = r.real();
    }));
    t.add(
        rp::customOption(rp::prefix("-i"), "-i", [&o](rp::OptionReader&) { o.fromInput = true; }));
    t.add(
        rp::customOption(rp::prefix("-u"), "-u", [&o](rp::OptionReader&) { o.unbuffered = true; }));
    return t;
}

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-x 512\t\t\t\t# maximum x resolution\n"
    "-y 512\t\t\t\t# maximum y resolution\n"
    "-pa 1\t\t\t\t# pixel aspect (0: keep -x and -y)\n"
    "-pj 0\t\t\t\t# pixel jitter\n"
    "-pd 0\t\t\t\t# aperture diameter for depth of field\n"
    "-c 1\t\t\t\t# rays per pixel\n"
    "-fa\t\t\t\t# ASCII rays (-ff floats, -fd doubles)\n"
    "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    try {
        std::vector<std::string> args(argv, argv + argc);
        if (args.size() < 2) throw rp::InputError(kUsage);
        rp::rays::VwraysOptions o;
        bool dimensions = false;
        const std::size_t first = vwraysTable(o, dimensions).parse(args, 1).next;
        if (first + 2 < args.size()) throw rp::InputError(kUsage);
        if (first < args.size()) o.picture = args[first];
        if (first + 1 < args.size()) o.depthFile = args[first + 1];
        std::ios::sync_with_stdio(false);
        const rp::rays::Vwrays vwrays(o);
        if (dimensions) {
            std::cout << vwrays.dimensionsLine() << '\n';
        } else if (o.fromInput) {
            vwrays.writeFromInput(std::cin, std::cout);
        } else {
            vwrays.writeAll(std::cout);
        }
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "vwrays: " << e.line << '\n';
        return e.exitCode;
    }
}
