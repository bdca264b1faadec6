// pmapdump command line: option groups that apply to the photon map file following them
// and are reset after it (photon-map manual section 7; RADIANCE pmapdump.c main loop).
#include <cmath>
#include <cstdlib>

#include "pmap/dump.h"
#include "pmap/mkpmap_options.h"
#include "util/error.h"

namespace rp::pmap {
namespace {

// RADIANCE compat: setBool() in pmapdump.c: a bare switch toggles, y/t/+/1 set, n/f/-/0
// clear. Unlike RADIANCE we also reject trailing characters ("-a+x").
bool setBool(const std::string& opt, bool& var) {
    if (opt.size() == 2) {
        var = !var;
        return true;
    }
    if (opt.size() != 3) return false;
    switch (opt[2]) {
        case 'y':
        case 'Y':
        case 't':
        case 'T':
        case '+':
        case '1':
            var = true;
            return true;
        case 'n':
        case 'N':
        case 'f':
        case 'F':
        case '-':
        case '0':
            var = false;
            return true;
        default:
            return false;
    }
}

std::optional<double> parseReal(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (*end != '\0' || !std::isfinite(v)) return std::nullopt;
    return v;
}

class ArgReader {
public:
    ArgReader(int argc, const char* const* argv) : argc_(argc), argv_(argv) {}
    bool done() const { return i_ >= argc_; }
    std::string next() { return argv_[i_++]; }
    std::string value(const std::string& opt, const char* what) {
        if (done()) throw InputError("option " + opt + " needs " + what);
        return next();
    }

private:
    int argc_;
    const char* const* argv_;
    int i_ = 1;
};

void parseOption(const std::string& opt, ArgReader& args, DumpOptions& o) {
    const char letter = opt[1];
    const bool bare = opt.size() == 2;
    auto badSyntax = [&] { return InputError("invalid option syntax at " + opt); };
    switch (letter) {
        case 'a':
            if (!setBool(opt, o.ascii)) throw badSyntax();
            return;
        case 'P':
            if (!setBool(opt, o.ply)) throw badSyntax();
            return;
        case 'f':
            if (!setBool(opt, o.fluxColour)) throw badSyntax();
            return;
        case 'n': {
            if (!bare) break;
            const std::string v = args.value(opt, "a count");
            const auto n = parsePhotonCount(v);
            if (!n)
                throw InputError("invalid number of points/spheres '" + v +
                                 "' for -n (expected a positive count, e.g. 5000, 10k, 1M)");
            o.num = *n;
            return;
        }
        case 'r': {
            if (!bare) break;
            const std::string v = args.value(opt, "a radius scale");
            const auto r = parseReal(v);
            if (!r || *r <= 0)
                throw InputError("invalid radius scale '" + v + "' for -r (must be > 0)");
            o.radScale = *r;
            return;
        }
        case 'c': {
            if (!bare) break;
            std::array<float, 3> c{};
            double sum = 0;
            for (int i = 0; i < 3; ++i) {
                const std::string v = args.value(opt, "3 colour components (r g b)");
                const auto x = parseReal(v);
                if (!x || *x < 0)
                    throw InputError("invalid RGB colour component '" + v + "' for -c");
                c[size_t(i)] = static_cast<float>(*x);
                sum += *x;
            }
            // RADIANCE treats a colour of zero intensity as "no -c given"; we reject it.
            if (!(sum > 0)) throw InputError("invalid RGB colour for -c (all components 0)");
            o.colour = c;
            return;
        }
        default:
            break;
    }
    throw InputError("unknown option " + opt);
}

}  // namespace

std::vector<DumpRequest> parseDumpArgs(int argc, const char* const* argv) {
    std::vector<DumpRequest> requests;
    DumpOptions current;
    std::string pending;  // options seen since the last map, for the trailing-options error
    ArgReader args(argc, argv);
    while (!args.done()) {
        const std::string arg = args.next();
        if (arg.size() >= 2 && arg[0] == '-') {
            parseOption(arg, args, current);
            pending += pending.empty() ? arg : " " + arg;
            continue;
        }
        if (arg.empty() || arg == "-")
            throw InputError("invalid photon map file name '" + arg + "'");
        // RADIANCE compat: -c and -f are mutually exclusive (pmapdump.c checks them in
        // command-line order; we check the final group so "-f -f- -c" is fine).
        if (current.fluxColour && current.colour)
            throw InputError(SourceLoc{arg, 0}, "-c and -f are mutually exclusive");
        requests.push_back({arg, current});
        current = DumpOptions{};  // manual section 7: options reset after each map
        pending.clear();
    }
    if (!pending.empty())
        throw InputError("options after the last photon map apply to no map: " + pending);
    if (requests.empty()) throw InputError("no photon map file given");

    // A PLY file needs the vertex count up front and cannot hold scene text or other point
    // lists, so -P is all or nothing.
    size_t numPly = 0;
    for (const DumpRequest& r : requests) numPly += r.options.ply ? 1 : 0;
    if (numPly > 0 && numPly < requests.size())
        for (const DumpRequest& r : requests)
            if (!r.options.ply)
                throw InputError(SourceLoc{r.path, 0},
                                 "-P given for other photon maps but not for this one; a PLY "
                                 "file cannot hold other output, so use -P for every map");
    return requests;
}

}  // namespace rp::pmap
