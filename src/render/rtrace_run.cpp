// rtrace's batch loop (see rtrace_run.h).
#include "render/rtrace_run.h"

#include <cmath>
#include <string>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "util/error.h"
#include "util/warnings.h"

namespace rp::render {

namespace {

struct Record {
    InputRay ray;
    double maxDistance = HUGE_VAL;
    uint64_t index = 0;
    bool bogus = false;
    bool flushAfter = false;
    std::string text;  // formatted output
};

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

RtraceRunStats runRtrace(const RtraceRunSettings& s, std::istream& in, std::ostream& out,
                         const RayWriter& writer, const RayTraceFn& trace) {
    RtraceRunStats stats;
    const int threads = std::max(1, s.threads);
    const size_t batchSize = s.batchSize > 0 ? s.batchSize : size_t(64) * size_t(threads);
    // RADIANCE compat (rtrace.c rtrace): with -x and -y exactly x*y records are read
    // (-y alone: y records); -x alone is only the flush interval.
    uint64_t remaining = s.xres > 1 ? uint64_t(s.xres) * uint64_t(std::max(0, s.yres))
                                    : uint64_t(std::max(0, s.yres));
    const bool counted = remaining > 0;
    if (s.xres > 0 && s.yres > 0) {
        out << resolutionLine(s.xres, s.yres);
        out.flush();
    }
    RayReader reader(in, s.inputFormat);
    long sinceFlush = 0;
    uint64_t index = 0;
    bool ended = false;
    std::string pendingError;
    const bool wantTree = writer.spec().wantsTree();
    tbb::task_arena arena(threads);
    std::vector<Record> batch;
    batch.reserve(batchSize);

    while (!ended) {
        batch.clear();
        // Read until the batch is full, a flush point or the end: a program driving
        // rtrace through a pipe waits for the flushed results before sending more.
        while (batch.size() < batchSize) {
            if (counted && remaining == 0) { ended = true; break; }
            Record r;
            RayReader::Status st = reader.next(r.ray);
            if (st == RayReader::Status::End) { ended = true; break; }
            if (st == RayReader::Status::Bad) { pendingError = reader.error(); ended = true; break; }
            r.index = index++;
            if (counted) --remaining;
            const double len = std::sqrt(r.ray.direction.x * r.ray.direction.x +
                                         r.ray.direction.y * r.ray.direction.y +
                                         r.ray.direction.z * r.ray.direction.z);
            if (!finite(r.ray.origin) || !finite(r.ray.direction) || !std::isfinite(len)) {
                if (stats.nonFinite++ == 0)
                    warn("non-finite ray input (record " + std::to_string(r.index + 1) +
                         "): bogus record written; further ones are not reported");
                r.bogus = true;
            } else if (len == 0) {
                r.bogus = true;
            } else {
                r.ray.direction = r.ray.direction / len;
                if (s.limitDistance) r.maxDistance = len;
            }
            // RADIANCE compat (rtrace.c): a zero direction flushes when -x is 0 or 1 or at
            // the -x boundary; other rays flush at the -x boundary.
            ++sinceFlush;
            if (r.bogus) {
                ++stats.bogus;
                if (s.xres <= 1 || sinceFlush >= s.xres) r.flushAfter = true;
            } else if (s.xres > 0 && sinceFlush >= s.xres) {
                r.flushAfter = true;
            }
            if (r.flushAfter) sinceFlush = 0;
            const bool stop = r.flushAfter;
            batch.push_back(std::move(r));
            if (stop) break;
        }

        arena.execute([&] {
            tbb::parallel_for(size_t(0), batch.size(), [&](size_t k) {
                Record& r = batch[k];
                if (r.bogus) {
                    writer.writeBogus(r.text);
                    return;
                }
                std::vector<TracedRay> tree;
                RayResult res = trace(r.ray.origin, r.ray.direction, r.index,
                                      wantTree ? &tree : nullptr, r.maxDistance);
                writer.write(r.text, res, wantTree ? &tree : nullptr);
            });
        });
        for (const Record& r : batch) {
            if (!r.bogus) ++stats.rays;
            out << r.text;
            if (r.flushAfter) out.flush();
        }
        if (!out) throw InputError("write error on output");
    }
    out.flush();
    if (!pendingError.empty()) throw InputError(pendingError);
    if (counted && remaining > 0) throw InputError("unexpected EOF on input");
    return stats;
}

}  // namespace rp::render
