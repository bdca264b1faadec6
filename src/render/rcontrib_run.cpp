// rcontrib's batch loop (see rcontrib_run.h).
#include "render/rcontrib_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/rtrace_io.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::render {

namespace {

struct Ray {
    Vec3 origin, dir;
    double maxDistance = HUGE_VAL;
    uint64_t index = 0;
    bool dummy = false;  // zero direction: no contribution, a flush mark
    std::vector<Color> values;
};

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// -t progress (rcontrib.c morays): "<p>% done after <h> hours" every interval.
class Progress {
public:
    Progress(const RcontribRunSettings& s, uint64_t total)
        : s_(s), total_(total), start_(std::chrono::steady_clock::now()), last_(start_) {}
    void update(uint64_t done) {
        if (s_.reportSeconds <= 0 || !s_.progress || total_ == 0) return;
        auto now = std::chrono::steady_clock::now();
        if (now - last_ < std::chrono::seconds(s_.reportSeconds)) return;
        last_ = now;
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.2f%% done after %.3f hours\n",
                      100.0 * double(done) / double(total_),
                      std::chrono::duration<double>(now - start_).count() / 3600);
        *s_.progress << buf << std::flush;
    }

private:
    const RcontribRunSettings& s_;
    uint64_t total_;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace

RcontribRunStats runRcontrib(const RcontribRunSettings& s, std::istream& in, ContribOutput& out,
                             const ContribTraceFn& trace) {
    RcontribRunStats stats;
    const int threads = std::max(1, s.threads);
    // Each ray of a batch holds all its bins until its record is written: many modifiers
    // with fine bins (100 sources x Reinhart MF 4 is 230,000 values, 5.5 MB a ray) get
    // smaller batches, down to one ray per thread.
    constexpr size_t kBatchBytes = size_t(256) << 20;
    const size_t perRay = std::max<size_t>(1, s.values * sizeof(Color));
    const size_t batchSize =
        s.batchSize > 0 ? s.batchSize
                        : std::clamp(kBatchBytes / perRay, size_t(threads), size_t(64) * size_t(threads));
    const uint64_t perRecord = s.accumulate > 1 ? uint64_t(s.accumulate) : 1;
    // RADIANCE compat (rcontrib.c rcinit): with -y the input holds x*y (or y) records of
    // -c rays each; -x alone is the flush interval, -x with -y a picture (no flushing).
    uint64_t remaining = s.yres > 0 ? uint64_t(s.yres) * uint64_t(s.xres > 0 ? s.xres : 1) * perRecord
                                    : 0;
    const bool counted = remaining > 0;
    Progress progress(s, remaining);
    const uint64_t total = remaining;
    long flushEvery = s.yres > 0 && s.xres > 1 ? 0 : s.xres;
    long untilFlush = flushEvery;

    RayReader reader(in, s.inputFormat);
    // -r: the records the outputs hold already are not traced again.
    for (uint64_t k = 0; k < s.skipRecords * perRecord; ++k) {
        InputRay r;
        if (reader.next(r) != RayReader::Status::Ok) throw InputError("unexpected EOF on input");
        if (counted) --remaining;
    }
    uint64_t index = s.skipRecords * perRecord;

    std::vector<Color> sum(s.values);
    if (s.accumulate <= 0 && s.totals.size() == s.values) sum = s.totals;
    int account = s.accumulate;  // rays left in this record
    uint64_t inRecord = 0;
    bool warnedDummy = false, ended = false;
    std::string pendingError;
    tbb::task_arena arena(threads);
    std::vector<Ray> batch;
    auto emit = [&](double scale, bool flush) {
        out.writeRecord(sum, scale, flush);
        std::fill(sum.begin(), sum.end(), Color{});
        ++stats.records;
    };

    while (!ended) {
        batch.clear();
        // A zero-direction ray ends the batch: a program driving rcontrib through a pipe
        // waits for the flushed record before it sends more.
        while (batch.size() < batchSize) {
            if (counted && remaining == 0) { ended = true; break; }
            InputRay in;
            RayReader::Status st = reader.next(in);
            if (st == RayReader::Status::End) { ended = true; break; }
            if (st == RayReader::Status::Bad) { pendingError = reader.error(); ended = true; break; }
            if (counted) --remaining;
            Ray r;
            r.index = index++;
            r.origin = in.origin;
            const double len = length(in.direction);
            if (!finite(in.origin) || !std::isfinite(len))
                throw InputError("non-finite ray input (record " + std::to_string(r.index + 1) + ")");
            r.dummy = len == 0;
            if (r.dummy && s.accumulate <= 0) {
                // RADIANCE compat (rcontrib.c): no flushing while summing everything.
                if (!warnedDummy) warn("dummy ray(s) ignored during accumulation");
                warnedDummy = true;
                continue;
            }
            if (!r.dummy) r.dir = in.direction / len;
            if (s.limitDistance && !r.dummy) r.maxDistance = len;
            const bool stop = r.dummy;
            batch.push_back(std::move(r));
            if (stop) break;
        }

        arena.execute([&] {
            tbb::parallel_for(size_t(0), batch.size(), [&](size_t k) {
                Ray& r = batch[k];
                r.values.assign(s.values, Color{});
                if (!r.dummy) trace(r.origin, r.dir, r.index, r.maxDistance, r.values);
            });
        });
        for (Ray& r : batch) {
            for (size_t v = 0; v < s.values; ++v) sum[v] += r.values[v];
            ++inRecord;
            if (!r.dummy) ++stats.rays;
            // rcontrib.c done_contrib: a record per -c rays (none until the end with -c 0).
            bool flushMark = r.dummy && (s.yres <= 0 || s.xres <= 1);
            if (flushMark) untilFlush = 1;
            if (account > 0 && --account == 0) {
                --untilFlush;
                const bool flush = untilFlush == 0;
                if (flush) untilFlush = flushEvery;
                emit(perRecord > 1 ? 1.0 / double(perRecord) : 1.0, flush);
                account = s.accumulate;
                inRecord = 0;
            }
            progress.update(total - remaining);
        }
    }
    // The last record: the sum of everything (-c 0) or what a short -c record holds.
    if (s.accumulate <= 0) {
        emit(1.0, true);
    } else if (inRecord > 0) {
        warn("partial accumulation in final record");
        emit(inRecord > 1 ? 1.0 / double(inRecord) : 1.0, true);
    }
    out.close();
    if (!pendingError.empty()) throw InputError(pendingError);
    if (counted && remaining > 0) throw InputError("unexpected EOF on input");
    return stats;
}

}  // namespace rp::render
