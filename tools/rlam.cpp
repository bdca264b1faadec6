// rlam: RADIANCE's record laminator (see src/data/rlam.h).
//   rlam [-tS][-u][-iaN|-ifN|-idN|-iiN|-iwN|-ibN][-in M] input1 [options] input2 ..
#include "data/rlam.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/options.h"

namespace {

struct RlamArgs {
    rp::data::RlamState state;
    std::vector<rp::data::RlamInput> inputs;
    long limit = 0;
    bool unbuffered = false;
};

// Options and inputs mix: each option changes the settings of the inputs named after it.
rp::OptionTable rlamTable(RlamArgs& a) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.unknown = [](const std::string& opt) { return "bad option '" + opt + "'"; };
    t.add(rp::customOption(rp::prefix("-t"), "-t", [&a](rp::OptionReader& r) {
        a.state.setSeparator(r.option().substr(2));
    }));
    t.add(rp::customOption(rp::prefix("-u"), "-u",
                           [&a](rp::OptionReader&) { a.unbuffered = !a.unbuffered; }));
    t.add(rp::customOption(rp::prefix("-i"), "-i", [&a](rp::OptionReader& r) {
        const std::string format = r.option().substr(2);
        if (!format.empty() && format[0] == 'n')
            a.limit = std::atol(r.word().c_str());
        else
            a.state.setFormat(format);
    }));
    return t;
}

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-t\\t\t\t\t\t# separator before each input's record (-t alone: newline)\n"
    "-ia\t\t\t\t# one ASCII line per record (-iaN: N lines; -if -id -ii -iw -ibN: binary)\n"
    "-in 0\t\t\t\t# records (0: to the first input's end)\n"
    "-u-\t\t\t\t# output buffered\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    try {
        std::vector<std::string> args(argv, argv + argc);
        RlamArgs a;
        const rp::OptionTable table = rlamTable(a);
        for (std::size_t i = 1; i < args.size();) {
            i = table.parse(args, i).next;
            if (i >= args.size()) break;
            a.inputs.push_back({args[i], a.state.separator, a.state.recordBytes});
            ++i;
        }
        const rp::data::RlamResult r = rp::data::rlam(a.inputs, a.limit, a.unbuffered, stdout);
        if (r.premature) std::cerr << "rlam: warning: premature EOD\n";
        return 0;
    } catch (...) {
        std::fflush(stdout);
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "rlam: " << e.line << '\n';
        return e.exitCode;
    }
}
