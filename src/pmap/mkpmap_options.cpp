// mkpmap command-line parsing (RADIANCE mkpmap.c main, mkpmap.1). Option semantics are
// RADIANCE's; messages are ours, one line each.
#include <unistd.h>

#include <climits>
#include <cstdio>

#include "calc/search_path.h"
#include "pmap/mkpmap.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/options.h"
#include "util/paths.h"

namespace rp::pmap {

uint64_t defaultMemoryPhotons() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return uint64_t{1} << 27;  // unknown: 3 GB of photons
    return uint64_t(pages) / 2 * uint64_t(pageSize) / sizeof(Photon);
}

namespace {

// The words of a modifier list file, found along RAYPATH (RADIANCE mkpmap.c: wordfile on
// getpath).
std::vector<std::string> readWordFile(const std::string& name, const std::string& what) {
    return calc::readWordFile(name, calc::defaultSearchPath(projectLibDir()), what);
}

void append(std::vector<std::string>& to, const std::vector<std::string>& words) {
    to.insert(to.end(), words.begin(), words.end());
}

}  // namespace

namespace {

// mkpmap's messages: a bad photon count says so; a range error is its own sentence.
OptionMessages mkpmapMessages() {
    OptionMessages m;
    const auto bad = m.bad;
    m.bad = [bad](const std::string& opt, const std::string& v, ValueKind kind) {
        if (kind == ValueKind::kCount)
            return "bad photon count '" + v + "' for option '" + opt + "'";
        return bad(opt, v, kind);
    };
    m.range = [](const std::string&, const std::string& what) { return what; };
    return m;
}

// -apg/-apc/-apv/-apd/-app/-apC(PD) file nphotons [bwidth]: a later one replaces an
// earlier one of the same type, as RADIANCE's.
OptionSpec mapOption(const std::string& name, PhotonMapType type, MkpmapOptions& o) {
    return customOption(name, [&o, type, name](OptionReader& r) {
        MapRequest m;
        m.file = r.word();
        m.target = r.count();
        if (type == PhotonMapType::PreComp) {
            const long b = r.integer(LONG_MIN, LONG_MAX);
            r.require(b > 0, "bandwidth for option '" + name + "' must be > 0");
            m.bandwidth = int(b);
        }
        m.primaryRays = name == "-apCPD";
        o.maps[size_t(type)] = m;
    });
}

bool positive(double v) { return v > 0; }

void addMapOptions(OptionTable& t, MkpmapOptions& o) {
    t.add(mapOption("-apg", PhotonMapType::Global, o));
    t.add(mapOption("-apc", PhotonMapType::Caustic, o));
    t.add(mapOption("-apv", PhotonMapType::Volume, o));
    t.add(mapOption("-apd", PhotonMapType::Direct, o));
    t.add(mapOption("-apC", PhotonMapType::Contrib, o));
    t.add(mapOption("-apCPD", PhotonMapType::Contrib, o));
    t.add(mapOption("-app", PhotonMapType::PreComp, o));
    t.add(countOption("-aC", o.memoryPhotons));
    t.add(valueOption("-apD", o.preDistrib, positive, "predistribution factor must be > 0"));
    t.add(valueOption("-apM", o.maxPrepass, positive, "max predistribution passes must be > 0"));
    t.add(valueOption(
        "-apP", o.precompFraction, [](double v) { return v > 0 && v <= 1; },
        "global photon precomputation factor must be in range ]0, 1]"));
    t.add(customOption("-apr", [&o](OptionReader& r) { o.seed = r.integer(LONG_MIN, LONG_MAX); }));
    t.add(customOption("-api", [&o](OptionReader& r) {
        RegionOfInterest roi;
        for (int k = 0; k < 3; ++k) roi.min[k] = r.real();
        for (int k = 0; k < 3; ++k) roi.max[k] = r.real();
        for (int k = 0; k < 3; ++k)
            r.require(roi.min[k] < roi.max[k], "invalid region of interest (swapped min/max?)");
        o.trace.rois.push_back(roi);
    }));
    for (const char* name : {"-apm", "-lr"})
        t.add(customOption(name, [&o](OptionReader& r) {
            o.trace.maxBounce = r.integer(LONG_MIN, LONG_MAX);
            r.require(o.trace.maxBounce > 0, "max photon bounces must be > 0");
        }));
    t.add(valueOption("-ld", o.trace.maxDistance, positive, "max photon distance must be > 0"));
}

// -apo[+|-|0] mod, -apO[+|-|0] file (RADIANCE mkpmap.c): the orientation is the option's
// suffix (forward when none), not part of the modifier's name.
void addPortOptions(OptionTable& t, MkpmapOptions& o) {
    auto isPort = [](const std::string& w) {
        return (w.rfind("-apo", 0) == 0 || w.rfind("-apO", 0) == 0) &&
               (w.size() == 4 ||
                (w.size() == 5 && std::string("+-0").find(w[4]) != std::string::npos));
    };
    t.add(customOption(isPort, "-apo", [&o](OptionReader& r) {
        const std::string& opt = r.option();
        const light::PortDirection dir = opt.size() == 4 || opt[4] == '+'
                                             ? light::PortDirection::Forward
                                         : opt[4] == '-' ? light::PortDirection::Backward
                                                         : light::PortDirection::Bidirectional;
        std::vector<std::string> mods{r.word()};
        if (opt[3] == 'O') mods = readWordFile(mods[0], "photon port");
        for (std::string& m : mods) o.portSpecs.push_back({std::move(m), dir});
    }));
}

void addModifierOptions(OptionTable& t, MkpmapOptions& o) {
    t.add(customOption("-aps", [&o](OptionReader& r) { o.trace.sensors.push_back(r.word()); }));
    t.add(customOption("-apS", [&o](OptionReader& r) {
        append(o.trace.sensors, readWordFile(r.word(), "antimatter sensor"));
    }));
    t.add(customOption("-ai", [&o](OptionReader& r) { o.trace.include.push_back(r.word()); }));
    for (const char* name : {"-aI", "-al"})
        t.add(customOption(name, [&o](OptionReader& r) {
            append(o.trace.include, readWordFile(r.word(), "ambient include"));
        }));
    t.add(customOption("-ae", [&o](OptionReader& r) { o.trace.exclude.push_back(r.word()); }));
    t.add(customOption("-aE", [&o](OptionReader& r) {
        append(o.trace.exclude, readWordFile(r.word(), "ambient exclude"));
    }));
}

void addOtherOptions(OptionTable& t, MkpmapOptions& o) {
    t.add(flagOption("-bv", o.trace.backVisible));
    t.add(flagOption("-fo", o.overwrite));
    t.add(valueOption("-dp", o.pdfSamples, positive, "PDF samples must be > 0"));
    t.add(valueOption("-ds", o.partitionSize, positive, "source partition size ratio must be > 0"));
    t.add(valueOption("-e", o.diagnosticsFile));
    t.add(valueOption("-ma", o.trace.medium.albedo));
    t.add(valueOption("-me", o.trace.medium.extinction));
    t.add(valueOption("-mg", o.trace.medium.eccentricity));
    t.add(customOption("-n", [&o](OptionReader& r) {
        const long n = r.integer(LONG_MIN, LONG_MAX);
        r.require(n > 0, "number of processes must be > 0");
        o.nproc = int(n);
    }));
    t.add(customOption("-t", [&o](OptionReader& r) {
        const long s = r.integer(LONG_MIN, LONG_MAX);
        r.require(s >= 0, "report interval must be >= 0");
        o.reportSeconds = int(s);
    }));
}

OptionTable mkpmapTable(MkpmapOptions& o) {
    OptionTable t;
    t.messages = mkpmapMessages();
    t.helpIsDefaults = true;
    addMapOptions(t, o);
    addPortOptions(t, o);
    addModifierOptions(t, o);
    addOtherOptions(t, o);
    return t;
}

}  // namespace

MkpmapOptions parseMkpmapArgs(int argc, const char* const* argv) {
    MkpmapOptions o;
    std::vector<std::string> args = argVector(argc, argv);
    const OptionParse p = mkpmapTable(o).parse(args, 1);
    o.printVersion = p.stop == OptionStop::kVersion;
    o.printDefaults = p.stop == OptionStop::kDefaults;
    if (p.stop != OptionStop::kEnd) return o;
    o.sceneFiles.assign(args.begin() + std::ptrdiff_t(p.next), args.end());
    if (!o.trace.include.empty() && !o.trace.exclude.empty())
        throw InputError("ambient include (-ai/-aI) and exclude (-ae/-aE) are mutually exclusive");
    bool any = false;
    for (const auto& m : o.maps) any = any || m.has_value();
    if (!any) throw InputError("no photon maps specified");
    if (o.sceneFiles.empty()) throw InputError("missing octree argument");
    return o;
}

}  // namespace rp::pmap

namespace rp::pmap {

namespace {

// One -defaults line: the option and its value, padded to RADIANCE's comment column.
void defaultsLine(std::string& out, const std::string& option, const char* what) {
    out += option;
    for (size_t width = option.size(); width < 40; width += 8 - width % 8) out += '\t';
    out += "# ";
    out += what;
    out += '\n';
}

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string mapLine(const MkpmapOptions& o, PhotonMapType t, const char* opt) {
    const auto& m = o.maps[size_t(t)];
    if (!m)
        return std::string(opt) + " file nPhotons" + (t == PhotonMapType::PreComp ? " bwidth" : "");
    std::string s = std::string(opt) + " " + m->file + " " + std::to_string(m->target);
    if (t == PhotonMapType::PreComp) s += " " + std::to_string(m->bandwidth);
    return s;
}

}  // namespace

std::string formatMkpmapDefaults(const MkpmapOptions& o) {
    std::string out;
    const auto sign = [](bool b) { return b ? std::string("+") : std::string("-"); };
    const auto colour = [&](const Color& c, int digits) {
        return fixed(c[0], digits) + " " + fixed(c[1], digits) + " " + fixed(c[2], digits);
    };
    defaultsLine(out, "-ae  mod", "exclude modifier");
    defaultsLine(out, "-aE  file", "exclude modifiers from file");
    defaultsLine(out, "-ai  mod", "include modifier");
    defaultsLine(out, "-aI  file", "include modifiers from file");
    defaultsLine(out, "-aC  " + std::to_string(o.memoryPhotons), "photons held in memory");
    defaultsLine(out, "-api xmin ymin zmin xmax ymax zmax", "rectangular region of interest");
    defaultsLine(out, mapLine(o, PhotonMapType::Global, "-apg"), "global photon map");
    defaultsLine(out, mapLine(o, PhotonMapType::Caustic, "-apc"), "caustic photon map");
    defaultsLine(out, mapLine(o, PhotonMapType::Direct, "-apd"), "direct photon map");
    defaultsLine(out, mapLine(o, PhotonMapType::PreComp, "-app"), "precomputed global photon map");
    defaultsLine(out, mapLine(o, PhotonMapType::Volume, "-apv"), "volume photon map");
    defaultsLine(out, mapLine(o, PhotonMapType::Contrib, "-apC"), "contribution photon map");
    defaultsLine(out, "-apD " + fixed(o.preDistrib, 6), "predistribution factor");
    defaultsLine(out, "-apM " + std::to_string(o.maxPrepass), "max predistrib passes");
    defaultsLine(out, "-apm " + std::to_string(o.trace.maxBounce), "limit photon bounces");
    defaultsLine(out, "-apo+ mod", "photon port modifier");
    defaultsLine(out, "-apO+ file", "photon ports from file");
    defaultsLine(out, "-apP " + fixed(o.precompFraction, 6), "precomputation factor");
    defaultsLine(out, "-apr " + std::to_string(o.seed), "random seed");
    defaultsLine(out, "-aps mod", "antimatter sensor modifier");
    defaultsLine(out, "-apS file", "antimatter sensors from file");
    defaultsLine(out, "-bv" + sign(o.trace.backVisible),
                 o.trace.backVisible ? "back face visibility on" : "back face visibility off");
    defaultsLine(out, "-dp  " + fixed(o.pdfSamples, 1), "PDF samples / sr");
    defaultsLine(out, "-ds  " + fixed(o.partitionSize, 6), "source partition size ratio");
    defaultsLine(out,
                 "-e   " + (o.diagnosticsFile.empty() ? std::string("(null)") : o.diagnosticsFile),
                 "diagnostics output file");
    defaultsLine(out, "-fo" + sign(o.overwrite), o.overwrite ? "overwrite" : "do not overwrite");
    defaultsLine(out, "-ld " + fixed(o.trace.maxDistance, 1), "limit photon distance");
    defaultsLine(out, "-lr " + std::to_string(o.trace.maxBounce), "limit photon bounces");
    defaultsLine(out, "-ma  " + colour(o.trace.medium.albedo, 2), "scattering albedo");
    char ext[96];
    std::snprintf(ext, sizeof ext, "-me  %.2e %.2e %.2e", o.trace.medium.extinction[0],
                  o.trace.medium.extinction[1], o.trace.medium.extinction[2]);
    defaultsLine(out, ext, "extinction coefficient");
    defaultsLine(out, "-mg  " + fixed(o.trace.medium.eccentricity, 2), "scattering eccentricity");
    defaultsLine(out, "-n   " + std::to_string(o.nproc), "number of parallel processes");
    defaultsLine(out, "-t   " + std::to_string(o.reportSeconds), "time between reports");
    return out;
}

}  // namespace rp::pmap
