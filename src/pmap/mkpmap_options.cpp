// mkpmap command-line parsing (RADIANCE mkpmap.c main, mkpmap.1). Option semantics are
// RADIANCE's; messages are ours, one line each.
#include "pmap/mkpmap_options.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "calc/search_path.h"
#include "util/bool_option.h"
#include "util/error.h"
#include "util/paths.h"

namespace rp::pmap {

std::optional<uint64_t> parsePhotonCount(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || errno != 0) return std::nullopt;
    std::string rest(end);
    if (rest == "k" || rest == "K")
        v *= 1e3;
    else if (rest == "m" || rest == "M")
        v *= 1e6;
    else if (rest == "g" || rest == "G")
        v *= 1e9;
    else if (!rest.empty())
        return std::nullopt;
    if (!(v >= 1) || v > 1e15) return std::nullopt;
    return uint64_t(std::llround(v));
}

uint64_t defaultMemoryPhotons() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return uint64_t{1} << 27;  // unknown: 3 GB of photons
    return uint64_t(pages) / 2 * uint64_t(pageSize) / sizeof(Photon);
}

namespace {

class ArgReader {
public:
    ArgReader(int argc, const char* const* argv) : argc_(argc), argv_(argv) {}
    bool done() const { return i_ >= argc_; }
    bool last() const { return i_ == argc_ - 1; }
    std::string peek() const { return argv_[i_]; }
    std::string next() { return argv_[i_++]; }

    // The value after option `opt`.
    std::string value(const std::string& opt) {
        if (i_ >= argc_) throw InputError("missing value for option '" + opt + "'");
        return argv_[i_++];
    }
    double real(const std::string& opt) {
        std::string v = value(opt);
        char* end = nullptr;
        double d = std::strtod(v.c_str(), &end);
        if (end == v.c_str() || *end != '\0' || !std::isfinite(d))
            throw InputError("bad value '" + v + "' for option '" + opt + "'");
        return d;
    }
    long integer(const std::string& opt) {
        std::string v = value(opt);
        char* end = nullptr;
        errno = 0;
        long n = std::strtol(v.c_str(), &end, 10);
        if (end == v.c_str() || *end != '\0' || errno != 0)
            throw InputError("bad value '" + v + "' for option '" + opt + "'");
        return n;
    }

private:
    int argc_;
    const char* const* argv_;
    int i_ = 1;
};

// The words of a modifier list file, found along RAYPATH (RADIANCE mkpmap.c: wordfile on
// getpath).
std::vector<std::string> readWordFile(const std::string& name, const std::string& what) {
    return calc::readWordFile(name, calc::defaultSearchPath(projectLibDir()), what);
}

void append(std::vector<std::string>& to, const std::vector<std::string>& words) {
    to.insert(to.end(), words.begin(), words.end());
}

// RADIANCE mkpmap.c: the port orientation is the option's suffix, -apo[+|-|0] mod and
// -apO[+|-|0] file (forward when none), not part of the modifier's name.
bool isPortOption(const std::string& opt) {
    return (opt.rfind("-apo", 0) == 0 || opt.rfind("-apO", 0) == 0) &&
           (opt.size() == 4 ||
            (opt.size() == 5 && std::string("+-0").find(opt[4]) != std::string::npos));
}

light::PortDirection portDirection(const std::string& opt) {
    if (opt.size() == 4 || opt[4] == '+') return light::PortDirection::Forward;
    return opt[4] == '-' ? light::PortDirection::Backward : light::PortDirection::Bidirectional;
}

}  // namespace

MkpmapOptions parseMkpmapArgs(int argc, const char* const* argv) {
    MkpmapOptions o;
    ArgReader a(argc, argv);
    auto mapOpt = [&](const std::string& opt, PhotonMapType type, bool bwidth) {
        MapRequest r;
        r.file = a.value(opt);
        std::string n = a.value(opt);
        auto count = parsePhotonCount(n);
        if (!count) throw InputError("bad photon count '" + n + "' for option '" + opt + "'");
        r.target = *count;
        if (bwidth) {
            long b = a.integer(opt);
            if (b <= 0) throw InputError("bandwidth for option '" + opt + "' must be > 0");
            r.bandwidth = int(b);
        }
        o.maps[size_t(type)] = r;
    };
    auto positive = [](double v, const char* msg) {
        if (!(v > 0)) throw InputError(msg);
        return v;
    };

    while (!a.done()) {
        std::string opt = a.peek();
        if (opt.size() < 2 || opt[0] != '-') break;  // scene files from here on
        a.next();
        if (opt == "-defaults" || opt == "-help" || opt == "-version") {
            (opt == "-version" ? o.printVersion : o.printDefaults) = true;
            return o;
        }
        if (opt == "-apg")
            mapOpt(opt, PhotonMapType::Global, false);
        else if (opt == "-apc")
            mapOpt(opt, PhotonMapType::Caustic, false);
        else if (opt == "-apv")
            mapOpt(opt, PhotonMapType::Volume, false);
        else if (opt == "-apd")
            mapOpt(opt, PhotonMapType::Direct, false);
        else if (opt == "-apC" || opt == "-apCPD") {
            mapOpt(opt, PhotonMapType::Contrib, false);
            o.maps[size_t(PhotonMapType::Contrib)]->primaryRays = opt == "-apCPD";
        } else if (opt == "-app")
            mapOpt(opt, PhotonMapType::PreComp, true);
        else if (opt == "-aC") {
            const std::string n = a.value(opt);
            const auto count = parsePhotonCount(n);
            if (!count) throw InputError("bad photon count '" + n + "' for option '-aC'");
            o.memoryPhotons = *count;
        } else if (opt == "-apD")
            o.preDistrib = positive(a.real(opt), "predistribution factor must be > 0");
        else if (opt == "-apM") {
            o.maxPrepass = int(a.integer(opt));
            if (o.maxPrepass <= 0) throw InputError("max predistribution passes must be > 0");
        } else if (opt == "-apP") {
            o.precompFraction = a.real(opt);
            if (!(o.precompFraction > 0 && o.precompFraction <= 1))
                throw InputError("global photon precomputation factor must be in range ]0, 1]");
        } else if (opt == "-apr")
            o.seed = a.integer(opt);
        else if (opt == "-api") {
            RegionOfInterest r;
            for (int k = 0; k < 3; ++k) r.min[k] = a.real(opt);
            for (int k = 0; k < 3; ++k) r.max[k] = a.real(opt);
            for (int k = 0; k < 3; ++k)
                if (r.min[k] >= r.max[k])
                    throw InputError("invalid region of interest (swapped min/max?)");
            o.rois.push_back(r);
        } else if (opt == "-apm" || opt == "-lr") {
            o.maxBounce = a.integer(opt);
            if (o.maxBounce <= 0) throw InputError("max photon bounces must be > 0");
        } else if (opt == "-ld")
            o.maxDistance = positive(a.real(opt), "max photon distance must be > 0");
        else if (isPortOption(opt)) {
            const light::PortDirection dir = portDirection(opt);
            std::vector<std::string> mods{a.value(opt)};
            if (opt[3] == 'O') mods = readWordFile(mods[0], "photon port");
            for (std::string& m : mods) o.portSpecs.push_back({std::move(m), dir});
        } else if (opt == "-aps")
            o.sensors.push_back(a.value(opt));
        else if (opt == "-apS")
            append(o.sensors, readWordFile(a.value(opt), "antimatter sensor"));
        else if (opt == "-ai")
            o.include.push_back(a.value(opt));
        else if (opt == "-aI" || opt == "-al")
            append(o.include, readWordFile(a.value(opt), "ambient include"));
        else if (opt == "-ae")
            o.exclude.push_back(a.value(opt));
        else if (opt == "-aE")
            append(o.exclude, readWordFile(a.value(opt), "ambient exclude"));
        else if (opt.rfind("-bv", 0) == 0)
            o.backVisible = boolSuffix(opt, 3, o.backVisible);
        else if (opt.rfind("-fo", 0) == 0)
            o.overwrite = boolSuffix(opt, 3, o.overwrite);
        else if (opt == "-dp")
            o.pdfSamples = positive(a.real(opt), "PDF samples must be > 0");
        else if (opt == "-ds")
            o.partitionSize = positive(a.real(opt), "source partition size ratio must be > 0");
        else if (opt == "-e")
            o.diagnosticsFile = a.value(opt);
        else if (opt == "-ma" || opt == "-me") {
            Color c;
            for (int k = 0; k < 3; ++k) c[k] = a.real(opt);
            (opt == "-ma" ? o.mediumAlbedo : o.mediumExtinction) = c;
        } else if (opt == "-mg")
            o.mediumEccentricity = a.real(opt);
        else if (opt == "-n") {
            long n = a.integer(opt);
            if (n <= 0) throw InputError("number of processes must be > 0");
            o.nproc = int(n);
        } else if (opt == "-t") {
            long t = a.integer(opt);
            if (t < 0) throw InputError("report interval must be >= 0");
            o.reportSeconds = int(t);
        } else
            throw InputError("unknown option '" + opt + "'");
    }
    while (!a.done()) o.sceneFiles.push_back(a.next());

    if (!o.include.empty() && !o.exclude.empty())
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
    defaultsLine(out, "-apm " + std::to_string(o.maxBounce), "limit photon bounces");
    defaultsLine(out, "-apo+ mod", "photon port modifier");
    defaultsLine(out, "-apO+ file", "photon ports from file");
    defaultsLine(out, "-apP " + fixed(o.precompFraction, 6), "precomputation factor");
    defaultsLine(out, "-apr " + std::to_string(o.seed), "random seed");
    defaultsLine(out, "-aps mod", "antimatter sensor modifier");
    defaultsLine(out, "-apS file", "antimatter sensors from file");
    defaultsLine(out, "-bv" + sign(o.backVisible),
                 o.backVisible ? "back face visibility on" : "back face visibility off");
    defaultsLine(out, "-dp  " + fixed(o.pdfSamples, 1), "PDF samples / sr");
    defaultsLine(out, "-ds  " + fixed(o.partitionSize, 6), "source partition size ratio");
    defaultsLine(out,
                 "-e   " + (o.diagnosticsFile.empty() ? std::string("(null)") : o.diagnosticsFile),
                 "diagnostics output file");
    defaultsLine(out, "-fo" + sign(o.overwrite), o.overwrite ? "overwrite" : "do not overwrite");
    defaultsLine(out, "-ld " + fixed(o.maxDistance, 1), "limit photon distance");
    defaultsLine(out, "-lr " + std::to_string(o.maxBounce), "limit photon bounces");
    defaultsLine(out, "-ma  " + colour(o.mediumAlbedo, 2), "scattering albedo");
    char ext[96];
    std::snprintf(ext, sizeof ext, "-me  %.2e %.2e %.2e", o.mediumExtinction[0],
                  o.mediumExtinction[1], o.mediumExtinction[2]);
    defaultsLine(out, ext, "extinction coefficient");
    defaultsLine(out, "-mg  " + fixed(o.mediumEccentricity, 2), "scattering eccentricity");
    defaultsLine(out, "-n   " + std::to_string(o.nproc), "number of parallel processes");
    defaultsLine(out, "-t   " + std::to_string(o.reportSeconds), "time between reports");
    return out;
}

}  // namespace rp::pmap
