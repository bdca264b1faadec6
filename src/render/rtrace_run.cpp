// rtrace's batch loop (see rtrace_run.h).
#include "render/rtrace_run.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <string>

#include "render/cluster_batch.h"
#include "render/spectral_passes.h"
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

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The input side of the loop (on the root): records, -x/-y counting, flush points.
class RayInput {
public:
    RayInput(const RtraceRunSettings& s, std::istream& in, RtraceRunStats& stats)
        : s_(s), reader_(in, s.inputFormat), stats_(stats) {
        // RADIANCE compat (rtrace.c rtrace): with -x and -y exactly x*y records are read
        // (-y alone: y records); -x alone is only the flush interval.
        remaining_ = s.xres > 1 ? uint64_t(s.xres) * uint64_t(std::max(0, s.yres))
                                : uint64_t(std::max(0, s.yres));
        counted_ = remaining_ > 0;
    }

    // Reads until the batch is full, a flush point or the end (a program driving rtrace
    // through a pipe waits for the flushed results before sending more). False at the end.
    bool fill(std::vector<Record>& batch, size_t batchSize) {
        while (batch.size() < batchSize) {
            if (counted_ && remaining_ == 0) return false;
            Record r;
            RayReader::Status st = reader_.next(r.ray);
            if (st == RayReader::Status::End) return false;
            if (st == RayReader::Status::Bad) {
                pendingError_ = reader_.error();
                return false;
            }
            r.index = index_++;
            if (counted_) --remaining_;
            classify(r);
            const bool stop = r.flushAfter;
            batch.push_back(std::move(r));
            if (stop) break;
        }
        return true;
    }

    // Bad input met (after the rays before it), or short input with -x and -y.
    void check() const {
        if (!pendingError_.empty()) throw InputError(pendingError_);
        if (counted_ && remaining_ > 0) throw InputError("unexpected EOF on input");
    }

private:
    void classify(Record& r) {
        const double len = std::sqrt(r.ray.direction.x * r.ray.direction.x +
                                     r.ray.direction.y * r.ray.direction.y +
                                     r.ray.direction.z * r.ray.direction.z);
        if (!finite(r.ray.origin) || !finite(r.ray.direction) || !std::isfinite(len)) {
            if (stats_.nonFinite++ == 0)
                warn("non-finite ray input (record " + std::to_string(r.index + 1) +
                     "): bogus record written; further ones are not reported");
            r.bogus = true;
        } else if (len == 0) {
            r.bogus = true;
        } else {
            r.ray.direction = r.ray.direction / len;
            if (s_.limitDistance) r.maxDistance = len;
        }
        // RADIANCE compat (rtrace.c): a zero direction flushes when -x is 0 or 1 or at
        // the -x boundary; other rays flush at the -x boundary.
        ++sinceFlush_;
        if (r.bogus) {
            ++stats_.bogus;
            if (s_.xres <= 1 || sinceFlush_ >= s_.xres) r.flushAfter = true;
        } else if (s_.xres > 0 && sinceFlush_ >= s_.xres) {
            r.flushAfter = true;
        }
        if (r.flushAfter) sinceFlush_ = 0;
    }

    const RtraceRunSettings& s_;
    RayReader reader_;
    RtraceRunStats& stats_;
    uint64_t remaining_ = 0, index_ = 0;
    bool counted_ = false;
    long sinceFlush_ = 0;
    std::string pendingError_;
};

// What a rank needs of a record to trace it, and what it sends back (cluster_batch.h).
struct RecordCodec {
    static void putRay(ByteWriter& w, const Record& r) {
        w.put(r.ray);
        w.put(r.maxDistance);
        w.put(r.index);
        w.put(r.bogus);
    }
    static void getRay(ByteReader& rd, Record& r) {
        r.ray = rd.get<InputRay>();
        r.maxDistance = rd.get<double>();
        r.index = rd.get<uint64_t>();
        r.bogus = rd.get<bool>();
    }
    static void putResult(ByteWriter& w, const Record& r) { w.putString(r.text); }
    static void getResult(ByteReader& rd, Record& r) { r.text = rd.getString(); }
};

// A spectral rendering's passes one after another over the batch, then each ray's results
// gathered band by band (mergePasses, mergeTrees). Pass after pass rather than ray by ray:
// each pass's photon maps and caches stay warm (-cs 9 on bench/spectral_cost.sh's room,
// 1000 points: 0.89 of the time ray by ray, 3.1 times RGB).
void tracePassMajor(std::vector<Record>& batch, const Slice& mine,
                    std::span<const RayTraceFn> passes, std::span<const spectral::Pass> bands,
                    const RayWriter& writer, bool wantTree, tbb::task_arena& arena) {
    const size_t n = mine.end - mine.begin;
    std::vector<std::vector<RayResult>> results(passes.size(), std::vector<RayResult>(n));
    std::vector<std::vector<std::vector<TracedRay>>> trees(wantTree ? passes.size() : 0,
                                                           std::vector<std::vector<TracedRay>>(n));
    arena.execute([&] {
        for (size_t p = 0; p < passes.size(); ++p)
            tbb::parallel_for(mine.begin, mine.end, [&](size_t k) {
                const Record& r = batch[k];
                if (r.bogus) return;
                results[p][k - mine.begin] =
                    passes[p](r.ray.origin, r.ray.direction, r.index,
                              wantTree ? &trees[p][k - mine.begin] : nullptr, r.maxDistance);
            });
        tbb::parallel_for(mine.begin, mine.end, [&](size_t k) {
            Record& r = batch[k];
            if (r.bogus) {
                writer.writeBogus(r.text);
                return;
            }
            std::vector<RayResult> perPass;
            std::vector<std::vector<TracedRay>> perPassTrees;
            for (size_t p = 0; p < passes.size(); ++p) {
                perPass.push_back(std::move(results[p][k - mine.begin]));
                if (wantTree) perPassTrees.push_back(std::move(trees[p][k - mine.begin]));
            }
            std::vector<TracedRay> tree;
            if (wantTree) tree = mergeTrees(perPassTrees, bands);
            writer.write(r.text, mergePasses(perPass, bands), wantTree ? &tree : nullptr);
        });
    });
}

}  // namespace

RtraceRunStats runRtrace(const RtraceRunSettings& s, std::istream& in, std::ostream& out,
                         const RayWriter& writer, const RayTraceFn& trace) {
    return runRtrace(s, in, out, writer, std::span<const RayTraceFn>(&trace, 1), {});
}

RtraceRunStats runRtrace(const RtraceRunSettings& s, std::istream& in, std::ostream& out,
                         const RayWriter& writer, std::span<const RayTraceFn> passes,
                         std::span<const spectral::Pass> bands) {
    const RayTraceFn& trace = passes[0];
    RtraceRunStats stats;
    const int threads = std::max(1, s.threads);
    const BatchRole role(s.cluster);
    const size_t batchSize =
        s.batchSize > 0 ? s.batchSize : size_t(64) * size_t(threads) * size_t(role.ranks());
    if (role.root() && s.xres > 0 && s.yres > 0) {
        out << resolutionLine(s.xres, s.yres, s.paddedResolution);
        out.flush();
    }
    RayInput input(s, in, stats);
    const bool wantTree = writer.spec().wantsTree();
    tbb::task_arena arena(threads);
    std::vector<Record> batch;
    batch.reserve(batchSize);
    // An input stream tied to the output (std::cin to std::cout) flushes it before every
    // number read: a tenth of a run of bare photon lookups. It is untied for the run and
    // the output flushed once before each batch is read instead, which delivers every
    // finished result before rtrace may wait for input, as the tie did.
    std::ostream* const tied = in.tie(nullptr);
    struct Retie {
        std::istream& in;
        std::ostream* tied;
        ~Retie() { in.tie(tied); }
    } retie{in, tied};
    for (bool more = true; more;) {
        batch.clear();
        if (tied) tied->flush();
        if (role.root()) more = input.fill(batch, batchSize);
        more = role.share<RecordCodec>(batch, more);
        const Slice mine = role.slice(batch.size());
        if (passes.size() > 1)
            tracePassMajor(batch, mine, passes, bands, writer, wantTree, arena);
        else
            arena.execute([&] {
                tbb::parallel_for(mine.begin, mine.end, [&](size_t k) {
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
        role.collect<RecordCodec>(batch, mine);
        if (!role.root()) continue;
        for (const Record& r : batch) {
            if (!r.bogus) ++stats.rays;
            out << r.text;
            if (r.flushAfter) out.flush();
        }
        if (!out) throw InputError("write error on output");
    }
    if (!role.root()) return stats;
    out.flush();
    input.check();
    return stats;
}

}  // namespace rp::render
