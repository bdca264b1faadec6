// rcollate's command line (rcollate.h parseRcollateArgs), as RADIANCE rcollate.c main.
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "matrix/rcollate.h"
#include "util/error.h"
#include "util/header.h"

namespace rp::matrix {

namespace {

constexpr const char* kUsage =
    "Usage: rcollate [-h[io]][-w][-c][-f[afdb][N]][-t][-ic in_col][-ir in_row][-oc out_col]"
    "[-or out_row][-o RxC[xR1xC1..]] [input.dat]";
constexpr int kMaxLevels = 16;  // RADIANCE MAXLEVELS

InputError usage(const std::string& word) {
    return InputError("bad option '" + word + "'; " + kUsage);
}

// RADIANCE compat (get_array): "3x10X7x2" nests 7x2 blocks in a 3x10 array; each level's
// size is multiplied by the levels inside it.
std::vector<std::pair<int, int>> parseBlocks(const std::string& spec) {
    std::vector<std::pair<int, int>> levels;
    const char* s = spec.c_str();
    for (;;) {
        if (static_cast<int>(levels.size()) >= kMaxLevels)
            throw InputError("too many block levels in '" + spec + "'");
        int r, c;
        if (std::sscanf(s, "%dx%d", &r, &c) != 2)
            throw InputError("bad block specification '" + spec + "'");
        levels.push_back({r, c});
        while (std::isdigit(static_cast<unsigned char>(*s))) ++s;
        ++s;  // the 'x'
        while (std::isdigit(static_cast<unsigned char>(*s))) ++s;
        if (*s != 'x' && *s != 'X') {
            if (*s) throw InputError("blocks must be separated by 'x' or 'X' in '" + spec + "'");
            break;
        }
        ++s;
    }
    for (size_t i = levels.size() - 1; i-- > 0;) {
        levels[i].first *= levels[i + 1].first;
        levels[i].second *= levels[i + 1].second;
    }
    return levels;
}

}  // namespace

RcollateOptions parseRcollateArgs(int argc, const char* const* argv) {
    RcollateOptions o;
    int a = 1;
    auto value = [&](const std::string& w) -> int {
        if (a + 1 >= argc) throw InputError("missing value for option '" + w + "'");
        return std::atoi(argv[++a]);
    };
    for (; a < argc && argv[a][0] == '-'; ++a) {
        const std::string w = argv[a];
        const char c2 = w.size() > 2 ? w[2] : '\0';
        switch (w.size() > 1 ? w[1] : '\0') {
            case 'i':
                if (c2 == 'c')
                    o.inCols = value(w);
                else if (c2 == 'r')
                    o.inRows = value(w);
                else
                    throw usage(w);
                break;
            case 'o':
                if (c2 == 'c')
                    o.outCols = value(w);
                else if (c2 == 'r')
                    o.outRows = value(w);
                else if (c2 != '\0')
                    throw usage(w);
                else if (a + 1 >= argc)
                    throw InputError("missing value for option '-o'");
                else
                    o.blocks = parseBlocks(argv[++a]);
                break;
            case 'h':
                if (c2 == 'i')
                    o.inHeader = false;
                else if (c2 == 'o')
                    o.outHeader = false;
                else if (c2 == '\0')
                    o.inHeader = o.outHeader = false;
                else
                    throw usage(w);
                break;
            case 't':
                o.transpose = !o.transpose;
                break;
            case 'f': {
                const char t = static_cast<char>(std::tolower(static_cast<unsigned char>(c2)));
                if (t == 'a')
                    o.format = "ascii", o.componentSize = 0;
                else if (t == 'f')
                    o.format = "float", o.componentSize = 4;
                else if (t == 'd')
                    o.format = "double", o.componentSize = 8;
                else if (t == 'b')
                    o.format = "byte", o.componentSize = 1;
                else
                    throw usage(w);
                if (w.size() > 3 && !std::isdigit(static_cast<unsigned char>(w[3]))) throw usage(w);
                o.components = w.size() > 3 ? std::atoi(w.c_str() + 3) : 1;
                break;
            }
            case 'w':
                o.warnings = !o.warnings;
                break;
            case 'c':
                o.check = true;
                break;
            default:
                throw usage(w);
        }
    }
    if (a < argc - 1) throw InputError(std::string("more than one input file; ") + kUsage);
    if (a == argc - 1) o.input = argv[a];
    o.commandLine = commandLine(a, argv);
    if (!o.blocks.empty()) {
        o.outRows = o.blocks[0].first;
        o.outCols = o.blocks[0].second;
    }
    return o;
}

}  // namespace rp::matrix
