// mkpmap's work as a library call: check the request, load the scene, find sources and
// ports, distribute photons (distribute.h), build each photon map and save it with the
// command line in its header. Option parsing is mkpmap_options.h; the tool's main only
// maps errors to exit codes.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "pmap/mkpmap_options.h"
#include "pmap/photon.h"
#include "scene/reader.h"
#include "util/cluster.h"

namespace rp::pmap {

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
MkpmapReport runMkpmap(const MkpmapOptions& options, const std::string& commandLine,
                       std::ostream& diag, const LoadOptions& load = {},
                       Cluster* cluster = nullptr);

}  // namespace rp::pmap
