// The options rtrace and rpict share (RADIANCE renderopts.c getrenderopt/print_rdefaults and
// pmapopt.c) as entries of the tool's option table: parsing and the -defaults text. Semantics and
// defaults are RADIANCE 5.4's; error messages are ours, one line each.
#include "render/render_options.h"

#include "calc/search_path.h"
#include "util/error.h"
#include "util/paths.h"
#include "util/warnings.h"

namespace rp::render {

namespace {

bool nonNegative(double v) { return v >= 0; }
bool unitInterval(double v) { return v >= 0 && v <= 1; }
constexpr const char* kNonNegative = "must be >= 0";

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

// A boolean's -defaults line: "-bv+\t\t\t\t# back face visibility on".
std::function<std::string()> boolLine(const bool& v, const char* name, const char* on,
                                      const char* off) {
    return [&v, name, on, off] {
        return formatLine("%s%c\t\t\t\t# %s\n", name, v ? '+' : '-', v ? on : off);
    };
}

std::function<std::string()> realLine(const double& v, const char* fmt) {
    return [&v, fmt] { return formatLine(fmt, v); };
}

std::function<std::string()> intLine(const int& v, const char* fmt) {
    return [&v, fmt] { return formatLine(fmt, v); };
}

void addFlagsAndDirect(OptionTable& t, RenderOptions& opt) {
    // RADIANCE compat: -i, -u and -w are recognised by length (rtrace's -I, -ld are not).
    t.add(
        flagOption("-i", opt.irradiance, 3),
        boolLine(opt.irradiance, "-i", "irradiance calculation on", "irradiance calculation off"));
    t.add(flagOption("-u", opt.uncorrelated, 3),
          boolLine(opt.uncorrelated, "-u", "uncorrelated Monte Carlo sampling",
                   "correlated quasi-Monte Carlo sampling"));
    t.add(flagOption("-bv", opt.backVisible),
          boolLine(opt.backVisible, "-bv", "back face visibility on", "back face visibility off"));
    DirectOptions& d = opt.direct;
    t.add(valueOption("-dt", d.threshold, nonNegative, kNonNegative),
          realLine(d.threshold, "-dt %f\t\t\t# direct threshold\n"));
    t.add(valueOption("-dc", d.certainty, unitInterval, "must be in [0, 1]"),
          realLine(d.certainty, "-dc %f\t\t\t# direct certainty\n"));
    t.add(valueOption("-dj", d.jitter, unitInterval, "must be in [0, 1]"),
          realLine(d.jitter, "-dj %f\t\t\t# direct jitter\n"));
    t.add(valueOption("-ds", d.sampling, nonNegative, kNonNegative),
          realLine(d.sampling, "-ds %f\t\t\t# direct sampling\n"));
    t.add(valueOption("-dr", d.relays, nonNegative, kNonNegative),
          intLine(d.relays, "-dr %-9d\t\t\t# direct relays\n"));
    t.add(valueOption("-dp", d.pretest, nonNegative, kNonNegative),
          intLine(d.pretest, "-dp %-9d\t\t\t# direct pretest density\n"));
    t.add(flagOption("-dv", d.visibility),
          boolLine(d.visibility, "-dv", "direct visibility on", "direct visibility off"));
    t.add(valueOption("-ss", opt.specular.sampling, nonNegative, kNonNegative),
          realLine(opt.specular.sampling, "-ss %f\t\t\t# specular sampling\n"));
    t.add(valueOption("-st", opt.specular.threshold, nonNegative, kNonNegative),
          realLine(opt.specular.threshold, "-st %f\t\t\t# specular threshold\n"));
}

void addAmbient(OptionTable& t, AmbientOptions& a) {
    t.add(valueOption("-av", a.value), [&a] {
        return formatLine("-av %f %f %f\t# ambient value\n", a.value.r, a.value.g, a.value.b);
    });
    t.add(valueOption("-aw", a.valueWeight, nonNegative, kNonNegative),
          intLine(a.valueWeight, "-aw %-9d\t\t\t# ambient value weight\n"));
    // RADIANCE allows a negative -ab (rtrace.1: use the ambient file without new records);
    // the renderer decides what it means.
    t.add(valueOption("-ab", a.bounces), intLine(a.bounces, "-ab %-9d\t\t\t# ambient bounces\n"));
    t.add(valueOption("-aa", a.accuracy, nonNegative, kNonNegative),
          realLine(a.accuracy, "-aa %f\t\t\t# ambient accuracy\n"));
    t.add(valueOption("-ar", a.resolution, nonNegative, kNonNegative),
          intLine(a.resolution, "-ar %-9d\t\t\t# ambient resolution\n"));
    // Each hemisphere holds its divisions in memory (about 90 bytes each): beyond 1e8 the
    // request is an error here, not an allocation that fails (issue 43).
    t.add(valueOption(
              "-ad", a.divisions, [](long v) { return v >= 0 && v <= kMaxAmbientDivisions; },
              "must be in [0, " + std::to_string(kMaxAmbientDivisions) + "]"),
          intLine(a.divisions, "-ad %-9d\t\t\t# ambient divisions\n"));
    t.add(valueOption("-as", a.supersamples, nonNegative, kNonNegative),
          intLine(a.supersamples, "-as %-9d\t\t\t# ambient super-samples\n"));
    t.add(valueOption("-af", a.file));
    t.add(customOption("-ai", [&a](OptionReader& r) { modifierList(a, true, {r.word()}); }));
    t.add(customOption("-ae", [&a](OptionReader& r) { modifierList(a, false, {r.word()}); }));
    t.add(customOption("-aI", [&a](OptionReader& r) {
        modifierList(a, true, readWordFile(r.word(), "include"));
    }));
    t.add(customOption("-aE", [&a](OptionReader& r) {
        modifierList(a, false, readWordFile(r.word(), "exclude"));
    }));
}

void addMist(OptionTable& t, MistOptions& m) {
    t.add(valueOption("-me", m.extinction), [&m] {
        return formatLine("-me %.2e %.2e %.2e\t# mist extinction coefficient\n", m.extinction.r,
                          m.extinction.g, m.extinction.b);
    });
    t.add(valueOption("-ma", m.albedo), [&m] {
        return formatLine("-ma %f %f %f\t# mist scattering albedo\n", m.albedo.r, m.albedo.g,
                          m.albedo.b);
    });
    t.add(valueOption("-mg", m.eccentricity),
          realLine(m.eccentricity, "-mg %f\t\t\t# mist scattering eccentricity\n"));
    t.add(valueOption("-ms", m.samplingDistance),
          realLine(m.samplingDistance, "-ms %f\t\t\t# mist sampling distance\n"));
}

void addSpectral(OptionTable& t, RenderOptions& opt) {
    t.add(valueOption("-cs", opt.spectralSamples), [&opt] {
        if (opt.spectralSamples <= 3) return std::string();
        return formatLine("-cs %-2d\t\t\t\t# number of spectral bins\n", opt.spectralSamples) +
               formatLine("-cw %3.0f %3.0f\t\t\t# wavelength limits (nm)\n",
                          std::min(opt.wavelengthA, opt.wavelengthB),
                          std::max(opt.wavelengthA, opt.wavelengthB));
    });
    t.add(customOption("-cw", [&opt](OptionReader& r) {
        opt.wavelengthA = r.real();
        opt.wavelengthB = r.real();
    }));
}

void addLimits(OptionTable& t, LimitOptions& l) {
    t.add(valueOption("-lr", l.maxDepth), [&l] {
        return formatLine("-lr %-9d\t\t\t# limit reflection%s\n", l.maxDepth,
                          l.maxDepth <= 0 ? " (Russian roulette)" : "");
    });
    t.add(valueOption("-lw", l.minWeight, nonNegative, kNonNegative),
          realLine(l.minWeight, "-lw %.2e\t\t\t# limit weight\n"));
}

// -ap file [bwidth1 [bwidth2]].
void readPhotonMap(OptionReader& r, RenderOptions& opt) {
    PhotonMapUse use;
    use.file = r.word();
    // RADIANCE compat (pmapopt.c): the following words are bandwidths only if integers.
    if (r.nextIsInteger()) {
        use.bandwidth = int(r.integer());
        r.require(use.bandwidth > 0, "photon lookup bandwidth must be > 0");
        if (r.nextIsInteger()) {
            use.bandwidth2 = int(r.integer());
            r.require(use.bandwidth2 > use.bandwidth,
                      "maximum bandwidth must exceed the minimum (bias compensation)");
        }
    }
    use.edgeAware = opt.photonEdge;
    opt.photonMaps.push_back(use);
    // RADIANCE compat (pmapopt.c): a photon map implies at least one ambient bounce.
    if (opt.ambient.bounces == 0) opt.ambient.bounces = 1;
}

// -ape[+|-]: radphoton's own, so its -defaults line appears only when it is on (the
// listing of RADIANCE's options stays RADIANCE 5.4's).
void addPhotonEdge(OptionTable& t, RenderOptions& opt) {
    OptionSpec s = flagOption("-ape", opt.photonEdge);
    s.read = [&opt, read = s.read](OptionReader& r) {
        read(r);
        for (PhotonMapUse& m : opt.photonMaps) m.edgeAware = opt.photonEdge;
    };
    t.add(std::move(s), [&opt] {
        return opt.photonEdge ? std::string("-ape+\t\t\t\t# photon density edge-aware\n")
                              : std::string();
    });
}

void addPhotonMaps(OptionTable& t, RenderOptions& opt) {
    t.add(customOption("-ap", [&opt](OptionReader& r) { readPhotonMap(r, opt); }));
    addPhotonEdge(t, opt);
    t.add(valueOption(
              "-am", opt.photonMaxRadius, [](double v) { return v > 0; },
              "invalid max photon search radius"),
          [&opt] {
              return formatLine("-am %.1f\t\t\t\t# max photon search radius\n",
                                opt.photonMaxRadius);
          });
    t.add(valueOption(
        "-ac", opt.photonPageSize, [](double v) { return v > 0; },
        "invalid photon cache page size"));
    t.add(customOption("-aC", [&opt](OptionReader& r) {
        const std::optional<uint64_t> n = parseCount(r.word());
        r.require(n && *n > 0, "invalid photon cache size");
        opt.photonCache = *n;
    }));
}

}  // namespace

OptionSpec threadsOption(int& threads) {
    return valueOption(
        "-n", threads, [](long v) { return v >= 1; }, "bad number of processes");
}

OptionSpec warningsOption(bool& warnings) {
    OptionSpec s = flagOption("-w", warnings, 3);
    s.defaults = boolLine(warnings, "-w", "warning messages on", "warning messages off");
    return s;
}

void addRenderOptions(OptionTable& t, RenderOptions& opt) {
    // RADIANCE compat: the order of print_rdefaults (renderopts.c) and printPmapDefaults
    // (pmapopt.c), which is the order of the -defaults lines.
    addFlagsAndDirect(t, opt);
    addAmbient(t, opt.ambient);
    addMist(t, opt.mist);
    addSpectral(t, opt);
    addLimits(t, opt.limits);
    addPhotonMaps(t, opt);
    t.add(threadsOption(opt.threads));
    t.add(valueOption("-e", opt.errorFile));
    t.add(flagOption("-w", opt.warnings, 3));
}

spectral::Sampling spectralSampling(const RenderOptions& opt) {
    auto c = spectral::makeSampling(opt.spectralSamples, opt.wavelengthA, opt.wavelengthB);
    if (!c) throw InputError("unsupported spectral sampling");
    if (!c->tuned) warn("spectral range incompatible with color output");
    return c->sampling;
}

RenderOptions passOptions(const RenderOptions& opt, const spectral::Pass& p) {
    RenderOptions o = opt;
    o.pass = p;
    o.direct.pass = p;
    o.ambient.value = p.ofRgb(opt.ambient.value);
    o.mist.extinction = p.ofRgb(opt.mist.extinction);
    o.mist.albedo = p.ofRgb(opt.mist.albedo);
    for (PhotonMapUse& use : o.photonMaps) use.pass = p;
    // Each pass keeps its own ambient file, its bands in the header.
    if (!o.ambient.file.empty()) o.ambient.file = spectral::passFile(o.ambient.file, p);
    o.ambient.bands = spectral::passLabel(p);
    return o;
}

std::vector<RenderOptions> passOptions(const RenderOptions& opt,
                                       const spectral::Sampling& sampling) {
    std::vector<RenderOptions> out;
    for (const spectral::Pass& p : spectral::passesOf(sampling)) out.push_back(passOptions(opt, p));
    return out;
}

std::string formatRenderDefaults(const RenderOptions& opt) {
    RenderOptions copy = opt;
    OptionTable t;
    addRenderOptions(t, copy);
    return t.formatDefaults();
}

}  // namespace rp::render
