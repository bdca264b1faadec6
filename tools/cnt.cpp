// cnt: RADIANCE's index counter (see src/data/cnt.h).
//   cnt N ..
#include "data/cnt.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/options.h"

// -defaults (tools/info_options.h).
constexpr const char* kDefaults = "cnt N ..\t\t\t# counters, the last turning fastest\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    try {
        std::vector<std::string> args(argv, argv + argc);
        std::vector<int> counts;
        // cnt has no options: a word such as "-2" is a (negative) count, read with atoi as
        // RADIANCE reads every argument.
        rp::OptionTable t;
        t.defaultsStops = false;
        t.add(rp::customOption(
            [](const std::string&) { return true; }, "N",
            [&counts](rp::OptionReader& r) { counts.push_back(std::atoi(r.option().c_str())); }));
        const std::size_t first = t.parse(args, 1).next;
        for (std::size_t i = first; i < args.size(); ++i)
            counts.push_back(std::atoi(args[i].c_str()));
        std::ios::sync_with_stdio(false);
        rp::data::writeCounts(counts, std::cout);
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "cnt: " << e.line << '\n';
        return e.exitCode;
    }
}
