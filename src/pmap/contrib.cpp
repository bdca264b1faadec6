// Contribution photon distribution, source by source (contrib.h).
#include "pmap/contrib.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <ostream>

#include "pmap/chunk_stream.h"
#include "pmap/distribute.h"
#include "util/dir_code.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/warnings.h"

namespace rp::pmap {

namespace {

using Clock = std::chrono::steady_clock;

// Deposits of a range of emitted photons in index order, with the number stored by each
// path that stored any (one primary per such path).
struct PathBatch {
    std::vector<RawPhoton> photons;
    std::vector<uint32_t> pathSizes;
    std::vector<PrimaryRay> rays;  // per path, when primary rays are kept
    long runaways = 0;

    void append(PathBatch&& b) {
        photons.insert(photons.end(), b.photons.begin(), b.photons.end());
        pathSizes.insert(pathSizes.end(), b.pathSizes.begin(), b.pathSizes.end());
        rays.insert(rays.end(), b.rays.begin(), b.rays.end());
        runaways += b.runaways;
    }
};

// Where emitted photon `index` left its source and the direction back to it (the tracer
// emitted it from the same (seed, index) stream, so it is the same photon).
PrimaryRay primaryRay(const light::EmissionPlan& plan, uint64_t seed, uint64_t index) {
    const light::EmittedPhoton e = plan.emitPhoton(seed, index);
    PrimaryRay r;
    r.pos = {float(e.ray.origin.x), float(e.ray.origin.y), float(e.ray.origin.z)};
    r.dir = encodeDirection({-e.ray.dir.x, -e.ray.dir.y, -e.ray.dir.z});
    return r;
}

class Reporter {
public:
    explicit Reporter(const ContribSettings& s)
        : s_(s), start_(Clock::now()), next_(s.pass.reportSeconds) {}
    void add(uint64_t emitted, uint64_t stored) {
        emitted_.fetch_add(emitted, std::memory_order_relaxed);
        stored_.fetch_add(stored, std::memory_order_relaxed);
        if (s_.pass.reportSeconds <= 0 || !s_.progress) return;
        double t = std::chrono::duration<double>(Clock::now() - start_).count();
        if (t < next_.load(std::memory_order_relaxed)) return;
        std::lock_guard<std::mutex> lock(mutex_);
        if (t < next_.load()) return;
        next_.store(t + s_.pass.reportSeconds);
        uint64_t st = stored_.load();
        double pct = s_.target ? std::min(100.0, 100.0 * double(st) / double(s_.target)) : 100.0;
        char line[256];
        std::snprintf(line, sizeof line,
                      "%llu emitted, %llu global, 0 caustic, 0 volume, 0 direct, "
                      "%.1f%% after %.3f hours\n",
                      (unsigned long long)emitted_.load(), (unsigned long long)st, pct, t / 3600);
        *s_.progress << line << std::flush;
    }

private:
    const ContribSettings& s_;
    Clock::time_point start_;
    std::atomic<double> next_;
    std::mutex mutex_;
    std::atomic<uint64_t> emitted_{0}, stored_{0};
};

void encode(ByteWriter& w, const PathBatch& b) {
    w.putVector(b.photons);
    w.putVector(b.pathSizes);
    w.putVector(b.rays);
    w.put(b.runaways);
}

void decode(ByteReader& r, PathBatch& b) {
    r.getVector(b.photons);
    r.getVector(b.pathSizes);
    r.getVector(b.rays);
    b.runaways = r.get<long>();
}

// Traces [begin, end) over threads and ranks (chunk_stream.h); the root gets the paths in
// index order. `rays` (may be null): the plan to record each storing path's primary ray
// from.
PathBatch traceRange(const PhotonTracer& tracer, tbb::task_arena& arena, const ContribSettings& s,
                     uint64_t seed, uint64_t begin, uint64_t end, Reporter& reporter,
                     const light::EmissionPlan* rays) {
    PathBatch out;
    if (end <= begin) return out;
    std::array<double, kNumPhotonMapTypes> all{};
    all.fill(1.0);
    const uint64_t chunks = (end - begin + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    streamChunks<PathBatch>(
        s.cluster, arena, s.pass.threads, chunks,
        [&](uint64_t c) {
            const uint64_t i0 = begin + c * kPhotonsPerChunk;
            const uint64_t i1 = std::min(end, i0 + kPhotonsPerChunk);
            PhotonBins bins;
            auto& g = bins.maps[size_t(PhotonMapType::Global)];
            PathBatch b;
            PhotonTracer::Workspace ws(tracer);
            for (uint64_t i = i0; i < i1; ++i) {
                const size_t before = g.size();
                tracer.trace(ws, seed, i, all, bins);
                if (g.size() == before) continue;
                b.pathSizes.push_back(uint32_t(g.size() - before));
                if (rays) b.rays.push_back(primaryRay(*rays, seed, i));
            }
            b.photons = std::move(g);
            b.runaways = bins.runaways;
            return b;
        },
        [&](uint64_t c, PathBatch& b) {
            const uint64_t i0 = begin + c * kPhotonsPerChunk;
            reporter.add(std::min(end, i0 + kPhotonsPerChunk) - i0, b.photons.size());
            out.append(std::move(b));
        });
    return out;
}

}  // namespace

ContribResult distributeContrib(const Scene& scene, const SceneGeometry& geometry,
                                const light::EmissionPlan& plan,
                                const light::EmissionOptions& emission, TraceSettings trace,
                                const ContribSettings& settings,
                                const material::SurfaceChains& chains,
                                const material::MaterialCalc* materialCalc) {
    const auto& sources = plan.sources();
    const size_t nsrc = sources.size();
    if (nsrc > size_t(INT16_MAX))
        throw InputError("too many light sources (" + std::to_string(nsrc) +
                         ") for a contribution photon map's 16-bit source index");
    RP_CHECK(settings.target > 0);
    trace.maps = {};
    trace.maps[size_t(PhotonMapType::Global)] = true;

    ContribResult result;
    result.emitted.assign(nsrc, 0);
    result.stored.assign(nsrc, 0);
    tbb::task_arena arena(std::max(1, settings.pass.threads));
    Reporter reporter(settings);
    // RADIANCE: the target is shared equally by all sources (pmapcontrib.c).
    const double srcTarget = double(settings.target) / double(nsrc);

    for (size_t s = 0; s < nsrc; ++s) {
        if (!(plan.sourceFlux(s).average() > 0)) {
            warn(sources[s].loc, "source " + sources[s].name + " has zero emission");
            continue;
        }
        light::EmissionPlan single(geometry, {sources[s]}, emission);
        PhotonTracer tracer(scene, geometry, single, trace, chains, materialCalc);
        const light::EmissionPlan* rays = settings.primaryRays ? &single : nullptr;
        const uint64_t seed = mix64(settings.pass.seed + 0x632be59bd9b4e019ULL * (s + 1));

        // Prepass: a fraction of the source's share, doubled while nothing is stored.
        PathBatch batch;
        uint64_t emitted = 0;
        uint64_t pass =
            std::max<uint64_t>(1, uint64_t(std::ceil(settings.pass.preDistrib * srcTarget)));
        uint64_t stored = 0;  // the root's count, known to every rank
        for (int prepass = 1; prepass <= settings.pass.maxPrepass; ++prepass, pass *= 2) {
            batch.append(
                traceRange(tracer, arena, settings, seed, emitted, emitted + pass, reporter, rays));
            emitted += pass;
            stored = broadcastValue(settings.cluster, uint64_t(batch.photons.size()));
            if (stored > 0) break;
        }
        const bool ok = stored > 0;
        if (!ok) {
            warn(sources[s].loc, "too many prepasses, no photons from source " + sources[s].name);
            result.emitted[s] = emitted;
            result.totalEmitted += emitted;
            result.runaways += batch.runaways;
            continue;
        }
        // Main pass: emit the rest so that the source stores about its share.
        const double ratio = srcTarget / double(stored);
        const uint64_t total =
            std::max(emitted, uint64_t(std::ceil(double(emitted) * std::max(1.0, ratio))));
        batch.append(traceRange(tracer, arena, settings, seed, emitted, total, reporter, rays));
        result.emitted[s] = total;
        result.stored[s] = batch.photons.size();
        result.totalEmitted += total;
        result.runaways += batch.runaways;

        // Flux per photon: the source's flux over its emitted count (the tracer's emitted
        // weight has mean flux = this source's flux).
        const double scale = 1.0 / double(total);
        size_t k = 0;
        result.photons.reserve(result.photons.size() + batch.photons.size());
        if (settings.primaryRays)
            result.primaryRays.insert(result.primaryRays.end(), batch.rays.begin(),
                                      batch.rays.end());
        for (uint32_t n : batch.pathSizes) {
            const uint32_t primary = uint32_t(result.primaries.size());
            result.primaries.push_back(PhotonPrimary{int16_t(s)});
            for (uint32_t j = 0; j < n; ++j, ++k) {
                const RawPhoton& r = batch.photons[k];
                Photon p;
                std::copy(r.pos, r.pos + 3, p.pos);
                std::copy(r.norm, r.norm + 3, p.norm);
                p.setCaustic(r.caustic != 0);
                p.setFlux(r.flux[0] * scale, r.flux[1] * scale, r.flux[2] * scale);
                p.primary = primary;
                result.photons.push_back(p);
            }
        }
        RP_CHECK(k == batch.photons.size());
    }
    if (broadcastValue(settings.cluster, uint64_t(result.photons.size())) == 0)
        throw InputError("empty contribution photon map (no photons stored from any source)");
    return result;
}

}  // namespace rp::pmap
