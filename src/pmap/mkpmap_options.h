// mkpmap's command line (RADIANCE mkpmap.1 and photon-map manual 4.5): the options
// struct and its parser. Checks that need the scene (sensor modifiers, ports, sources)
// and the run itself live in mkpmap.h; tracing in trace.h, distribution in distribute.h.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "light/light_sources.h"
#include "pmap/photon.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::pmap {

// One requested map: -apg/-apc/-apv/-apd/-app/-apC file nphotons [bwidth].
struct MapRequest {
    std::string file;
    uint64_t target = 0;  // nphotons
    int bandwidth = 0;    // -app only
    // -apCPD: a contribution map that keeps where each primary left its source
    // (RADIANCE's 3.1kPD variant), so that rcontrib can bin photons by direction.
    bool primaryRays = false;
};

// -api box (xmin ymin zmin xmax ymax zmax).
struct RegionOfInterest {
    Vec3 min, max;
    bool contains(const Vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
};

// mkpmap -aC's default: half the physical memory, in 24-byte photons.
uint64_t defaultMemoryPhotons();

struct MkpmapOptions {
    // Indexed by PhotonMapType; unset = not requested. As RADIANCE (mkpmap.1), a later
    // instance of the same type replaces an earlier one.
    std::array<std::optional<MapRequest>, kNumPhotonMapTypes> maps;

    double preDistrib = 0.25;                // -apD
    int maxPrepass = 4;                      // -apM
    double precompFraction = 0.25;           // -apP
    int64_t seed = 0;                        // -apr
    std::vector<RegionOfInterest> rois;      // -api (cumulative)
    long maxBounce = 5000;                   // -lr / -apm (RADIANCE's PMAP_MAXBOUNCE)
    double maxDistance = 0;                  // -ld, 0 = unlimited
    std::vector<light::PortSpec> portSpecs;  // -apo[+|-|0] mod, -apO[+|-|0] file contents
    std::vector<std::string> sensors;        // -aps, -apS file contents
    // Ambient include (-ai/-aI/-al) or exclude (-ae/-aE) modifiers; mutually exclusive.
    std::vector<std::string> include, exclude;
    bool backVisible = true;        // -bv: RADIANCE's mkpmap default is on (backvis = 1)
    double pdfSamples = 1000;       // -dp
    double partitionSize = 0.01;    // -ds
    std::string diagnosticsFile;    // -e
    bool overwrite = false;         // -fo
    Color mediumAlbedo;             // -ma
    Color mediumExtinction;         // -me
    double mediumEccentricity = 0;  // -mg
    int nproc = 1;                  // -n
    int reportSeconds = 0;          // -t
    // -aC N (a radphoton extension; RADIANCE's rtrace -aC sizes its out-of-core cache):
    // hold about N photons in memory at most while building, all maps together (prepass
    // deposits, collected photons, kd-tree parts). Photons beyond it go to temporary files
    // beside the maps, whose trees are then built externally (kdtree_external.h); the
    // files are the same as when built in memory. Precomputed (-app) and contribution
    // (-apC) maps are always built in memory.
    uint64_t memoryPhotons = defaultMemoryPhotons();
    std::vector<std::string> sceneFiles;  // the octree / scene file(s), last
    // -defaults (-help) or -version: print and exit; parsing stops there and nothing
    // else is checked (RADIANCE mkpmap prints its defaults even without a map).
    bool printDefaults = false, printVersion = false;

    bool wants(PhotonMapType t) const { return maps[size_t(t)].has_value(); }
};

// Parses argv[1..argc-1]. Throws InputError with RADIANCE-like one-line messages
// (without the "mkpmap: " prefix, which the tool adds): unknown option, missing or bad
// value, no photon map requested, -ai with -ae, no scene file. File lists for -apO,
// -apS, -aI/-al and -aE are read here (whitespace separated words).
MkpmapOptions parseMkpmapArgs(int argc, const char* const* argv);

// The -defaults listing, one option a line with the values in `o`, in RADIANCE mkpmap's
// layout ("-apD 0.250000\t\t\t\t# predistribution factor").
std::string formatMkpmapDefaults(const MkpmapOptions& o);

// "500k" -> 500000, "1m" -> 1000000, "2.5M" -> 2500000, "1g" -> 1e9 (RADIANCE
// parseMultiplier); nullopt for anything else or a value that is not a positive count.
std::optional<uint64_t> parsePhotonCount(const std::string& s);

}  // namespace rp::pmap
