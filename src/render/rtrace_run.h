// rtrace's driver loop (RADIANCE rtrace.c rtrace()): read rays in batches, trace each batch
// in parallel, write results in input order, flush at -x boundaries and after bogus records,
// check the -x*-y count. The tracing function is injected so that the loop is tested
// without a scene; tools/rtrace.cpp passes one that calls Renderer.
#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <ostream>
#include <span>
#include <vector>

#include "render/renderer.h"
#include "render/rtrace_io.h"
#include "util/cluster.h"
#include "util/spectrum.h"

namespace rp::render {

// Traces one input ray. `direction` is unit length; `rayIndex` is the record's 0-based
// position in the input (bogus records count), so results do not depend on threads.
// `tree` is non-null when the output wants the ray tree. `maxDistance`: with -ld the
// length of the direction as given (nothing beyond is seen), else infinite. Called
// concurrently.
using RayTraceFn =
    std::function<RayResult(const Vec3& origin, const Vec3& direction, uint64_t rayIndex,
                            std::vector<TracedRay>* tree, double maxDistance)>;

struct RtraceRunSettings {
    char inputFormat = 'a';
    int xres = 0, yres = 0;         // -x -y
    int threads = 1;                // -n
    bool limitDistance = false;     // -ld: rays end at the length of their direction
    bool paddedResolution = false;  // the resolution line as RADIANCE 6 writes it
    size_t batchSize = 0;  // rays per batch; 0: 64 per thread and rank (tests use small values)
    // The ranks of an MPI run (null: this process alone). The root reads the input and
    // writes the output; every rank traces a contiguous slice of each batch, so the
    // output is the same as one process's.
    Cluster* cluster = nullptr;
};

struct RtraceRunStats {
    uint64_t rays = 0;   // traced
    uint64_t bogus = 0;  // zero-direction or non-finite records
    uint64_t nonFinite = 0;
};

// Writes the resolution line first when both -x and -y are given (on the root; the other
// ranks of a cluster read and write nothing and return empty statistics). Throws InputError for bad
// input (after writing and flushing every result before it) and, with -x and -y, for input
// that ends before x*y rays ("unexpected EOF on input").
RtraceRunStats runRtrace(const RtraceRunSettings& settings, std::istream& in, std::ostream& out,
                         const RayWriter& writer, const RayTraceFn& trace);
// The same for the passes of a spectral rendering (one per pass, `bands`: passesOf the
// sampling): each batch of rays is traced pass after pass and gathered band by band.
RtraceRunStats runRtrace(const RtraceRunSettings& settings, std::istream& in, std::ostream& out,
                         const RayWriter& writer, std::span<const RayTraceFn> passes,
                         std::span<const spectral::Pass> bands);

}  // namespace rp::render
