// gendaymtx: a Perez sky matrix from a weather tape (see src/gen/gendaymtx.h).
#include "gen/gendaymtx.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "util/error.h"

namespace {

constexpr const char* kDefaults =
    "gendaymtx [-v][-h][-A][-d|-s|-n][-u][-D file [-M modfile]][-r deg][-m N][-g r g b]"
    "[-c r g b][-o{f|d}][-O{0|1}][-5 deg] [tape.wea]\n";

std::unique_ptr<std::ofstream> openOutput(const std::string& path) {
    auto f = std::make_unique<std::ofstream>(path, std::ios::binary);
    if (!*f) throw rp::InputError("cannot open '" + path + "' for output");
    return f;
}

void run(const std::vector<std::string>& args) {
    using namespace rp::gen;
    GendaymtxOptions opt = parseGendaymtxArgs(args);
    std::ifstream file;
    if (!opt.input.empty()) {
        file.open(opt.input, std::ios::binary);
        if (!file)
            throw rp::InputError("cannot open '" + opt.input +
                                 "' for input: " + std::strerror(errno));
    }
    const std::string name = opt.input.empty() ? "<stdin>" : opt.input;
    WeaTape tape = readWea(opt.input.empty() ? std::cin : file, name);
    std::unique_ptr<std::ofstream> suns, modifiers;
    GendaymtxOutputs out;
    out.matrix = &std::cout;
    if (opt.sunFile == "-") {
        out.suns = &std::cout;
    } else if (!opt.sunFile.empty()) {
        suns = openOutput(opt.sunFile);
        out.suns = suns.get();
    }
    if (!opt.modifierFile.empty()) {
        modifiers = openOutput(opt.modifierFile);
        if (out.suns) out.modifiers = modifiers.get();
    }
    out.note = [](const std::string& s) { std::cerr << "gendaymtx: " << s << '\n'; };
    runGendaymtx(opt, tape, name, args, out);
    for (std::ofstream* f : {suns.get(), modifiers.get()})
        if (f && !f->flush()) throw rp::InputError("write error on output file");
}

}  // namespace

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<std::string> args(argv, argv + argc);
    args[0] = "gendaymtx";  // RADIANCE prints argv[0]; a fixed name keeps output path-independent
    std::ios::sync_with_stdio(false);
    try {
        run(args);
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "gendaymtx: " << e.line << '\n';
        return e.exitCode;
    }
    std::cout.flush();
    if (!std::cout) {
        std::cerr << "gendaymtx: write error on output\n";
        return 1;
    }
    return 0;
}
