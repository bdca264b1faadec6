// mkpmap command-line parsing (RADIANCE mkpmap.c main, mkpmap.1). Option semantics are
// RADIANCE's; messages are ours, one line each.
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <string>

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
        if (type == PhotonMapType::PreComp ||
            (type == PhotonMapType::Contrib && r.nextIsInteger())) {
            const long b = r.integer(LONG_MIN, LONG_MAX);
            r.require(b > 0, "bandwidth for option '" + name + "' must be > 0");
            m.bandwidth = int(b);
        }
        // The development branch's comp after a precomputed contribution map's bandwidth.
        if (type == PhotonMapType::Contrib && m.bandwidth > 0 && r.hasNext() &&
            parseReal(r.args()[r.next()])) {
            m.compression = r.real();
            r.require(m.compression >= 0 && m.compression <= 1,
                      "compression for option '" + name + "' must be in [0, 1]");
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
    t.add(valueOption("-apD", o.pass.preDistrib, positive, "predistribution factor must be > 0"));
    t.add(
        valueOption("-apM", o.pass.maxPrepass, positive, "max predistribution passes must be > 0"));
    t.add(valueOption(
        "-apP", o.precompFraction, [](double v) { return v > 0 && v <= 1; },
        "global photon precomputation factor must be in range ]0, 1]"));
    t.add(customOption(
        "-apr", [&o](OptionReader& r) { o.pass.seed = uint64_t(r.integer(LONG_MIN, LONG_MAX)); }));
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
    t.add(flagOption("-apE", o.portExterior));
    t.add(flagOption("-fo", o.overwrite));
    t.add(valueOption("-dp", o.pdfSamples, positive, "PDF samples must be > 0"));
    t.add(valueOption("-ds", o.partitionSize, positive, "source partition size ratio must be > 0"));
    // RADIANCE 5.4's -e names the diagnostics file; rcontrib's -e is a definition, which
    // the binning of a precomputed contribution map needs (-e MF:1 -f reinhart.cal -bn
    // Nrbins). A word with an assignment (':' or '=') is taken as the latter.
    t.add(customOption("-e", [&o](OptionReader& r) {
        const std::string& w = r.word();
        if (w.find_first_of(":=") != std::string::npos)
            o.contribDefinitions.push_back({false, w});
        else
            o.diagnosticsFile = w;
    }));
    t.add(valueOption("-cs", o.spectralSamples));
    t.add(customOption("-cw", [&o](OptionReader& r) {
        o.wavelengthA = r.real();
        o.wavelengthB = r.real();
    }));
    t.add(valueOption("-ma", o.trace.medium.albedo));
    t.add(valueOption("-me", o.trace.medium.extinction));
    t.add(valueOption("-mg", o.trace.medium.eccentricity));
    t.add(customOption("-n", [&o](OptionReader& r) {
        const long n = r.integer(LONG_MIN, LONG_MAX);
        r.require(n > 0, "number of processes must be > 0");
        o.pass.threads = int(n);
    }));
    t.add(customOption("-t", [&o](OptionReader& r) {
        const long s = r.integer(LONG_MIN, LONG_MAX);
        r.require(s >= 0, "report interval must be >= 0");
        o.pass.reportSeconds = int(s);
    }));
}

// One -defaults line: the option and its value, padded to RADIANCE's comment column.
std::string defaultsLine(const std::string& option, const char* what) {
    std::string out = option;
    for (size_t width = option.size(); width < 40; width += 8 - width % 8) out += '\t';
    out += "# ";
    out += what;
    out += '\n';
    return out;
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

// Each option's -defaults line (RADIANCE mkpmap's layout and order), from the values in
// `o`: those given before -defaults are the ones listed, as in RADIANCE.
void addDefaults(OptionTable& t, const MkpmapOptions& o) {
    const auto sign = [](bool b) { return b ? std::string("+") : std::string("-"); };
    const auto colour = [](const Color& c, int digits) {
        return fixed(c[0], digits) + " " + fixed(c[1], digits) + " " + fixed(c[2], digits);
    };
    const auto fixedLine = [&t](const char* name, std::string text, const char* what) {
        t.setDefaults(name, [text = std::move(text), what] { return defaultsLine(text, what); });
    };
    fixedLine("-ae", "-ae  mod", "exclude modifier");
    fixedLine("-aE", "-aE  file", "exclude modifiers from file");
    fixedLine("-ai", "-ai  mod", "include modifier");
    fixedLine("-aI", "-aI  file", "include modifiers from file");
    t.setDefaults("-aC", [&o] {
        return defaultsLine("-aC  " + std::to_string(o.memoryPhotons), "photons held in memory");
    });
    fixedLine("-api", "-api xmin ymin zmin xmax ymax zmax", "rectangular region of interest");
    const auto map = [&](const char* name, PhotonMapType type, const char* what) {
        t.setDefaults(
            name, [&o, name, type, what] { return defaultsLine(mapLine(o, type, name), what); });
    };
    map("-apg", PhotonMapType::Global, "global photon map");
    map("-apc", PhotonMapType::Caustic, "caustic photon map");
    map("-apd", PhotonMapType::Direct, "direct photon map");
    map("-app", PhotonMapType::PreComp, "precomputed global photon map");
    map("-apv", PhotonMapType::Volume, "volume photon map");
    map("-apC", PhotonMapType::Contrib, "contribution photon map");
    t.setDefaults("-apD", [&o] {
        return defaultsLine("-apD " + fixed(o.pass.preDistrib, 6), "predistribution factor");
    });
    t.setDefaults("-apE", [&o, sign] {
        return defaultsLine("-apE" + sign(o.portExterior),
                            o.portExterior ? "ports see the outside" : "ports see sources only");
    });
    t.setDefaults("-apM", [&o] {
        return defaultsLine("-apM " + std::to_string(o.pass.maxPrepass), "max predistrib passes");
    });
    t.setDefaults("-apm", [&o] {
        return defaultsLine("-apm " + std::to_string(o.trace.maxBounce), "limit photon bounces");
    });
    t.setDefaults("-apo", [] {
        return defaultsLine("-apo+ mod", "photon port modifier") +
               defaultsLine("-apO+ file", "photon ports from file");
    });
    t.setDefaults("-apP", [&o] {
        return defaultsLine("-apP " + fixed(o.precompFraction, 6), "precomputation factor");
    });
    t.setDefaults("-apr", [&o] {
        return defaultsLine("-apr " + std::to_string(int64_t(o.pass.seed)), "random seed");
    });
    fixedLine("-aps", "-aps mod", "antimatter sensor modifier");
    fixedLine("-apS", "-apS file", "antimatter sensors from file");
    t.setDefaults("-bv", [&o, sign] {
        return defaultsLine("-bv" + sign(o.trace.backVisible), o.trace.backVisible
                                                                   ? "back face visibility on"
                                                                   : "back face visibility off");
    });
    t.setDefaults(
        "-dp", [&o] { return defaultsLine("-dp  " + fixed(o.pdfSamples, 1), "PDF samples / sr"); });
    t.setDefaults("-ds", [&o] {
        return defaultsLine("-ds  " + fixed(o.partitionSize, 6), "source partition size ratio");
    });
    t.setDefaults("-e", [&o] {
        return defaultsLine(
            "-e   " + (o.diagnosticsFile.empty() ? std::string("(null)") : o.diagnosticsFile),
            "diagnostics output file");
    });
    t.setDefaults("-fo", [&o, sign] {
        return defaultsLine("-fo" + sign(o.overwrite),
                            o.overwrite ? "overwrite" : "do not overwrite");
    });
    t.setDefaults("-ld", [&o] {
        return defaultsLine("-ld " + fixed(o.trace.maxDistance, 1), "limit photon distance");
    });
    t.setDefaults("-lr", [&o] {
        return defaultsLine("-lr " + std::to_string(o.trace.maxBounce), "limit photon bounces");
    });
    t.setDefaults("-ma", [&o, colour] {
        return defaultsLine("-ma  " + colour(o.trace.medium.albedo, 2), "scattering albedo");
    });
    t.setDefaults("-me", [&o] {
        const Color& e = o.trace.medium.extinction;
        return defaultsLine(formatLine("-me  %.2e %.2e %.2e", e[0], e[1], e[2]),
                            "extinction coefficient");
    });
    t.setDefaults("-mg", [&o] {
        return defaultsLine("-mg  " + fixed(o.trace.medium.eccentricity, 2),
                            "scattering eccentricity");
    });
    t.setDefaults("-n", [&o] {
        return defaultsLine("-n   " + std::to_string(o.pass.threads),
                            "number of parallel processes");
    });
    t.setDefaults("-t", [&o] {
        return defaultsLine("-t   " + std::to_string(o.pass.reportSeconds), "time between reports");
    });
    t.setDefaultsOrder({"-ae",  "-aE",  "-ai",  "-aI",  "-aC",  "-api", "-apg", "-apc", "-apd",
                        "-app", "-apv", "-apC", "-apD", "-apE", "-apM", "-apm", "-apo", "-apP",
                        "-apr", "-aps", "-apS", "-bv",  "-dp",  "-ds",  "-e",   "-fo",  "-ld",
                        "-lr",  "-ma",  "-me",  "-mg",  "-n",   "-t"});
}

// Precomputed contribution maps: rcontrib's binning options (contrib_bins.h), -f for its
// .cal files and -V.
void addBinningOptions(OptionTable& t, MkpmapOptions& o, ModifierOptions& mods) {
    mods.addTo(t, false);
    t.add(customOption("-f", [&o](OptionReader& r) {
        o.contribDefinitions.push_back({true, r.word()});
    }));
    t.add(flagOption("-V", o.contributions, 3));
}

OptionTable mkpmapTable(MkpmapOptions& o, ModifierOptions& mods) {
    OptionTable t;
    t.messages = mkpmapMessages();
    t.helpIsDefaults = true;
    addMapOptions(t, o);
    addBinningOptions(t, o, mods);
    addPortOptions(t, o);
    addModifierOptions(t, o);
    addOtherOptions(t, o);
    addDefaults(t, o);
    return t;
}

}  // namespace

// The development branch's precomputed contribution map: -apC with a bandwidth and -m/-M
// go together.
static void checkPrecomputedContrib(const MkpmapOptions& o) {
    const auto& c = o.maps[size_t(PhotonMapType::Contrib)];
    if (o.precomputedContrib() && !c)
        throw InputError("modifiers (-m/-M) need a precomputed contribution map (-apC)");
    if (!c) return;
    if (o.precomputedContrib() && c->bandwidth <= 0)
        throw InputError("precomputed contribution map " + c->file +
                         " needs a bandwidth (-apC file nphotons bwidth [comp])");
    if (!o.precomputedContrib() && c->bandwidth > 0)
        throw InputError("contribution map " + c->file +
                         " with a bandwidth is precomputed: name its modifiers (-m/-M)");
    if (c->primaryRays && o.precomputedContrib())
        throw InputError("-apCPD keeps primary rays of contribution maps, not of precomputed ones");
}

MkpmapOptions parseMkpmapArgs(int argc, const char* const* argv) {
    MkpmapOptions o;
    std::vector<std::string> args = argVector(argc, argv);
    ModifierOptions mods(o.contribModifiers, o.contribDefinitions, &evalBinCount);
    const OptionParse p = mkpmapTable(o, mods).parse(args, 1);
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
    checkPrecomputedContrib(o);
    return o;
}

std::string formatMkpmapDefaults(const MkpmapOptions& o) {
    MkpmapOptions values = o;
    ModifierOptions mods(values.contribModifiers, values.contribDefinitions, nullptr);
    return mkpmapTable(values, mods).formatDefaults();
}

}  // namespace rp::pmap
