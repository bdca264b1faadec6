// Photon distribution: prepass, prediction, main pass, normalisation (distribute.h).
#include "pmap/distribute.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <ostream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "util/bulk_memory.h"
#include "util/error.h"

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
        : settings_(s), start_(Clock::now()), next_(s.reportSeconds) {}

    void setPass(uint64_t passBegin, uint64_t passEnd) {
        passBegin_ = passBegin;
        passEnd_ = passEnd;
    }
    void add(uint64_t emitted, const PhotonBins& bins) {
        emitted_.fetch_add(emitted, std::memory_order_relaxed);
        for (size_t t = 0; t < bins.maps.size(); ++t)
            stored_[t].fetch_add(bins.maps[t].size(), std::memory_order_relaxed);
        if (settings_.reportSeconds > 0 && settings_.progress) maybeReport();
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
        next_.store(elapsed + settings_.reportSeconds);
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

// The prepass deposits, as per-chunk bins in photon index order. Kept as chunks rather
// than concatenated: each concatenation copied every photon into fresh memory, and first
// touching fresh memory (page faults) cost more than the copy itself. They are read once,
// thinned into the final records (PhotonOutput) before the main pass streams its own.
using Chunks = std::vector<PhotonBins>;

uint64_t storedIn(const Chunks& chunks, size_t t) {
    uint64_t n = 0;
    for (const PhotonBins& b : chunks) n += b.maps[t].size();
    return n;
}

// Sizes bins' lists for n photons expected to deposit perPhoton[t] each in map t (0 if
// unknown), so that they are not copied as they grow: +10 % and 4 sigma, rarely outgrown.
void reserveFor(PhotonBins& bins, const std::array<double, kNumPhotonMapTypes>& perPhoton,
                uint64_t n) {
    for (size_t t = 0; t < size_t(kNumPhotonMapTypes); ++t)
        if (perPhoton[t] > 0)
            bins.maps[t].reserve(size_t(1.1 * perPhoton[t] * double(n) +
                                        4 * std::sqrt(perPhoton[t] * double(n)) + 16));
}

// Traces photon indices [begin, end) in fixed chunks on `arena` and appends their
// deposits to `out` in index order (the prepass: its chunks are kept until the main pass
// knows how to thin them). `perPhoton` as reserveFor.
void traceRange(const PhotonTracer& tracer, tbb::task_arena& arena, uint64_t seed,
                uint64_t begin, uint64_t end,
                const std::array<double, kNumPhotonMapTypes>& prob,
                const std::array<double, kNumPhotonMapTypes>& perPhoton, Progress& progress,
                Chunks& out) {
    if (end <= begin) return;
    const uint64_t chunks = (end - begin + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    const size_t first = out.size();
    out.resize(first + chunks);
    PhotonBins* bins = out.data() + first;
    progress.setPass(begin, end);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<uint64_t>(0, chunks, 1),
            [&](const tbb::blocked_range<uint64_t>& r) {
                for (uint64_t c = r.begin(); c != r.end(); ++c) {
                    uint64_t i0 = begin + c * kPhotonsPerChunk;
                    uint64_t i1 = std::min(end, i0 + kPhotonsPerChunk);
                    reserveFor(bins[c], perPhoton, i1 - i0);
                    for (uint64_t i = i0; i < i1; ++i) tracer.trace(seed, i, prob, bins[c]);
                    progress.add(i1 - i0, bins[c]);
                }
            },
            tbb::simple_partitioner());
    });
}

// The final photon records of one map, appended chunk by chunk in index order. The array
// is advised for huge pages before its first touch: 4 KiB page faults on fresh memory
// cost more than filling it (util/bulk_memory.h).
class PhotonOutput {
public:
    void reserve(size_t n) {
        std::vector<Photon> v;
        v.reserve(n);
        adviseHugePages(v.data(), n * sizeof(Photon));
        v.insert(v.end(), photons_.begin(), photons_.end());
        photons_.swap(v);
    }
    // Appends raw's deposits with u < keepBelow (the prepass's thinning; +inf keeps all)
    // with flux x scale.
    void append(const std::vector<RawPhoton>& raw, double keepBelow, double scale) {
        if (photons_.size() + raw.size() > photons_.capacity())
            reserve(std::max(2 * photons_.capacity(), photons_.size() + raw.size()));
        for (const RawPhoton& s : raw) {
            if (!(double(s.u) < keepBelow)) continue;
            Photon& p = photons_.emplace_back();
            std::copy(s.pos, s.pos + 3, p.pos);
            std::copy(s.norm, s.norm + 3, p.norm);
            p.flags = 0;
            p.setCaustic(s.caustic != 0);
            p.setFlux(s.flux[0] * scale, s.flux[1] * scale, s.flux[2] * scale);
            p.primary = 0;
        }
    }
    std::vector<Photon> take() { return std::move(photons_); }

private:
    std::vector<Photon> photons_;
};

// The main pass: traces [begin, end) in chunks in parallel and hands each chunk's bins to
// `consume` in index order (a serial in-order stage), so a chunk's memory is reused as
// soon as its photons are converted instead of the whole pass being held (and its fresh
// memory faulted in) first.
template <class Consume>
void traceStreamed(const PhotonTracer& tracer, tbb::task_arena& arena, int threads,
                   uint64_t seed, uint64_t begin, uint64_t end,
                   const std::array<double, kNumPhotonMapTypes>& prob,
                   const std::array<double, kNumPhotonMapTypes>& perPhoton, Consume consume) {
    if (end <= begin) return;
    const uint64_t chunks = (end - begin + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    uint64_t next = 0;
    struct Traced {
        uint64_t photons = 0;
        PhotonBins bins;
    };
    using Token = std::shared_ptr<Traced>;  // TBB tokens must be copyable
    arena.execute([&] {
        tbb::parallel_pipeline(
            size_t(4 * std::max(1, threads)),
            tbb::make_filter<void, uint64_t>(tbb::filter_mode::serial_in_order,
                                             [&](tbb::flow_control& fc) -> uint64_t {
                                                 if (next == chunks) fc.stop();
                                                 return next < chunks ? next++ : 0;
                                             }) &
                tbb::make_filter<uint64_t, Token>(
                    tbb::filter_mode::parallel,
                    [&](uint64_t c) {
                        auto t = std::make_shared<Traced>();
                        uint64_t i0 = begin + c * kPhotonsPerChunk;
                        uint64_t i1 = std::min(end, i0 + kPhotonsPerChunk);
                        t->photons = i1 - i0;
                        reserveFor(t->bins, perPhoton, t->photons);
                        for (uint64_t i = i0; i < i1; ++i) tracer.trace(seed, i, prob, t->bins);
                        return t;
                    }) &
                tbb::make_filter<Token, void>(
                    tbb::filter_mode::serial_in_order,
                    [&](const Token& t) { consume(t->photons, t->bins); }));
    });
}

}  // namespace

DistributionResult distributePhotons(const PhotonTracer& tracer,
                                     const DistributionSettings& settings) {
    const auto& targets = settings.targets;
    std::vector<size_t> active;
    uint64_t minTarget = 0, sumTargets = 0;
    for (size_t t = 0; t < targets.size(); ++t)
        if (targets[t] > 0) {
            active.push_back(t);
            minTarget = minTarget == 0 ? targets[t] : std::min(minTarget, targets[t]);
            sumTargets += targets[t];
        }
    RP_CHECK(!active.empty());

    tbb::task_arena arena(std::max(1, settings.threads));
    Progress progress(settings);
    DistributionResult result;

    // ---- Prepass: store everything, measure photons stored per photon emitted.
    std::array<double, kNumPhotonMapTypes> all{};
    all.fill(1.0);
    Chunks chunks;
    std::array<uint64_t, kNumPhotonMapTypes> preStored{};
    // Expected deposits per photon, for sizing the bins. Before the first prepass is
    // measured: 2 per map (a photon in a closed room deposits at about every bounce).
    // Only memory depends on it: without a guess the first prepass's bins grew by
    // doubling, and those copies and their page faults were ~1 % of a Cornell run.
    std::array<double, kNumPhotonMapTypes> perPhoton{};
    for (size_t t : active) perPhoton[t] = 2;
    uint64_t emitted = 0;
    uint64_t passSize = std::max<uint64_t>(
        1, uint64_t(std::ceil(settings.preDistrib * double(minTarget))));
    for (;;) {
        traceRange(tracer, arena, settings.seed, emitted, emitted + passSize, all, perPhoton,
                   progress, chunks);
        emitted += passSize;
        ++result.prepasses;
        for (size_t t : active) {
            preStored[t] = storedIn(chunks, t);
            perPhoton[t] = double(preStored[t]) / double(emitted);
        }
        bool anyEmpty = false, anySparse = false;
        uint64_t storedTotal = 0;
        for (size_t t : active) {
            anyEmpty = anyEmpty || preStored[t] == 0;
            anySparse = anySparse || preStored[t] < std::min(kMinPrepassStored, targets[t]);
            storedTotal += preStored[t];
        }
        if (anyEmpty) {
            if (result.prepasses >= settings.maxPrepass) {
                std::string empty;
                for (size_t t : active)
                    if (preStored[t] == 0)
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
            passSize = emitted;
            continue;
        }
        break;
    }
    result.prepassEmitted = emitted;
    const size_t prepassChunks = chunks.size();

    // ---- Prediction: one total N and one storage probability per map.
    std::array<double, kNumPhotonMapTypes> need{};  // photons to emit for map t alone
    double maxNeed = 0;
    for (size_t t : active) {
        need[t] = double(targets[t]) * double(emitted) / double(preStored[t]);
        maxNeed = std::max(maxNeed, need[t]);
    }
    const uint64_t total = std::max(emitted, uint64_t(std::ceil(maxNeed)));
    std::array<double, kNumPhotonMapTypes> prob{};
    for (size_t t : active) prob[t] = std::min(1.0, need[t] / std::max(maxNeed, double(emitted)));
    result.storeProbability = prob;

    // The prepass deposits are thinned with the same draws the main pass uses (below);
    // count the survivors for progress reports.
    std::array<uint64_t, kNumPhotonMapTypes> kept{};
    for (size_t t : active)
        for (size_t c = 0; c < prepassChunks; ++c)
            for (const RawPhoton& p : chunks[c].maps[t]) kept[t] += double(p.u) < prob[t];
    progress.setStored(kept);

    // ---- Output: the thinned prepass photons, then the main pass as it is traced.
    // Normalisation: flux / (N p_t) in the 24-byte record.
    std::array<PhotonOutput, kNumPhotonMapTypes> out;
    std::array<double, kNumPhotonMapTypes> scale{};
    for (size_t t : active) {
        scale[t] = 1.0 / (double(total) * prob[t]);
        perPhoton[t] *= prob[t];
        const double n = perPhoton[t] * double(total - emitted);
        out[t].reserve(size_t(double(kept[t]) + 1.02 * n + 4 * std::sqrt(n) + 1024));
        for (size_t c = 0; c < prepassChunks; ++c) {
            out[t].append(chunks[c].maps[t], prob[t], scale[t]);
            std::vector<RawPhoton>().swap(chunks[c].maps[t]);
        }
    }
    for (const PhotonBins& b : chunks) result.runaways += b.runaways;
    Chunks().swap(chunks);

    // ---- Main pass.
    progress.setPass(emitted, total);
    traceStreamed(tracer, arena, settings.threads, settings.seed, emitted, total, prob,
                  perPhoton, [&](uint64_t photons, const PhotonBins& bins) {
                      progress.add(photons, bins);
                      result.runaways += bins.runaways;
                      for (size_t t : active) out[t].append(bins.maps[t], HUGE_VAL, scale[t]);
                  });
    result.emitted = total;
    for (size_t t : active) result.photons[t] = out[t].take();
    return result;
}

}  // namespace rp::pmap
