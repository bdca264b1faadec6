// Photon distribution: prepass, prediction, main pass, normalisation (distribute.h).
#include "pmap/distribute.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <ostream>

#include "pmap/chunk_stream.h"
#include "util/error.h"
#include "util/temp_file.h"

namespace rp::pmap {

namespace {

using Clock = std::chrono::steady_clock;

// Prepass statistics below this many photons in a map give target errors of several
// percent (relative error ~ 1/sqrt(n), worse with correlated deposits along a path).
constexpr uint64_t kMinPrepassStored = 2000;

// -t progress lines in the manual's 4.4 format. Counters are updated per chunk; the
// thread that finishes a chunk past the report time prints.
class Progress {
public:
    explicit Progress(const DistributionSettings& s)
        : settings_(s), start_(Clock::now()), next_(s.pass.reportSeconds) {}

    void setPass(uint64_t passBegin, uint64_t passEnd) {
        passBegin_ = passBegin;
        passEnd_ = passEnd;
    }
    void add(uint64_t emitted, const std::array<uint64_t, kNumPhotonMapTypes>& stored) {
        emitted_.fetch_add(emitted, std::memory_order_relaxed);
        for (size_t t = 0; t < stored.size(); ++t)
            stored_[t].fetch_add(stored[t], std::memory_order_relaxed);
        if (settings_.pass.reportSeconds > 0 && settings_.progress) maybeReport();
    }
    void setStored(const std::array<uint64_t, kNumPhotonMapTypes>& counts) {
        for (size_t t = 0; t < counts.size(); ++t) stored_[t].store(counts[t]);
    }

private:
    void maybeReport() {
        double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
        if (elapsed < next_.load(std::memory_order_relaxed)) return;
        std::lock_guard<std::mutex> lock(mutex_);
        if (elapsed < next_.load()) return;
        next_.store(elapsed + settings_.pass.reportSeconds);
        uint64_t e = emitted_.load();
        double pct = passEnd_ > passBegin_
                         ? 100.0 * double(std::min(e, passEnd_) - std::min(e, passBegin_)) /
                               double(passEnd_ - passBegin_)
                         : 100.0;
        auto n = [&](PhotonMapType t) {
            uint64_t v = stored_[size_t(t)].load();
            if (t == PhotonMapType::Global) {
                v += stored_[size_t(PhotonMapType::PreComp)].load();
                v += stored_[size_t(PhotonMapType::Contrib)].load();
            }
            return (unsigned long long)v;
        };
        char line[256];
        std::snprintf(line, sizeof line,
                      "%llu emitted, %llu global, %llu caustic, %llu volume, %llu direct, "
                      "%.1f%% after %.3f hours\n",
                      (unsigned long long)e, n(PhotonMapType::Global), n(PhotonMapType::Caustic),
                      n(PhotonMapType::Volume), n(PhotonMapType::Direct), pct, elapsed / 3600);
        *settings_.progress << line << std::flush;
    }

    const DistributionSettings& settings_;
    Clock::time_point start_;
    std::atomic<double> next_;
    std::mutex mutex_;
    std::atomic<uint64_t> emitted_{0};
    std::array<std::atomic<uint64_t>, kNumPhotonMapTypes> stored_{};
    uint64_t passBegin_ = 0, passEnd_ = 0;
};

// Sizes bins' lists for n photons expected to deposit perPhoton[t] each in map t (0 if
// unknown), so that they are not copied as they grow: +10 % and 4 sigma, rarely outgrown.
void reserveFor(PhotonBins& bins, const std::array<double, kNumPhotonMapTypes>& perPhoton,
                uint64_t n) {
    for (size_t t = 0; t < size_t(kNumPhotonMapTypes); ++t)
        if (perPhoton[t] > 0)
            bins.maps[t].reserve(size_t(1.1 * perPhoton[t] * double(n) +
                                        4 * std::sqrt(perPhoton[t] * double(n)) + 16));
}

// The final 24-byte record of a deposit, its flux scaled by `scale` (distributePhotons'
// normalisation).
Photon finalPhoton(const RawPhoton& s, double scale) {
    Photon p;
    std::copy(s.pos, s.pos + 3, p.pos);
    std::copy(s.norm, s.norm + 3, p.norm);
    p.flags = 0;
    p.setCaustic(s.caustic != 0);
    p.setFlux(s.flux[0] * scale, s.flux[1] * scale, s.flux[2] * scale);
    p.primary = 0;
    return p;
}

// One chunk's deposits as traced, and how to send them to the root: raw in the prepass
// (kept until the storage probabilities are known), final records in the main pass, made
// where they are traced so that the root only appends them.
struct Traced {
    uint64_t photons = 0;
    PhotonBins bins;
    std::array<std::vector<Photon>, kNumPhotonMapTypes> final;

    std::array<uint64_t, kNumPhotonMapTypes> counts() const {
        std::array<uint64_t, kNumPhotonMapTypes> n{};
        for (size_t t = 0; t < n.size(); ++t) n[t] = bins.maps[t].size() + final[t].size();
        return n;
    }
};

void encode(ByteWriter& w, const Traced& t) {
    w.put(t.photons);
    w.put(t.bins.runaways);
    for (const auto& list : t.bins.maps) w.putVector(list);
    for (const auto& list : t.final) w.putVector(list);
}

void decode(ByteReader& r, Traced& t) {
    t.photons = r.get<uint64_t>();
    t.bins.runaways = r.get<long>();
    for (auto& list : t.bins.maps) r.getVector(list);
    for (auto& list : t.final) r.getVector(list);
}

// Traces [begin, end) in chunks, in parallel over threads and ranks (chunk_stream.h),
// and hands each chunk to `consume` on the root in index order, so a chunk's memory is
// reused as soon as its photons are stored instead of the whole pass being held (and its
// fresh memory faulted in) first. With `scale` (the main pass) the deposits come as final
// records scaled by it. Returns the root's seconds storing (streamChunks).
template <class Consume>
double traceStreamed(const PhotonTracer& tracer, tbb::task_arena& arena,
                     const DistributionSettings& s, uint64_t begin, uint64_t end,
                     const std::array<double, kNumPhotonMapTypes>& prob,
                     const std::array<double, kNumPhotonMapTypes>& perPhoton,
                     const std::array<double, kNumPhotonMapTypes>* scale, Consume consume) {
    if (end <= begin) return 0;
    const uint64_t chunks = (end - begin + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    return streamChunks<Traced>(
        s.cluster, arena, s.pass.threads, chunks,
        [&](uint64_t c) {
            Traced t;
            const uint64_t i0 = begin + c * kPhotonsPerChunk;
            const uint64_t i1 = std::min(end, i0 + kPhotonsPerChunk);
            t.photons = i1 - i0;
            reserveFor(t.bins, perPhoton, t.photons);
            PhotonTracer::Workspace ws(tracer);
            for (uint64_t i = i0; i < i1; ++i) tracer.trace(ws, s.pass.seed, i, prob, t.bins);
            if (scale)
                for (size_t m = 0; m < t.final.size(); ++m) {
                    auto& raw = t.bins.maps[m];
                    t.final[m].reserve(raw.size());
                    for (const RawPhoton& r : raw)
                        t.final[m].push_back(finalPhoton(r, (*scale)[m]));
                    std::vector<RawPhoton>().swap(raw);
                }
            return t;
        },
        [&](uint64_t, const Traced& t) { consume(t); });
}

// Appends the kept prepass deposits of `block` (u < prob) to `out` as final records
// scaled by `scale`, converted in parallel, appended in order.
void thinBlock(std::span<const RawPhoton> block, double prob, double scale, tbb::task_arena& arena,
               RecordStore<Photon>& out) {
    std::vector<Photon> converted(block.size());
    std::vector<uint8_t> keep(block.size());
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, block.size(), 4096),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t i = r.begin(); i != r.end(); ++i) {
                                  keep[i] = double(block[i].u) < prob;
                                  if (keep[i]) converted[i] = finalPhoton(block[i], scale);
                              }
                          });
    });
    for (size_t i = 0; i < block.size(); ++i)
        if (keep[i]) out.append(converted[i]);
}

// A store for map t's records: within the settings' budget, spilling beside the map's
// file; in memory only without a budget.
template <class Record>
RecordStore<Record> newStore(const DistributionSettings& s, size_t t) {
    if (!s.budget) return RecordStore<Record>();
    return RecordStore<Record>(s.budget, folderOf(s.files[t]), s.files[t]);
}

struct Prepass {
    // All deposits, in index order (on the root; other ranks only trace).
    std::array<RecordStore<RawPhoton>, kNumPhotonMapTypes> deposits;
    std::array<uint64_t, kNumPhotonMapTypes> stored{};  // deposits per map, on every rank
    double storingSeconds = 0;
    uint64_t emitted = 0;
    int passes = 0;
    long runaways = 0;
};

// The prepass: traces from index 0 storing every deposit, doubling while a map is empty
// (up to -apM passes) or sparse, to measure each map's photons stored per photon emitted.
Prepass runPrepass(const PhotonTracer& tracer, tbb::task_arena& arena,
                   const DistributionSettings& settings, const std::vector<size_t>& active,
                   Progress& progress) {
    const auto& targets = settings.targets;
    uint64_t minTarget = 0, sumTargets = 0;
    for (size_t t : active) {
        minTarget = minTarget == 0 ? targets[t] : std::min(minTarget, targets[t]);
        sumTargets += targets[t];
    }
    Prepass pre;
    for (size_t t : active) pre.deposits[t] = newStore<RawPhoton>(settings, t);
    std::array<double, kNumPhotonMapTypes> all{};
    all.fill(1.0);
    // Expected deposits per photon, for sizing the bins. Before the first prepass is
    // measured: 2 per map (a photon in a closed room deposits at about every bounce).
    // Only memory depends on it: without a guess the first prepass's bins grew by
    // doubling, copies and page faults included (bench/README_profile.md).
    std::array<double, kNumPhotonMapTypes> perPhoton{};
    for (size_t t : active) perPhoton[t] = 2;
    uint64_t passSize =
        std::max<uint64_t>(1, uint64_t(std::ceil(settings.pass.preDistrib * double(minTarget))));
    for (;;) {
        progress.setPass(pre.emitted, pre.emitted + passSize);
        pre.storingSeconds +=
            traceStreamed(tracer, arena, settings, pre.emitted, pre.emitted + passSize, all,
                          perPhoton, nullptr, [&](const Traced& c) {
                              progress.add(c.photons, c.counts());
                              pre.runaways += c.bins.runaways;
                              for (size_t t : active)
                                  for (const RawPhoton& r : c.bins.maps[t])
                                      pre.deposits[t].append(r);
                          });
        pre.emitted += passSize;
        ++pre.passes;
        // Every rank takes the root's counts, so all decide on the next pass alike.
        for (size_t t : active) pre.stored[t] = pre.deposits[t].size();
        pre.stored = broadcastValue(settings.cluster, pre.stored);
        bool anyEmpty = false, anySparse = false;
        uint64_t storedTotal = 0;
        for (size_t t : active) {
            const uint64_t stored = pre.stored[t];
            perPhoton[t] = double(stored) / double(pre.emitted);
            anyEmpty = anyEmpty || stored == 0;
            anySparse = anySparse || stored < std::min(kMinPrepassStored, targets[t]);
            storedTotal += stored;
        }
        if (anyEmpty) {
            if (pre.passes >= settings.pass.maxPrepass) {
                std::string empty;
                for (size_t t : active)
                    if (pre.stored[t] == 0)
                        empty += std::string(empty.empty() ? "" : ", ") +
                                 photonMapTypeName(PhotonMapType(t));
                throw InputError("too many prepasses, no photons stored in " + empty +
                                 " photon map (no light reaches a surface the map can hold, or "
                                 "a map type incompatible with the scene; manual 4.2)");
            }
            passSize *= 2;
            continue;
        }
        // Not part of RADIANCE's algorithm: a map with few prepass photons predicts its
        // rate poorly, so keep doubling the (never wasted) prepass while memory allows.
        if (anySparse && storedTotal < 2 * sumTargets) {
            passSize = pre.emitted;
            continue;
        }
        return pre;
    }
}

}  // namespace

DistributionResult distributePhotons(const PhotonTracer& tracer,
                                     const DistributionSettings& settings) {
    const auto& targets = settings.targets;
    std::vector<size_t> active;
    for (size_t t = 0; t < targets.size(); ++t)
        if (targets[t] > 0) active.push_back(t);
    RP_CHECK(!active.empty());

    tbb::task_arena arena(std::max(1, settings.pass.threads));
    Progress progress(settings);
    DistributionResult result;
    Prepass pre = runPrepass(tracer, arena, settings, active, progress);
    const uint64_t emitted = pre.emitted;
    result.prepassEmitted = emitted;
    result.prepasses = pre.passes;
    result.runaways = pre.runaways;
    result.storingSeconds = pre.storingSeconds;

    // ---- Prediction: one total N and one storage probability per map.
    std::array<double, kNumPhotonMapTypes> need{};  // photons to emit for map t alone
    double maxNeed = 0;
    for (size_t t : active) {
        need[t] = double(targets[t]) * double(emitted) / double(pre.stored[t]);
        maxNeed = std::max(maxNeed, need[t]);
    }
    const uint64_t total = std::max(emitted, uint64_t(std::ceil(maxNeed)));
    std::array<double, kNumPhotonMapTypes> prob{};
    for (size_t t : active) prob[t] = std::min(1.0, need[t] / std::max(maxNeed, double(emitted)));
    result.storeProbability = prob;

    // ---- Output: the prepass photons thinned with the same draws the main pass uses,
    // then the main pass as it is traced. Normalisation: flux / (N p_t) in the 24-byte
    // record. Each prepass chunk is freed as soon as it is thinned.
    std::array<double, kNumPhotonMapTypes> scale{}, perPhoton{};
    std::array<uint64_t, kNumPhotonMapTypes> kept{};
    const auto thinning = Clock::now();
    for (size_t t : active) {
        scale[t] = 1.0 / (double(total) * prob[t]);
        perPhoton[t] = double(pre.stored[t]) / double(emitted) * prob[t];
        RecordStore<Photon>& out = result.photons[t] = newStore<Photon>(settings, t);
        pre.deposits[t].drain([&](std::span<const RawPhoton> block) {
            thinBlock(block, prob[t], scale[t], arena, out);
        });
        kept[t] = out.size();
    }
    progress.setStored(kept);
    result.storingSeconds += std::chrono::duration<double>(Clock::now() - thinning).count();

    // ---- Main pass.
    progress.setPass(emitted, total);
    result.storingSeconds += traceStreamed(tracer, arena, settings, emitted, total, prob, perPhoton,
                                           &scale, [&](const Traced& c) {
                                               progress.add(c.photons, c.counts());
                                               result.runaways += c.bins.runaways;
                                               for (size_t t : active)
                                                   for (const Photon& p : c.final[t])
                                                       result.photons[t].append(p);
                                           });
    result.emitted = total;
    return result;
}

}  // namespace rp::pmap
