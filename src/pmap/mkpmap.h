// mkpmap's work as a library call: check the request, load the scene, find sources and
// ports, distribute photons (distribute.h), build each photon map and save it with the
// command line in its header; mkpmap's options struct and its parser (mkpmap_options.cpp,
// an option table of util/options.h). The tool's main only maps errors to exit codes.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

#include "pmap/contrib_bins.h"
#include "pmap/mkpmap_options.h"
#include "pmap/pass_settings.h"
#include "pmap/photon.h"
#include "pmap/trace.h"
#include "scene/reader.h"
#include "util/cluster.h"

namespace rp::pmap {

struct MkpmapOptions {
    // Indexed by PhotonMapType; unset = not requested. As RADIANCE (mkpmap.1), a later
    // instance of the same type replaces an earlier one.
    std::array<std::optional<MapRequest>, kNumPhotonMapTypes> maps;

    // -apD -apM -apr -n -t: what every photon pass reads (distribution, contribution
    // photons, precomputation), handed to each as this one struct.
    PassSettings pass;
    double precompFraction = 0.25;  // -apP
    // Precomputed contribution maps (-apC file n bwidth [comp] with -m/-M; the
    // development branch's precomp_contrib.h): rcontrib's binning options -m -M -p -b -bn,
    // -f, -e with an assignment (otherwise RADIANCE's diagnostics file), and -V.
    std::vector<ContribModifier> contribModifiers;
    std::vector<CalcDefinition> contribDefinitions;
    bool contributions = false;
    bool precomputedContrib() const { return !contribModifiers.empty(); }
    // What the tracer reads, parsed straight into its settings (trace.h): -bv (on, as
    // RADIANCE's backvis = 1), -lr/-apm, -ld, -api (cumulative), -aps/-apS, ambient
    // include (-ai/-aI/-al) or exclude (-ae/-aE), mutually exclusive, and the global
    // medium -me -ma -mg. Which maps it fills follows from `maps`.
    TraceSettings trace;
    std::vector<light::PortSpec> portSpecs;  // -apo[+|-|0] mod, -apO[+|-|0] file contents
    // -apE[+|-] (issue 48; off as in RADIANCE): ports emit the light of the surfaces they
    // see outside as well as the sources (light/emitter.h PortExterior).
    bool portExterior = false;
    double pdfSamples = 1000;     // -dp
    double partitionSize = 0.01;  // -ds
    std::string diagnosticsFile;  // -e
    bool overwrite = false;       // -fo
    // -aC N (a radphoton extension; RADIANCE's rtrace -aC sizes its out-of-core cache):
    // hold about N photons in memory at most while building, all maps together (prepass
    // deposits, collected photons, kd-tree parts). Photons beyond it go to temporary files
    // beside the maps, whose trees are then built externally (kdtree_external.h); the
    // files are the same as when built in memory. Precomputed (-app) and contribution
    // (-apC) maps are always built in memory.
    uint64_t memoryPhotons = defaultMemoryPhotons();
    // -cs -cw (RADIANCE 6's spectral sampling; issue 50): more than 3 samples make a
    // spectral map set, one file per rendering pass (photon_map.h MapBands).
    int spectralSamples = 3;
    double wavelengthA = 380, wavelengthB = 780;
    std::vector<std::string> sceneFiles;  // the octree / scene file(s), last
    // -defaults (-help) or -version: print and exit; parsing stops there and nothing
    // else is checked (RADIANCE mkpmap prints its defaults even without a map).
    bool printDefaults = false, printVersion = false;

    bool wants(PhotonMapType t) const { return maps[size_t(t)].has_value(); }
};

// Parses argv[1..argc-1] with mkpmap's option table (util/options.h). Throws InputError with
// RADIANCE-like one-line messages (without the "mkpmap: " prefix, which the tool adds): unknown
// option, missing or bad value, no photon map requested, -ai with -ae, no scene file. File lists
// for -apO, -apS, -aI/-al and -aE are read here (whitespace separated words).
MkpmapOptions parseMkpmapArgs(int argc, const char* const* argv);

// The -defaults listing, one option a line with the values in `o`, in RADIANCE mkpmap's
// layout ("-apD 0.250000\t\t\t\t# predistribution factor").
std::string formatMkpmapDefaults(const MkpmapOptions& o);

struct MkpmapReport {
    std::array<uint64_t, kNumPhotonMapTypes> stored{};  // photons per saved map
    uint64_t emitted = 0;
    uint64_t prepassEmitted = 0;
    int prepasses = 0;
    long runaways = 0;
    double traceSeconds = 0;    // prepass + main pass
    double buildSeconds = 0;    // kd-trees and files of all maps (wall time)
    double storingSeconds = 0;  // of traceSeconds, storing on the root (distribute.h)
};

// -app maps are distributed as global maps, then precomputed (precomp.h); -apC uses its
// own per-source distribution (contrib.h) and ignores other maps with a warning.
// Throws InputError (one line, no program prefix) for: an existing output file without
// -fo (checked before anything is traced), two maps written to one file, a volume map
// (-apv) without a medium, scene errors, no light sources, bad ports/sensors,
// and distribution failure (manual 4.2). Progress (-t) and the summary go to `diag`.
// `load` carries the scene reader's command hook (tools pass the built-in generators).
// `cluster`: the ranks of an MPI run (null: this process alone). Every rank calls this
// with the same options and traces its share of the photons (chunk_stream.h); the root
// builds and writes the maps, which are the same bit for bit for any number of ranks,
// and reports. The other ranks return an empty report.
// `exterior` makes -apE's PortExterior for the loaded scene in a pass's bands (the classic
// calculation sits above this module: tools pass render::portExterior); -apE without it
// is an InputError.
using PortExteriorFactory =
    std::function<light::PortExterior(const Scene&, const SceneGeometry&, const spectral::Pass&)>;
MkpmapReport runMkpmap(const MkpmapOptions& options, const std::string& commandLine,
                       std::ostream& diag, const LoadOptions& load = {}, Cluster* cluster = nullptr,
                       const PortExteriorFactory& exterior = {});

}  // namespace rp::pmap
