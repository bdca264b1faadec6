// Precomputed global photons: stratified selection and per-photon density estimates
// (precomp.h).
#include "pmap/precomp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <ostream>

#include "pmap/density.h"
#include "pmap/photon_map.h"
#include "util/error.h"
#include "util/rng.h"

namespace rp::pmap {

std::vector<uint64_t> precompSelection(uint64_t n, double fraction, uint64_t seed) {
    RP_CHECK(fraction > 0 && fraction <= 1);
    const uint64_t count = std::min<uint64_t>(n, uint64_t(fraction * double(n)));
    std::vector<uint64_t> idx(count);
    Rng rng(seed, RngDomain::Sampling, 0x70726563ULL);  // "prec": its own stream
    for (uint64_t i = 0; i < count; ++i) {
        uint64_t k = uint64_t((double(i) + rng.uniform()) / fraction);
        idx[i] = std::min(k, n - 1);
    }
    return idx;
}

std::vector<Photon> precomputeGlobal(std::vector<Photon> global, const PrecompSettings& s) {
    const std::vector<uint64_t> sel = precompSelection(global.size(), s.fraction, s.pass.seed);
    std::vector<Photon> out(sel.size());
    for (size_t i = 0; i < sel.size(); ++i) out[i] = global[sel[i]];
    if (out.empty()) return out;

    tbb::task_arena arena(std::max(1, s.pass.threads));
    PhotonMap map;
    arena.execute([&] {
        map =
            PhotonMap::searchableFrom(PhotonMapType::Global, std::move(global), s.pass.threads > 1);
    });
    LookupParams lp;
    lp.bandwidth = std::max(1, s.bandwidth);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::atomic<uint64_t> done{0};
    std::atomic<double> nextReport{double(s.pass.reportSeconds)};
    std::mutex reportMutex;
    auto report = [&] {
        double t = std::chrono::duration<double>(Clock::now() - start).count();
        if (t < nextReport.load(std::memory_order_relaxed)) return;
        std::lock_guard<std::mutex> lock(reportMutex);
        if (t < nextReport.load()) return;
        nextReport.store(t + s.pass.reportSeconds);
        uint64_t d = done.load();
        char line[128];
        std::snprintf(line, sizeof line, "%llu precomputed, %.1f%% after %.3f hours\n",
                      (unsigned long long)d, 100.0 * double(d) / double(out.size()), t / 3600);
        *s.progress << line << std::flush;
    };

    const uint64_t chunks = (out.size() + kPrecompChunk - 1) / kPrecompChunk;
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<uint64_t>(0, chunks, 1),
            [&](const tbb::blocked_range<uint64_t>& r) {
                for (uint64_t c = r.begin(); c != r.end(); ++c) {
                    // A fresh lookup per chunk: its adaptive radius depends on the chunk only.
                    PhotonLookup lookup(map, lp);
                    const uint64_t i0 = c * kPrecompChunk;
                    const uint64_t i1 = std::min<uint64_t>(out.size(), i0 + kPrecompChunk);
                    for (uint64_t i = i0; i < i1; ++i) {
                        Photon& p = out[i];
                        Vec3 n{p.norm[0] / 127.0, p.norm[1] / 127.0, p.norm[2] / 127.0};
                        double len = length(n);
                        if (len > 0) n = n / len;
                        std::array<double, 3> e = lookup.surfaceDensity(p.position(), n);
                        p.setFlux(e[0], e[1], e[2]);
                        p.setCaustic(false);
                        p.setDiscr(0);
                        p.primary = 0;
                    }
                    done.fetch_add(i1 - i0, std::memory_order_relaxed);
                    if (s.pass.reportSeconds > 0 && s.progress) report();
                }
            },
            tbb::simple_partitioner());
    });
    if (s.pass.reportSeconds > 0 && s.progress) {
        char line[128];
        std::snprintf(line, sizeof line, "%llu precomputed, 100.0%% after %.3f hours\n",
                      (unsigned long long)out.size(),
                      std::chrono::duration<double>(Clock::now() - start).count() / 3600);
        *s.progress << line << std::flush;
    }
    return out;
}

}  // namespace rp::pmap
