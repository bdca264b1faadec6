// rfluxmtx's command line (see rfluxmtx.h): RADIANCE rfluxmtx.c main's option screen.
#include <cstdlib>
#include <cstring>

#include "flux/rfluxmtx.h"
#include "util/command_args.h"
#include "util/error.h"

namespace rp::flux {

namespace {

// What rfluxmtx keeps for itself while screening.
struct Screen {
    std::string format = "-faa";  // rcontrib's -f[io]; input becomes d with a sender
    std::string xres, yres, ld, irradiance;
};

// How many words (option included) an option passes on to rcontrib; 0 when rfluxmtx
// keeps it, -1 when rfluxmtx refuses it (rfluxmtx.c main: "keep consistent" with
// rcontrib's options).
int passedWords(const std::vector<std::string>& args, size_t& a, RfluxmtxCommand& cmd, Screen& sc) {
    const std::string& o = args[a];
    const char c2 = o.size() > 2 ? o[2] : '\0';
    auto value = [&](std::string& into) {
        if (a + 1 >= args.size()) return -1;
        into = args[++a];
        return 0;
    };
    switch (o[1]) {
        case 'v':
            cmd.verbose = true;
            return 0;
        case 'f':
            if (c2 != 'a' && c2 != 'f' && c2 != 'd' && c2 != 'c') return -1;
            sc.format = std::string("-f") + c2 + (o.size() > 3 ? o[3] : c2);
            return 0;
        case 'x':
            return value(sc.xres);
        case 'y':
            return value(sc.yres);
        case 'c': {
            std::string n;
            if (value(n) < 0) return -1;
            cmd.samples = std::atoi(n.c_str());
            return cmd.samples > 0 ? 0 : -1;
        }
        case 'I':
        case 'i':
            sc.irradiance = o;
            return 0;
        case 'w':
            if (!c2 || !std::strchr("+1tTyY", c2)) cmd.warnings = false;
            return 1;
        case 'V':
        case 'u':
        case 'h':
        case 'r':
            return 1;
        case 'n':
        case 's':
        case 'o':
        case 't':
            return 2;
        case 'b':
            return c2 == 'v' ? 1 : -1;
        case 'l':
            if (c2 == 'd') {
                sc.ld = o;
                return 0;
            }
            return 2;
        case 'd':
            return c2 == 'v' ? 1 : 2;
        case 'a':
            if (c2 == 'p') {
                // -ap file [bandwidth [bandwidth]]: the bandwidths are the numbers that
                // follow, leaving sender and receiver.
                int n = 2;
                if (a + 3 < args.size() && std::atoi(args[a + 2].c_str()) > 0)
                    n += 1 + (a + 4 < args.size() && std::atoi(args[a + 3].c_str()) > 0);
                return n;
            }
            return c2 == 'v' ? 4 : 2;
        case 'm':
            if (!c2) return -1;
            return c2 == 'e' || c2 == 'a' ? 4 : 2;
        default:
            return -1;
    }
}

InputError usageError(const std::vector<std::string>& args, size_t a) {
    std::string m;
    if (a + 2 < args.size()) m = "unsupported option '" + args[a] + "'; ";
    return InputError(m + rfluxmtxUsage("rfluxmtx"));
}

}  // namespace

std::string rfluxmtxUsage(const std::string& program) {
    return "Usage: " + program +
           " [-v][rcontrib options] sender.rad receiver.rad [-i system.oct] [system.rad ..]";
}

RfluxmtxCommand parseRfluxmtxArgs(std::vector<std::string> args) {
    RfluxmtxCommand cmd;
    cmd.rcontribArgs = {"rcontrib", "-fo+"};
    Screen sc;
    size_t a = 1;
    for (; a + 2 < args.size(); ++a) {
        expandArgAt(args, a);
        if (a + 2 >= args.size()) break;
        const std::string& o = args[a];
        if (o.size() < 2 || o[0] != '-') break;
        const size_t at = a;  // RADIANCE names the value of -c here, not -c
        const int n = passedWords(args, a, cmd, sc);
        if (n < 0 || a + size_t(n) > args.size()) throw usageError(args, at);
        for (int k = 0; k < n; ++k) cmd.rcontribArgs.push_back(args[a + size_t(k)]);
        if (n > 0) a += size_t(n - 1);
    }
    if (a + 2 > args.size()) throw usageError(args, a);
    const std::string sender = args[a++];
    if (sender[0] == '-') {
        if (sender.size() > 1) throw usageError(args, a - 1);
        std::vector<std::string>& rc = cmd.rcontribArgs;
        if (!sc.irradiance.empty()) rc.push_back(sc.irradiance);
        if (!sc.xres.empty()) rc.insert(rc.end(), {"-x", sc.xres});
        if (!sc.yres.empty()) rc.insert(rc.end(), {"-y", sc.yres});
        if (!sc.ld.empty()) rc.push_back(sc.ld);
        if (cmd.samples <= 0) cmd.samples = 1;
    } else {
        if (!sc.irradiance.empty()) throw InputError("-i, -I supported for pass-through only");
        cmd.senderFile = sender;
        sc.format[2] = 'd';  // the generated rays go in as doubles
        if (cmd.samples <= 0) cmd.samples = 10000;
    }
    cmd.rcontribArgs.insert(cmd.rcontribArgs.end(), {sc.format, "-c", std::to_string(cmd.samples)});
    cmd.receiverFile = args[a++];
    cmd.systemArgs.assign(args.begin() + long(a), args.end());
    return cmd;
}

}  // namespace rp::flux
