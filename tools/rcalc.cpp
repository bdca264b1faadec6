// rcalc: RADIANCE's record calculator (see src/calc/rcalc.h).
//   rcalc [-b][-l][-n][-p][-w][-u][-tS][-s svar=sval][-e expr][-f source][-i infmt]
//         [-o outfmt][-in M][-on M] [file ..]
#include "calc/rcalc.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"
#include "util/options.h"
#include "util/paths.h"

namespace {

constexpr const char* kUsage =
    "usage: rcalc [-b][-l][-n][-p][-w][-u][-tS][-s svar=sval][-e expr][-f source][-i infmt]"
    "[-o outfmt] [file]";

// RADIANCE reads the count after -id/-if with atoi (no digits: 1).
int binaryCount(const std::string& word) {
    return word.size() > 3 && std::isdigit(static_cast<unsigned char>(word[3]))
               ? std::atoi(word.c_str() + 3)
               : 1;
}

rp::OptionTable rcalcTable(rp::calc::RcalcOptions& o) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.unknown = [](const std::string& opt) {
        return "bad option '" + opt + "'; " + kUsage;
    };
    auto flag = [&t](const char* name, bool& v) {
        t.add(rp::customOption(rp::prefix(name), name, [&v](rp::OptionReader&) { v = !v; }));
    };
    flag("-b", o.blanksEqual);
    flag("-l", o.ignoreEol);
    flag("-p", o.passive);
    flag("-w", o.noWarnings);
    flag("-u", o.flush);
    t.add(rp::customOption(rp::prefix("-n"), "-n", [&o](rp::OptionReader&) { o.noInput = true; }));
    t.add(rp::customOption(rp::prefix("-t"), "-t",
                           [&o](rp::OptionReader& r) { o.separator = r.option().c_str()[2]; }));
    t.add(rp::customOption(rp::prefix("-s"), "-s",
                           [&o](rp::OptionReader& r) { o.presets.push_back(r.word()); }));
    t.add(rp::customOption(rp::prefix("-f"), "-f",
                           [&o](rp::OptionReader& r) { o.sources.emplace_back(true, r.word()); }));
    t.add(rp::customOption(rp::prefix("-e"), "-e",
                           [&o](rp::OptionReader& r) { o.sources.emplace_back(false, r.word()); }));
    t.add(rp::customOption(rp::prefix("-i"), "-i", [&o](rp::OptionReader& r) {
        const std::string w = r.option();
        const char c = w.c_str()[2];
        if (c == '\0') {
            o.inputType = 'a';
            o.binaryColumns = 0;
            o.inputFormat = rp::calc::recordFormatText(r.word());
            o.inputFormatIgnoreEol = o.ignoreEol;
            o.hasInputFormat = true;
        } else if (c == 'n') {
            o.inputLimit = std::atol(r.word().c_str());
        } else if (c == 'a') {
            o.inputType = 'a';
            o.binaryColumns = 0;
        } else if (c == 'd' || c == 'D' || c == 'f' || c == 'F') {
            o.inputType = c;
            o.binaryColumns = binaryCount(w);
            const std::size_t size = c == 'd' || c == 'D' ? sizeof(double) : sizeof(float);
            if (o.binaryColumns * size > 16384) throw rp::InputError("too many input columns");
        } else {
            throw rp::InputError("bad option '" + w + "'; " + kUsage);
        }
    }));
    t.add(rp::customOption(rp::prefix("-o"), "-o", [&o](rp::OptionReader& r) {
        const std::string w = r.option();
        const char c = w.c_str()[2];
        if (c == '\0') {
            o.outputType = 'a';
            o.outputFormat = rp::calc::recordFormatText(r.word());
            o.outputFormatIgnoreEol = o.ignoreEol;
            o.hasOutputFormat = true;
        } else if (c == 'n') {
            o.outputLimit = std::atol(r.word().c_str());
        } else if (c == 'a' || c == 'd' || c == 'D' || c == 'f' || c == 'F') {
            o.outputType = c;
        } else {
            throw rp::InputError("bad option '" + w + "'; " + kUsage);
        }
    }));
    return t;
}

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-b+\t\t\t\t# blanks compare equal (-b: exact matches only)\n"
    "-l-\t\t\t\t# newlines end records\n"
    "-p-\t\t\t\t# unmatched input dropped\n"
    "-t\\t\t\t\t\t# column separator\n"
    "-ia\t\t\t\t# ASCII input records\n"
    "-oa\t\t\t\t# ASCII output records\n"
    "-w-\t\t\t\t# warnings on\n"
    "-u-\t\t\t\t# output buffered\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    try {
        std::vector<std::string> args(argv, argv + argc);
        rp::calc::RcalcOptions o;
        const std::size_t first = rcalcTable(o).parse(args, 1).next;
        std::ios::sync_with_stdio(false);
        if (o.noInput && first < args.size())
            throw rp::InputError("file argument(s) incompatible with -n");
        rp::calc::Rcalc rcalc(o, rp::calc::defaultSearchPath(rp::projectLibDir()));
        if (o.noInput) {
            rcalc.runNoInput(std::cout);
        } else if (first == args.size()) {
            rcalc.run(std::cin, "standard input", std::cout);
        } else {
            for (std::size_t i = first; i < args.size(); ++i) {
                std::ifstream in(args[i], std::ios::binary);
                if (!in) throw rp::InputError(args[i] + ": cannot open");
                rcalc.run(in, args[i], std::cout);
            }
        }
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing standard output");
        if (rcalc.mathErrors() && !o.noWarnings)
            std::cerr << "rcalc: warning: " << rcalc.mathErrors()
                      << " division(s) by zero or bad function argument(s), each gave 0\n";
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "rcalc: " << e.line << '\n';
        return e.exitCode;
    }
}
