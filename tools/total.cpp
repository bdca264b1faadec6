// total: RADIANCE's column summer (see src/data/total.h).
//   total [-m][-sE|-p|-u|-l][-i{f|d}[N]][-o{f|d}][-in M][-on M][-tC][-N [-r]] [file ..]
#include "data/total.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/options.h"

namespace {

constexpr const char* kUsage =
    "usage: total [-m][-sE|p|u|l][-tC][-i{f|d}[N]][-o{f|d}][-count [-r]] [file..]";

rp::OptionTable totalTable(rp::data::TotalOptions& o) {
    using Func = rp::data::TotalOptions::Func;
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.unknown = [](const std::string& opt) {
        return "bad option '" + opt + "'; " + kUsage;
    };
    auto bad = [](const std::string& w) {
        return rp::InputError("bad option '" + w + "'; " + kUsage);
    };
    // -N: a result every N records (atoi, as RADIANCE).
    t.add(rp::customOption(
        [](const std::string& w) {
            return w.size() > 1 && std::isdigit(static_cast<unsigned char>(w[1]));
        },
        "-N", [&o](rp::OptionReader& r) { o.count = std::atoi(r.option().c_str() + 1); }));
    t.add(rp::customOption(rp::prefix("-m"), "-m", [&o](rp::OptionReader&) { o.mean = !o.mean; }));
    t.add(rp::customOption(rp::prefix("-p"), "-p",
                           [&o](rp::OptionReader&) { o.func = Func::Multiply; }));
    t.add(rp::customOption(rp::prefix("-s"), "-s", [&o](rp::OptionReader& r) {
        o.func = Func::Add;
        o.power = std::atof(r.option().c_str() + 2);
    }));
    t.add(
        rp::customOption(rp::prefix("-u"), "-u", [&o](rp::OptionReader&) { o.func = Func::Max; }));
    t.add(
        rp::customOption(rp::prefix("-l"), "-l", [&o](rp::OptionReader&) { o.func = Func::Min; }));
    t.add(rp::customOption(rp::prefix("-t"), "-t",
                           [&o](rp::OptionReader& r) { o.separator = r.option().c_str()[2]; }));
    t.add(rp::customOption(rp::prefix("-r"), "-r",
                           [&o](rp::OptionReader&) { o.subtotal = !o.subtotal; }));
    t.add(rp::customOption(rp::prefix("-i"), "-i", [&o, bad](rp::OptionReader& r) {
        const std::string w = r.option();
        const char c = w.c_str()[2];
        if (c == 'n') {
            o.inputLimit = std::atol(r.word().c_str());
        } else if (c == 'a') {
            o.binaryColumns = 0;
        } else if (c == 'd' || c == 'f') {
            const int n = w.size() > 3 && std::isdigit(static_cast<unsigned char>(w[3]))
                              ? std::atoi(w.c_str() + 3)
                              : 1;
            if (n > rp::data::kTotalMaxColumns) throw rp::InputError("too many input columns");
            o.binaryColumns = c == 'd' ? n : -n;
        } else {
            throw bad(w);
        }
    }));
    t.add(rp::customOption(rp::prefix("-o"), "-o", [&o, bad](rp::OptionReader& r) {
        const std::string w = r.option();
        const char c = w.c_str()[2];
        if (c == 'n')
            o.outputLimit = std::atol(r.word().c_str());
        else if (c == 'a')
            o.binaryOutput = 0;
        else if (c == 'd')
            o.binaryOutput = 1;
        else if (c == 'f')
            o.binaryOutput = -1;
        else
            throw bad(w);
    }));
    return t;
}

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-s0\t\t\t\t# plain sums (-sE: sums of |x|^E; -p products, -u maxima, -l minima)\n"
    "-m-\t\t\t\t# totals, not means\n"
    "-t\\t\t\t\t\t# column separator\n"
    "-ia\t\t\t\t# ASCII input\n"
    "-oa\t\t\t\t# ASCII output\n"
    "-r-\t\t\t\t# reset after each result\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    int status = 0;
    try {
        using Func = rp::data::TotalOptions::Func;
        std::vector<std::string> args(argv, argv + argc);
        rp::data::TotalOptions o;
        const std::size_t first = totalTable(o).parse(args, 1).next;
        if (o.mean && o.func == Func::Max) throw rp::InputError("average maximum?!");
        if (o.mean && o.func == Func::Min) throw rp::InputError("average minimum?!");
        std::ios::sync_with_stdio(false);
        rp::data::Total total(o);
        if (first == args.size()) {
            total.run(std::cin, std::cout);
        } else {
            for (std::size_t i = first; i < args.size() && !total.done(); ++i) {
                std::ifstream in(args[i], std::ios::binary);
                if (!in) {  // RADIANCE compat: reported, the other files still read
                    std::cout.flush();
                    std::cerr << "total: " << args[i] << ": cannot open\n";
                    status = 2;
                    continue;
                }
                total.run(in, std::cout);
            }
        }
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        return status;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "total: " << e.line << '\n';
        return e.exitCode;
    }
}
