// rcontrib's driver loop (RADIANCE rcontrib.c rcontrib(), done_contrib): read rays,
// trace them in parallel batches, add -c of them into a record (averaged; -c 0 sums all
// of them into one record at the end), write records in input order, flush at -x
// boundaries and after zero-direction rays, check the -x*-y count. The tracing function
// is injected so that the loop is tested without a scene.
#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <vector>

#include "render/rcontrib_output.h"
#include "util/cluster.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::render {

// Traces input ray `rayIndex` (0-based position in the input) from `origin` in unit
// `direction` and adds its contributions to `values` (zeroed, one per bin of every
// modifier). `maxDistance`: -ld length, else infinite. Called concurrently.
using ContribTraceFn =
    std::function<void(const Vec3& origin, const Vec3& direction, uint64_t rayIndex,
                       double maxDistance, std::vector<Color>& values)>;

struct RcontribRunSettings {
    char inputFormat = 'a';
    int xres = 0, yres = 0;      // -x -y
    int accumulate = 1;          // -c
    int threads = 1;             // -n
    bool limitDistance = false;  // -ld
    int reportSeconds = 0;       // -t (with -y: progress on `progress`)
    std::ostream* progress = nullptr;
    size_t values = 0;          // bins over all modifiers
    uint64_t skipRecords = 0;   // -r: records the outputs hold already
    std::vector<Color> totals;  // -r with -c 0: what the outputs hold, added to
    size_t batchSize = 0;       // rays per batch; 0: 64 per thread and rank
    // The ranks of an MPI run (null: this process alone). The root reads the input and
    // adds and writes the records; every rank traces a contiguous slice of each batch and
    // sends its rays' values back, so the records are the same as one process's.
    Cluster* cluster = nullptr;
};

struct RcontribRunStats {
    uint64_t rays = 0;     // traced
    uint64_t records = 0;  // written
};

// Throws InputError for bad input (after writing every record before it) and, with -y,
// for input that ends early ("unexpected EOF on input"). `out` is the root's (null on the
// other ranks of a cluster, which read nothing and return empty statistics).
RcontribRunStats runRcontrib(const RcontribRunSettings& settings, std::istream& in,
                             ContribOutput* out, const ContribTraceFn& trace);

}  // namespace rp::render
