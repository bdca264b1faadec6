// The options rtrace and rpict share (RADIANCE renderopts.c getrenderopt/print_rdefaults and
// pmapopt.c): parsing and the -defaults text. Semantics and defaults are RADIANCE 5.4's;
// error messages are ours, one line each.
#include "render/render_options.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "calc/search_path.h"
#include "pmap/mkpmap_options.h"
#include "util/bool_option.h"
#include "util/error.h"
#include "util/paths.h"

namespace rp::render {

namespace {

// Reads the values that follow the option at args[i].
class Values {
public:
    Values(const std::vector<std::string>& args, size_t i)
        : args_(args), opt_(args[i]), at_(i + 1) {}

    const std::string& word() {
        if (at_ >= args_.size()) throw InputError("missing value for option '" + opt_ + "'");
        return args_[at_++];
    }
    double real() {
        const std::string& v = word();
        char* end = nullptr;
        double d = std::strtod(v.c_str(), &end);
        if (v.empty() || *end != '\0' || !std::isfinite(d)) bad(v);
        return d;
    }
    int integer() {
        const std::string& v = word();
        char* end = nullptr;
        errno = 0;
        long n = std::strtol(v.c_str(), &end, 10);
        if (v.empty() || *end != '\0' || errno != 0 || n < -2147483647L || n > 2147483647L) bad(v);
        return int(n);
    }
    // True if the next word exists and is an integer (RADIANCE isint), without consuming it.
    bool nextIsInteger() const {
        if (at_ >= args_.size()) return false;
        const std::string& v = args_[at_];
        char* end = nullptr;
        errno = 0;
        std::strtol(v.c_str(), &end, 10);
        return !v.empty() && *end == '\0' && errno == 0;
    }
    [[noreturn]] void bad(const std::string& v) const {
        throw InputError("bad value '" + v + "' for option '" + opt_ + "'");
    }
    void require(bool ok, const std::string& what) const {
        if (!ok) throw InputError("option '" + opt_ + "': " + what);
    }
    size_t end() const { return at_; }

private:
    const std::vector<std::string>& args_;
    std::string opt_;
    size_t at_;
};

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The words of a modifier list file, found along RAYPATH (RADIANCE renderopts.c:
// wordfile on getpath).
std::vector<std::string> readWordFile(const std::string& name, const std::string& what) {
    return calc::readWordFile(name, calc::defaultSearchPath(projectLibDir()), "ambient " + what);
}

// -ai/-ae/-aI/-aE: RADIANCE compat (renderopts.c): switching between include and exclude
// starts a new list; repeating the same kind adds to it.
void modifierList(AmbientOptions& a, bool include, const std::vector<std::string>& words) {
    if (a.includeList != include) {
        a.modifiers.clear();
        a.includeList = include;
    }
    a.modifiers.insert(a.modifiers.end(), words.begin(), words.end());
}

Color readColor(Values& v) {
    Color c;
    for (int k = 0; k < 3; ++k) c[k] = v.real();
    return c;
}

}  // namespace

bool parseRenderOption(const std::vector<std::string>& args, size_t& i, RenderOptions& opt) {
    if (i >= args.size()) return false;
    const std::string& o = args[i];
    if (o.size() < 2 || o[0] != '-') return false;
    Values v(args, i);
    auto done = [&] {
        i = v.end();
        return true;
    };

    // Booleans (value-less).
    if (startsWith(o, "-bv")) {
        opt.backVisible = boolSuffix(o, 3, opt.backVisible);
        return done();
    }
    if (startsWith(o, "-dv")) {
        opt.direct.visibility = boolSuffix(o, 3, opt.direct.visibility);
        return done();
    }
    if (o.size() <= 3 && o[1] == 'i') {
        opt.irradiance = boolSuffix(o, 2, opt.irradiance);
        return done();
    }
    if (o.size() <= 3 && o[1] == 'u') {
        opt.uncorrelated = boolSuffix(o, 2, opt.uncorrelated);
        return done();
    }
    if (o.size() <= 3 && o[1] == 'w') {
        opt.warnings = boolSuffix(o, 2, opt.warnings);
        return done();
    }

    DirectOptions& d = opt.direct;
    AmbientOptions& a = opt.ambient;
    if (o == "-dt") {
        d.threshold = v.real();
        v.require(d.threshold >= 0, "must be >= 0");
    } else if (o == "-dc") {
        d.certainty = v.real();
        v.require(d.certainty >= 0 && d.certainty <= 1, "must be in [0, 1]");
    } else if (o == "-dj") {
        d.jitter = v.real();
        v.require(d.jitter >= 0 && d.jitter <= 1, "must be in [0, 1]");
    } else if (o == "-ds") {
        d.sampling = v.real();
        v.require(d.sampling >= 0, "must be >= 0");
    } else if (o == "-dr") {
        d.relays = v.integer();
        v.require(d.relays >= 0, "must be >= 0");
    } else if (o == "-dp") {
        d.pretest = v.integer();
        v.require(d.pretest >= 0, "must be >= 0");
    } else if (o == "-ss") {
        opt.specular.sampling = v.real();
        v.require(opt.specular.sampling >= 0, "must be >= 0");
    } else if (o == "-st") {
        opt.specular.threshold = v.real();
        v.require(opt.specular.threshold >= 0, "must be >= 0");
    } else if (o == "-lr")
        opt.limits.maxDepth = v.integer();
    else if (o == "-lw") {
        opt.limits.minWeight = v.real();
        v.require(opt.limits.minWeight >= 0, "must be >= 0");
    } else if (o == "-av")
        a.value = readColor(v);
    else if (o == "-aw") {
        a.valueWeight = v.integer();
        v.require(a.valueWeight >= 0, "must be >= 0");
    }
    // RADIANCE allows a negative -ab (rtrace.1: use the ambient file without new records);
    // the renderer decides what it means.
    else if (o == "-ab")
        a.bounces = v.integer();
    else if (o == "-aa") {
        a.accuracy = v.real();
        v.require(a.accuracy >= 0, "must be >= 0");
    } else if (o == "-ar") {
        a.resolution = v.integer();
        v.require(a.resolution >= 0, "must be >= 0");
    } else if (o == "-ad") {
        // Each hemisphere holds its divisions in memory (about 90 bytes each): beyond 1e8
        // the request is an error here, not an allocation that fails (issue 43).
        a.divisions = v.integer();
        v.require(a.divisions >= 0 && a.divisions <= kMaxAmbientDivisions,
                  "must be in [0, " + std::to_string(kMaxAmbientDivisions) + "]");
    } else if (o == "-as") {
        a.supersamples = v.integer();
        v.require(a.supersamples >= 0, "must be >= 0");
    } else if (o == "-af")
        a.file = v.word();
    else if (o == "-ai")
        modifierList(a, true, {v.word()});
    else if (o == "-ae")
        modifierList(a, false, {v.word()});
    else if (o == "-aI")
        modifierList(a, true, readWordFile(v.word(), "include"));
    else if (o == "-aE")
        modifierList(a, false, readWordFile(v.word(), "exclude"));
    else if (o == "-ap") {
        PhotonMapUse use;
        use.file = v.word();
        // RADIANCE compat (pmapopt.c): the following words are bandwidths only if integers.
        if (v.nextIsInteger()) {
            use.bandwidth = v.integer();
            v.require(use.bandwidth > 0, "photon lookup bandwidth must be > 0");
            if (v.nextIsInteger()) {
                use.bandwidth2 = v.integer();
                v.require(use.bandwidth2 > use.bandwidth,
                          "maximum bandwidth must exceed the minimum (bias compensation)");
            }
        }
        opt.photonMaps.push_back(use);
        // RADIANCE compat (pmapopt.c): a photon map implies at least one ambient bounce.
        if (a.bounces == 0) a.bounces = 1;
    } else if (o == "-am") {
        opt.photonMaxRadius = v.real();
        v.require(opt.photonMaxRadius > 0, "invalid max photon search radius");
    } else if (o == "-ac") {
        opt.photonPageSize = v.real();
        v.require(opt.photonPageSize > 0, "invalid photon cache page size");
    } else if (o == "-aC") {
        const std::optional<uint64_t> n = pmap::parsePhotonCount(v.word());
        v.require(n && *n > 0, "invalid photon cache size");
        opt.photonCache = *n;
    } else if (o == "-me")
        opt.mist.extinction = readColor(v);
    else if (o == "-ma")
        opt.mist.albedo = readColor(v);
    else if (o == "-mg")
        opt.mist.eccentricity = v.real();
    else if (o == "-ms")
        opt.mist.samplingDistance = v.real();
    else if (o == "-n") {
        opt.threads = v.integer();
        v.require(opt.threads >= 1, "bad number of processes");
    } else if (o == "-e")
        opt.errorFile = v.word();
    else
        return false;
    return done();
}

std::string formatRenderDefaults(const RenderOptions& opt) {
    std::string out;
    char line[200];
    auto put = [&](const char* fmt, auto... args) {
        std::snprintf(line, sizeof line, fmt, args...);
        out += line;
    };
    const auto& d = opt.direct;
    const auto& a = opt.ambient;
    // RADIANCE compat: the lines, order and printf formats of print_rdefaults (renderopts.c)
    // and printPmapDefaults (pmapopt.c).
    out += opt.irradiance ? "-i+\t\t\t\t# irradiance calculation on\n"
                          : "-i-\t\t\t\t# irradiance calculation off\n";
    out += opt.uncorrelated ? "-u+\t\t\t\t# uncorrelated Monte Carlo sampling\n"
                            : "-u-\t\t\t\t# correlated quasi-Monte Carlo sampling\n";
    out += opt.backVisible ? "-bv+\t\t\t\t# back face visibility on\n"
                           : "-bv-\t\t\t\t# back face visibility off\n";
    put("-dt %f\t\t\t# direct threshold\n", d.threshold);
    put("-dc %f\t\t\t# direct certainty\n", d.certainty);
    put("-dj %f\t\t\t# direct jitter\n", d.jitter);
    put("-ds %f\t\t\t# direct sampling\n", d.sampling);
    put("-dr %-9d\t\t\t# direct relays\n", d.relays);
    put("-dp %-9d\t\t\t# direct pretest density\n", d.pretest);
    out += d.visibility ? "-dv+\t\t\t\t# direct visibility on\n"
                        : "-dv-\t\t\t\t# direct visibility off\n";
    put("-ss %f\t\t\t# specular sampling\n", opt.specular.sampling);
    put("-st %f\t\t\t# specular threshold\n", opt.specular.threshold);
    put("-av %f %f %f\t# ambient value\n", a.value.r, a.value.g, a.value.b);
    put("-aw %-9d\t\t\t# ambient value weight\n", a.valueWeight);
    put("-ab %-9d\t\t\t# ambient bounces\n", a.bounces);
    put("-aa %f\t\t\t# ambient accuracy\n", a.accuracy);
    put("-ar %-9d\t\t\t# ambient resolution\n", a.resolution);
    put("-ad %-9d\t\t\t# ambient divisions\n", a.divisions);
    put("-as %-9d\t\t\t# ambient super-samples\n", a.supersamples);
    const auto& m = opt.mist;
    put("-me %.2e %.2e %.2e\t# mist extinction coefficient\n", m.extinction.r, m.extinction.g,
        m.extinction.b);
    put("-ma %f %f %f\t# mist scattering albedo\n", m.albedo.r, m.albedo.g, m.albedo.b);
    put("-mg %f\t\t\t# mist scattering eccentricity\n", m.eccentricity);
    put("-ms %f\t\t\t# mist sampling distance\n", m.samplingDistance);
    put("-lr %-9d\t\t\t# limit reflection%s\n", opt.limits.maxDepth,
        opt.limits.maxDepth <= 0 ? " (Russian roulette)" : "");
    put("-lw %.2e\t\t\t# limit weight\n", opt.limits.minWeight);
    put("-am %.1f\t\t\t\t# max photon search radius\n", opt.photonMaxRadius);
    return out;
}

}  // namespace rp::render
