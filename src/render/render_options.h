// The options rtrace, rpict (and later rcontrib and rvu) share: RADIANCE's -d (direct),
// -s (specular), -l (limits), -a (ambient), -b, -i/-I, -u, -e, -w and -ap families, with
// RADIANCE 5.4's defaults and spellings (doc/man/rtrace.1). Tool-specific options (rtrace's
// -o/-f/-h/-x/-y, rpict's -x/-y/-p/-v/-o) are added by each tool to its option table
// (util/options.h); what is common lives here.
#pragma once

#include <tbb/global_control.h>

#include <string>
#include <vector>

#include "util/color.h"
#include "util/options.h"
#include "util/spectrum.h"

namespace rp::render {

struct DirectOptions {
    double threshold = 0.03;  // -dt: relative contribution below which sources are not tested
    double certainty = 0.75;  // -dc: 1 = test every source, 0 = trust the estimates
    double jitter = 0;        // -dj: 0 = sample cell centres, 1 = anywhere in the cell
    double sampling = 0.2;    // -ds: source size over distance per sample (0 = no subdivision)
    int relays = 2;           // -dr: virtual source (mirror) relay levels
    int pretest = 512;        // -dp: virtual source pretest density (samples per steradian)
    bool visibility = true;   // -dv: light sources visible to primary/specular rays
    spectral::Pass pass;      // the bands the sources' colours are rendered in
};

struct SpecularOptions {
    double sampling = 1.0;    // -ss: rough specular (0 = mirror direction, >1.5 several)
    double threshold = 0.15;  // -st: rough specular below this goes to the ambient calc
};

struct LimitOptions {
    int maxDepth = -10;       // -lr: < 0 means Russian roulette past |maxDepth| (RADIANCE 5)
    double minWeight = 2e-3;  // -lw: rays of smaller weight are not traced (roulette if lr<0)
};

// The largest -ad: one hemisphere's divisions live in memory together.
constexpr int kMaxAmbientDivisions = 100'000'000;

struct AmbientOptions {
    Color value;             // -av: ambient value for rays past the last bounce
    int valueWeight = 0;     // -aw: weight of -av in the running average (0 = fixed)
    int bounces = 0;         // -ab
    double accuracy = 0.1;   // -aa: 0 turns the irradiance cache off
    int resolution = 256;    // -ar: scene size / ar = minimum record spacing
    int divisions = 1024;    // -ad: hemisphere samples per irradiance computation
    int supersamples = 512;  // -as: extra samples where the divisions vary most
    std::string file;        // -af: ambient file (records kept across runs)
    std::string bands;       // a spectral pass's label (spectral::passLabel; "" for RGB)
    // -ae/-ai (and -aE/-aI from files): modifiers excluded from / the only ones included
    // in the cache (others get -av). Order matters as in RADIANCE: the last of -ae/-ai
    // decides the mode; the list accumulates.
    std::vector<std::string> modifiers;
    bool includeList = false;  // true: `modifiers` lists the included ones (-ai/-aI)
};

// -ap file [bwidth1 [bwidth2]]: one photon map to use while rendering (issue 6).
struct PhotonMapUse {
    std::string file;
    int bandwidth = 0;   // 0: the default for the map's type (a warning is given)
    int bandwidth2 = 0;  // > bandwidth: bias compensation between the two
    // -ape (RenderOptions::photonEdge), copied to every map whichever of -ap and -ape
    // comes first, so that the maps' user (render/photon_lighting.h) needs nothing else.
    bool edgeAware = false;
    // The rendering pass it serves (passOptions): with -cs above 3 the map is that pass's
    // file of a spectral map set (pmap/photon_map.h MapBands).
    spectral::Pass pass{};
};

// -me/-ma/-mg/-ms: the global participating medium and the sampling distance of light
// scattered into rays (RADIANCE's mist options).
struct MistOptions {
    Color extinction;             // -me: extinction coefficient per unit length
    Color albedo;                 // -ma: scattering albedo
    double eccentricity = 0;      // -mg: Henyey-Greenstein g
    double samplingDistance = 0;  // -ms
    bool any() const {
        return !extinction.isBlack() || !albedo.isBlack() || eccentricity != 0 ||
               samplingDistance != 0;
    }
};

struct RenderOptions {
    DirectOptions direct;
    SpecularOptions specular;
    LimitOptions limits;
    AmbientOptions ambient;
    MistOptions mist;
    std::vector<PhotonMapUse> photonMaps;  // -ap (repeatable)
    double photonMaxRadius = 0;            // -am: fixed maximum search radius, 0 = automatic
    // -ape: edge-aware surface photon density estimates (radphoton's own; pmap/
    // edge_estimate.h); off: RADIANCE's.
    bool photonEdge = false;
    // Out-of-core photon maps (RADIANCE's OOC build, manual 3.2; pmap/photon_store.h):
    double photonPageSize = 4;  // -ac: cache page size, x the bandwidth
    uint64_t photonCache = 0;   // -aC: photons cached per thread; 0 = by memory
    bool backVisible = true;    // -bv
    bool irradiance = false;    // -i: compute irradiance at surfaces hit
    // -u: uncorrelated (random) sampling. RADIANCE compat: rpict's default is off; rtrace
    // (rtmain.c) turns it on before parsing, and so does our rtrace (rtrace_options.cpp).
    bool uncorrelated = false;
    // rtrace -o...T: the ray tree shows every shadow ray tested, not only those passed on
    // by a surface (RADIANCE's SFOLLOW; direct.h ShadowTree).
    bool treeShadowRays = false;
    int threads = 1;        // -n
    std::string errorFile;  // -e: diagnostics go here instead of stderr
    bool warnings = true;   // -w
    // rcontrib: -ap maps must be contribution maps (PhotonLighting), not other types, and
    // their lookups only see photons of sources whose light material is one of
    // `contribModifiers` (RADIANCE pmapkdt.c: the tracked modifiers).
    bool contributions = false;
    std::vector<std::string> contribModifiers;
    // -cs -cw: RADIANCE 6's spectral sampling as given (spectralSampling() checks it).
    int spectralSamples = 3;
    double wavelengthA = 380, wavelengthB = 780;
    // The bands this renderer traces (passOptions): RGB unless rendering a spectrum.
    spectral::Pass pass;
};

// The spectral sampling of -cs -cw (RADIANCE 6's setspectrsamp): InputError for one it
// rejects ("unsupported spectral sampling"), a warning for a range that misses a
// primary's peak.
spectral::Sampling spectralSampling(const RenderOptions& opt);
// The options of each rendering pass of `sampling` (spectrum.h Pass): the pass set for
// the renderer and the direct calculation, and the RGB colours given as options (-av,
// -me, -ma) as that pass renders them.
std::vector<RenderOptions> passOptions(const RenderOptions& opt,
                                       const spectral::Sampling& sampling);
// The same for one pass.
RenderOptions passOptions(const RenderOptions& opt, const spectral::Pass& pass);

// Adds the shared options to `table`, bound to `opt`, each with its line of RADIANCE's
// `rtrace -defaults` (print_rdefaults in renderopts.c, printPmapDefaults in pmapopt.c:
// "-dt 0.030000\t\t\t# direct threshold", same order and formats). Options the tool
// added before keep their place (rcontrib's -e is not the error file). Boolean options
// follow RADIANCE: "-bv" toggles, "-bv+"/"-bv-" set. Errors (InputError, no location, the
// table's messages): a missing or non-numeric value, an out-of-range one (negative -ad,
// -n < 1, ...). -aE/-aI files are read when parsed (one modifier per word); a missing one
// is an InputError naming it. -ap takes the following words as bandwidths only when they
// are integers; as RADIANCE (pmapopt.c), asking for a photon map with -ab 0 sets -ab 1.
// -n, -e, -w and the mist options -me -ma -mg -ms are here too; -n and -w have no
// -defaults line here, as each tool prints them in its own place (threadsOption,
// warningsOption).
void addRenderOptions(OptionTable& table, RenderOptions& opt);

// -n (threads, >= 1) without a -defaults line, and -w with RADIANCE's line.
OptionSpec threadsOption(int& threads);
OptionSpec warningsOption(bool& warnings);

// The -defaults lines of addRenderOptions alone, reflecting `opt`.
std::string formatRenderDefaults(const RenderOptions& opt);

// -n bounds every phase of a renderer, map loading and indexing included, not only the
// rendering: -n 1 uses one core, as RADIANCE's single process does (and as batch scripts
// that run one rtrace per core expect). Keep the result alive for the whole run.
inline tbb::global_control threadLimit(const RenderOptions& o) {
    return tbb::global_control(tbb::global_control::max_allowed_parallelism,
                               static_cast<size_t>(o.threads > 1 ? o.threads : 1));
}

}  // namespace rp::render
