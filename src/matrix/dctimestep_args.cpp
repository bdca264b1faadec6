// dctimestep's command line and file-name patterns (dctimestep.h), as RADIANCE
// dctimestep.c main and hasNumberFormat.
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "matrix/dctimestep.h"
#include "util/error.h"
#include "util/header.h"

namespace rp::matrix {

namespace {

constexpr const char* kUsage =
    "Usage: dctimestep [-n nsteps][-o ospec][-i{f|d|h}][-o{f|d|c}] DCspec [skyf]"
    " or dctimestep [-n nsteps][-o ospec][-i{f|d|h}][-o{f|d|c}] Vspec Tbsdf Dmat.dat [skyf]";

InputError usage(const std::string& why) { return InputError(why + "; " + kUsage); }

}  // namespace

DctimestepOptions parseDctimestepArgs(int argc, const char* const* argv) {
    DctimestepOptions o;
    int a = 1;
    for (; a < argc && argv[a][0] == '-'; ++a) {
        const std::string w = argv[a];
        const char c2 = w.size() > 2 ? w[2] : '\0';
        auto value = [&]() -> std::string {
            if (a + 1 >= argc) throw usage("missing value for option '" + w + "'");
            return argv[++a];
        };
        switch (w.size() > 1 ? w[1] : '\0') {
            case 'n':
                o.steps = std::atoi(value().c_str());
                if (o.steps < 0) throw usage("bad value for -n");
                o.skyType = o.steps ? DataType::Ascii : DataType::FromHeader;
                break;
            case 'h':
                o.header = !o.header;
                break;
            case 'i':
                if (c2 == 'f')
                    o.skyType = DataType::Float;
                else if (c2 == 'd')
                    o.skyType = DataType::Double;
                else if (c2 == 'a')
                    o.skyType = DataType::Ascii;
                else
                    throw usage("bad option '" + w + "'");
                break;
            case 'o':
                if (c2 == '\0')
                    o.outputSpec = value();
                else if (c2 == 'f')
                    o.outputType = DataType::Float;
                else if (c2 == 'd')
                    o.outputType = DataType::Double;
                else if (c2 == 'a')
                    o.outputType = DataType::Ascii;
                else if (c2 == 'c')
                    o.outputType = DataType::Rgbe;
                else
                    throw usage("bad option '" + w + "'");
                break;
            default:
                throw usage("bad option '" + w + "'");
        }
    }
    if (argc - a < 1 || argc - a > 4) throw usage("expected 1 to 4 matrix arguments");
    o.inputs.assign(argv + a, argv + argc);
    o.commandLine = commandLine(argc, argv);
    return o;
}

bool hasNumberFormat(const std::string& s) {
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '%') continue;
        if (i + 1 < s.size() && s[i + 1] == '%') {
            ++i;
            continue;
        }
        size_t j = i + 1;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
        if (j < s.size() && std::string("dioxX").find(s[j]) != std::string::npos) return true;
        i = j - 1;
    }
    return false;
}

std::string formatNumber(const std::string& spec, int n) {
    std::string out;
    for (size_t i = 0; i < spec.size(); ++i) {
        if (spec[i] != '%') {
            out += spec[i];
            continue;
        }
        size_t j = i + 1;
        while (j < spec.size() && std::isdigit(static_cast<unsigned char>(spec[j]))) ++j;
        if (j < spec.size() && spec[j] == '%' && j == i + 1) {
            out += '%';
        } else if (j < spec.size() && std::string("dioxX").find(spec[j]) != std::string::npos) {
            char buf[64];
            const std::string f = spec.substr(i, j - i + 1);
            std::snprintf(buf, sizeof buf, f.c_str(), n);
            out += buf;
        } else {
            throw InputError("bad file name pattern '" + spec + "' (only %d-like conversions)");
        }
        i = j;
    }
    return out;
}

}  // namespace rp::matrix
