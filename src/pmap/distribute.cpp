// Photon distribution: prepass, prediction, main pass, normalisation (distribute.h).
#include "pmap/distribute.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <ostream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

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

// Appends b's photons to a, map by map, in order.
void append(PhotonBins& a, PhotonBins&& b) {
    for (size_t t = 0; t < a.maps.size(); ++t) {
        if (a.maps[t].empty()) a.maps[t] = std::move(b.maps[t]);
        else a.maps[t].insert(a.maps[t].end(), b.maps[t].begin(), b.maps[t].end());
    }
    a.runaways += b.runaways;
}

// Traces photon indices [begin, end) in fixed chunks on `arena` and returns their
// deposits concatenated in index order.
PhotonBins traceRange(const PhotonTracer& tracer, tbb::task_arena& arena, uint64_t seed,
                      uint64_t begin, uint64_t end,
                      const std::array<double, kNumPhotonMapTypes>& prob, Progress& progress) {
    if (end <= begin) return {};
    const uint64_t chunks = (end - begin + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    std::vector<PhotonBins> bins(chunks);
    progress.setPass(begin, end);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<uint64_t>(0, chunks, 1),
            [&](const tbb::blocked_range<uint64_t>& r) {
                for (uint64_t c = r.begin(); c != r.end(); ++c) {
                    uint64_t i0 = begin + c * kPhotonsPerChunk;
                    uint64_t i1 = std::min(end, i0 + kPhotonsPerChunk);
                    for (uint64_t i = i0; i < i1; ++i) tracer.trace(seed, i, prob, bins[c]);
                    progress.add(i1 - i0, bins[c]);
                }
            },
            tbb::simple_partitioner());
    });
    PhotonBins all;
    for (size_t t = 0; t < all.maps.size(); ++t) {
        size_t n = 0;
        for (const PhotonBins& b : bins) n += b.maps[t].size();
        all.maps[t].reserve(n);
    }
    for (PhotonBins& b : bins) append(all, std::move(b));
    return all;
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
    PhotonBins pre;
    uint64_t emitted = 0;
    uint64_t passSize = std::max<uint64_t>(
        1, uint64_t(std::ceil(settings.preDistrib * double(minTarget))));
    for (;;) {
        append(pre, traceRange(tracer, arena, settings.seed, emitted, emitted + passSize, all,
                               progress));
        emitted += passSize;
        ++result.prepasses;
        bool anyEmpty = false, anySparse = false;
        uint64_t storedTotal = 0;
        for (size_t t : active) {
            anyEmpty = anyEmpty || pre.maps[t].empty();
            anySparse = anySparse || pre.maps[t].size() < std::min(kMinPrepassStored, targets[t]);
            storedTotal += pre.maps[t].size();
        }
        if (anyEmpty) {
            if (result.prepasses >= settings.maxPrepass) {
                std::string empty;
                for (size_t t : active)
                    if (pre.maps[t].empty())
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

    // ---- Prediction: one total N and one storage probability per map.
    std::array<double, kNumPhotonMapTypes> need{};  // photons to emit for map t alone
    double maxNeed = 0;
    for (size_t t : active) {
        need[t] = double(targets[t]) * double(emitted) / double(pre.maps[t].size());
        maxNeed = std::max(maxNeed, need[t]);
    }
    const uint64_t total = std::max(emitted, uint64_t(std::ceil(maxNeed)));
    std::array<double, kNumPhotonMapTypes> prob{};
    for (size_t t : active) prob[t] = std::min(1.0, need[t] / std::max(maxNeed, double(emitted)));
    result.storeProbability = prob;

    // Thin the prepass deposits with the same draws the main pass uses.
    std::array<uint64_t, kNumPhotonMapTypes> kept{};
    for (size_t t : active) {
        auto& v = pre.maps[t];
        v.erase(std::remove_if(v.begin(), v.end(),
                               [&](const RawPhoton& p) { return double(p.u) >= prob[t]; }),
                v.end());
        v.shrink_to_fit();
        kept[t] = v.size();
    }
    progress.setStored(kept);

    // ---- Main pass.
    append(pre, traceRange(tracer, arena, settings.seed, emitted, total, prob, progress));
    result.emitted = total;
    result.runaways = pre.runaways;

    // ---- Normalisation: flux / (N p_t), then the 24-byte record.
    for (size_t t : active) {
        const double scale = 1.0 / (double(total) * prob[t]);
        std::vector<RawPhoton> raw = std::move(pre.maps[t]);
        std::vector<Photon>& out = result.photons[t];
        out.resize(raw.size());
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, raw.size(), 1 << 14),
                              [&](const tbb::blocked_range<size_t>& r) {
                                  for (size_t i = r.begin(); i != r.end(); ++i) {
                                      const RawPhoton& s = raw[i];
                                      Photon& p = out[i];
                                      std::copy(s.pos, s.pos + 3, p.pos);
                                      std::copy(s.norm, s.norm + 3, p.norm);
                                      p.flags = 0;
                                      p.setCaustic(s.caustic != 0);
                                      p.setFlux(s.flux[0] * scale, s.flux[1] * scale,
                                                s.flux[2] * scale);
                                      p.primary = 0;
                                  }
                              });
        });
    }
    return result;
}

}  // namespace rp::pmap
