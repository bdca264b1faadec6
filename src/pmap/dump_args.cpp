// pmapdump command line: option groups that apply to the photon map file following them
// and are reset after it (photon-map manual section 7; RADIANCE pmapdump.c main loop).
#include <array>

#include "pmap/dump.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/options.h"

namespace rp::pmap {
namespace {

// RADIANCE compat: setBool() in pmapdump.c: a bare switch toggles, y/t/+/1 set, n/f/-/0
// clear (boolSuffix). Unlike RADIANCE we also reject trailing characters ("-a+x").
OptionSpec dumpFlag(const std::string& name, bool& var) {
    return customOption(prefix(name), name, [&var](OptionReader& r) {
        try {
            var = boolSuffix(r.option(), 2, var);
        } catch (const InputError&) {
            throw InputError("invalid option syntax at " + r.option());
        }
    });
}

// The value after -n/-r/-c, or "option -n needs a count".
const std::string& value(OptionReader& r, const char* what) {
    if (!r.hasNext()) throw InputError("option " + r.option() + " needs " + what);
    return r.word();
}

// The options of one group, bound to `o` (the group of the next map file).
OptionTable dumpTable(DumpOptions& o) {
    OptionTable t;
    t.messages.unknown = [](const std::string& opt) { return "unknown option " + opt; };
    t.defaultsStops = false;  // -defaults is tools/info_options.h's, at argv[1] only
    t.add(dumpFlag("-a", o.ascii));
    t.add(dumpFlag("-P", o.ply));
    t.add(dumpFlag("-f", o.fluxColour));
    t.add(customOption("-n", [&o](OptionReader& r) {
        const std::string& v = value(r, "a count");
        const auto n = parseCount(v);
        if (!n)
            throw InputError("invalid number of points/spheres '" + v +
                             "' for -n (expected a positive count, e.g. 5000, 10k, 1M)");
        o.num = *n;
    }));
    t.add(customOption("-r", [&o](OptionReader& r) {
        const std::string& v = value(r, "a radius scale");
        const auto x = parseReal(v);
        if (!x || *x <= 0)
            throw InputError("invalid radius scale '" + v + "' for -r (must be > 0)");
        o.radScale = *x;
    }));
    t.add(customOption("-c", [&o](OptionReader& r) {
        std::array<float, 3> c{};
        double sum = 0;
        for (int i = 0; i < 3; ++i) {
            const std::string& v = value(r, "3 colour components (r g b)");
            const auto x = parseReal(v);
            if (!x || *x < 0) throw InputError("invalid RGB colour component '" + v + "' for -c");
            c[size_t(i)] = static_cast<float>(*x);
            sum += *x;
        }
        // RADIANCE treats a colour of zero intensity as "no -c given"; we reject it.
        if (!(sum > 0)) throw InputError("invalid RGB colour for -c (all components 0)");
        o.colour = c;
    }));
    return t;
}

}  // namespace

std::vector<DumpRequest> parseDumpArgs(int argc, const char* const* argv) {
    std::vector<DumpRequest> requests;
    DumpOptions current;
    std::string pending;  // options seen since the last map, for the trailing-options error
    std::vector<std::string> args = argVector(argc, argv);
    const OptionTable table = dumpTable(current);
    for (size_t i = 1; i < args.size();) {
        const size_t next = table.parse(args, i).next;
        for (; i < next; ++i)
            if (args[i].size() >= 2 && args[i][0] == '-')
                pending += pending.empty() ? args[i] : " " + args[i];
        if (i >= args.size()) break;
        const std::string& arg = args[i++];
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
