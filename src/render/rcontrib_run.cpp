// rcontrib's batch loop (see rcontrib_run.h).
#include "render/rcontrib_run.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "render/cluster_batch.h"
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

// The input: rays read into batches, -y counting, -r skipping (rcontrib.c rcontrib()).
class RayInput {
public:
    RayInput(const RcontribRunSettings& s, std::istream& in)
        : s_(s),
          reader_(in, s.inputFormat),
          perRecord_(s.accumulate > 1 ? uint64_t(s.accumulate) : 1) {
        // RADIANCE compat (rcontrib.c rcinit): with -y the input holds x*y (or y) records
        // of -c rays each.
        remaining_ =
            s.yres > 0 ? uint64_t(s.yres) * uint64_t(s.xres > 0 ? s.xres : 1) * perRecord_ : 0;
        counted_ = remaining_ > 0;
        total_ = remaining_;
        // -r: the records the outputs hold already are not traced again.
        for (uint64_t k = 0; k < s.skipRecords * perRecord_; ++k) {
            InputRay r;
            if (reader_.next(r) != RayReader::Status::Ok)
                throw InputError("unexpected EOF on input");
            if (counted_) --remaining_;
        }
        index_ = s.skipRecords * perRecord_;
    }

    // Fills `batch` with up to `size` rays; false once the input is over. A zero-direction
    // ray ends the batch: a program driving rcontrib through a pipe waits for the flushed
    // record before it sends more.
    bool fill(std::vector<Ray>& batch, size_t size) {
        batch.clear();
        while (batch.size() < size) {
            if (counted_ && remaining_ == 0) return false;
            InputRay in;
            const RayReader::Status st = reader_.next(in);
            if (st == RayReader::Status::End) return false;
            if (st == RayReader::Status::Bad) {
                error_ = reader_.error();
                return false;
            }
            if (counted_) --remaining_;
            Ray r;
            r.index = index_++;
            r.origin = in.origin;
            const double len = length(in.direction);
            if (!finite(in.origin) || !std::isfinite(len))
                throw InputError("non-finite ray input (record " + std::to_string(r.index + 1) +
                                 ")");
            r.dummy = len == 0;
            if (r.dummy && s_.accumulate <= 0) {
                // RADIANCE compat (rcontrib.c): no flushing while summing everything.
                if (!warnedDummy_) warn("dummy ray(s) ignored during accumulation");
                warnedDummy_ = true;
                continue;
            }
            if (!r.dummy) r.dir = in.direction / len;
            if (s_.limitDistance && !r.dummy) r.maxDistance = len;
            batch.push_back(std::move(r));
            if (batch.back().dummy) break;
        }
        return true;
    }

    // Bad input met (after the rays before it), or short input with -y.
    void check() const {
        if (!error_.empty()) throw InputError(error_);
        if (counted_ && remaining_ > 0) throw InputError("unexpected EOF on input");
    }
    uint64_t total() const { return total_; }
    uint64_t done() const { return total_ - remaining_; }

private:
    const RcontribRunSettings& s_;
    RayReader reader_;
    uint64_t perRecord_;
    uint64_t remaining_ = 0, total_ = 0, index_ = 0;
    bool counted_ = false, warnedDummy_ = false;
    std::string error_;
};

// The records: -c rays averaged into each (rcontrib.c done_contrib), -c 0 summing all,
// flushes at -x and after zero-direction rays (rc2.c end_record).
class Records {
public:
    Records(const RcontribRunSettings& s, ContribOutput& out, RcontribRunStats& stats)
        : s_(s),
          out_(out),
          stats_(stats),
          sum_(s.values),
          account_(s.accumulate),
          flushEvery_(s.yres > 0 && s.xres > 1 ? 0 : s.xres),
          untilFlush_(flushEvery_) {
        if (s.accumulate <= 0 && s.totals.size() == s.values) sum_ = s.totals;
    }

    void add(const Ray& r) {
        for (size_t v = 0; v < s_.values; ++v) sum_[v] += r.values[v];
        ++inRecord_;
        if (!r.dummy) ++stats_.rays;
        if (r.dummy && (s_.yres <= 0 || s_.xres <= 1)) untilFlush_ = 1;
        if (account_ > 0 && --account_ == 0) {
            const bool flush = --untilFlush_ == 0;
            if (flush) untilFlush_ = flushEvery_;
            emit(s_.accumulate > 1 ? 1.0 / double(s_.accumulate) : 1.0, flush);
            account_ = s_.accumulate;
        }
    }

    // The last record: the sum of everything (-c 0) or what a short -c record holds.
    void finish() {
        if (s_.accumulate <= 0) {
            emit(1.0, true);
        } else if (inRecord_ > 0) {
            warn("partial accumulation in final record");
            emit(inRecord_ > 1 ? 1.0 / double(inRecord_) : 1.0, true);
        }
    }

private:
    void emit(double scale, bool flush) {
        out_.writeRecord(sum_, scale, flush);
        std::fill(sum_.begin(), sum_.end(), Color{});
        inRecord_ = 0;
        ++stats_.records;
    }
    const RcontribRunSettings& s_;
    ContribOutput& out_;
    RcontribRunStats& stats_;
    std::vector<Color> sum_;
    int account_;  // rays left in this record
    uint64_t inRecord_ = 0;
    long flushEvery_, untilFlush_;
};

// What a rank needs of a ray to trace it, and what it sends back (cluster_batch.h).
struct RayCodec {
    static void putRay(ByteWriter& w, const Ray& r) {
        w.put(r.origin);
        w.put(r.dir);
        w.put(r.maxDistance);
        w.put(r.index);
        w.put(r.dummy);
    }
    static void getRay(ByteReader& rd, Ray& r) {
        r.origin = rd.get<Vec3>();
        r.dir = rd.get<Vec3>();
        r.maxDistance = rd.get<double>();
        r.index = rd.get<uint64_t>();
        r.dummy = rd.get<bool>();
    }
    static void putResult(ByteWriter& w, const Ray& r) { w.putVector(r.values); }
    static void getResult(ByteReader& rd, Ray& r) { rd.getVector(r.values); }
};

}  // namespace

RcontribRunStats runRcontrib(const RcontribRunSettings& s, std::istream& in, ContribOutput* out,
                             const ContribTraceFn& trace) {
    RcontribRunStats stats;
    const int threads = std::max(1, s.threads);
    const BatchRole role(s.cluster);
    RP_CHECK(!role.root() || out);
    // Each ray of a batch holds all its bins until its record is written: many modifiers
    // with fine bins (100 sources x Reinhart MF 4 is 230,000 values, 5.5 MB a ray) get
    // smaller batches, down to one ray per thread.
    constexpr size_t kBatchBytes = size_t(256) << 20;
    const size_t perRay = std::max<size_t>(1, s.values * sizeof(Color));
    const size_t perRank =
        std::clamp(kBatchBytes / perRay, size_t(threads), size_t(64) * size_t(threads));
    const size_t batchSize = s.batchSize > 0 ? s.batchSize : perRank * size_t(role.ranks());
    std::optional<RayInput> input;
    std::optional<Records> records;
    if (role.root()) {
        input.emplace(s, in);
        records.emplace(s, *out, stats);
    }
    Progress progress(s, role.root() ? input->total() : 0);
    tbb::task_arena arena(threads);
    std::vector<Ray> batch;
    for (bool more = true; more;) {
        if (role.root()) more = input->fill(batch, batchSize);
        more = role.share<RayCodec>(batch, more);
        const Slice mine = role.slice(batch.size());
        arena.execute([&] {
            tbb::parallel_for(mine.begin, mine.end, [&](size_t k) {
                Ray& r = batch[k];
                r.values.assign(s.values, Color{});
                if (!r.dummy) trace(r.origin, r.dir, r.index, r.maxDistance, r.values);
            });
        });
        role.collect<RayCodec>(batch, mine);
        if (!role.root()) continue;
        for (const Ray& r : batch) {
            records->add(r);
            progress.update(input->done());
        }
    }
    if (!role.root()) return stats;
    records->finish();
    out->close();
    input->check();
    return stats;
}

}  // namespace rp::render
