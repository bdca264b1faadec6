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

namespace {
// 21 bits of x spread to every third bit.
uint64_t spreadBits(uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
}
}  // namespace

void sortAlongCurve(const std::vector<Photon>& photons, std::vector<uint64_t>::iterator first,
                    std::vector<uint64_t>::iterator last) {
    if (first == last) return;
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = hi[a] = photons[*first].pos[a];
    for (auto it = first; it != last; ++it)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], photons[*it].pos[a]);
            hi[a] = std::max(hi[a], photons[*it].pos[a]);
        }
    std::vector<std::pair<uint64_t, uint64_t>> keyed;
    keyed.reserve(size_t(last - first));
    for (auto it = first; it != last; ++it) {
        uint64_t code = 0;
        for (int a = 0; a < 3; ++a) {
            const double span = double(hi[a]) - double(lo[a]);
            const double u = span > 0 ? (double(photons[*it].pos[a]) - lo[a]) / span : 0;
            code |= spreadBits(uint64_t(std::clamp(u, 0.0, 1.0) * 0x1fffff)) << a;
        }
        keyed.emplace_back(code, *it);
    }
    std::sort(keyed.begin(), keyed.end());
    for (const auto& [code, i] : keyed) *first++ = i;
}

void forEachPrecompChunk(uint64_t count, const PassSettings& pass, std::ostream* progress,
                         const std::function<void(uint64_t, uint64_t)>& work) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const bool reporting = pass.reportSeconds > 0 && progress;
    std::atomic<uint64_t> done{0};
    std::atomic<double> nextReport{double(pass.reportSeconds)};
    std::mutex reportMutex;
    auto line = [&](uint64_t d, double t) {
        char text[128];
        std::snprintf(text, sizeof text, "%llu precomputed, %.1f%% after %.3f hours\n",
                      (unsigned long long)d, count ? 100.0 * double(d) / double(count) : 100.0,
                      t / 3600);
        *progress << text << std::flush;
    };
    auto report = [&] {
        double t = std::chrono::duration<double>(Clock::now() - start).count();
        if (t < nextReport.load(std::memory_order_relaxed)) return;
        std::lock_guard<std::mutex> lock(reportMutex);
        if (t < nextReport.load()) return;
        nextReport.store(t + pass.reportSeconds);
        line(done.load(), t);
    };
    const uint64_t chunks = (count + kPrecompChunk - 1) / kPrecompChunk;
    tbb::task_arena arena(std::max(1, pass.threads));
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<uint64_t>(0, chunks, 1),
            [&](const tbb::blocked_range<uint64_t>& r) {
                for (uint64_t c = r.begin(); c != r.end(); ++c) {
                    const uint64_t i0 = c * kPrecompChunk;
                    const uint64_t i1 = std::min<uint64_t>(count, i0 + kPrecompChunk);
                    work(i0, i1);
                    done.fetch_add(i1 - i0, std::memory_order_relaxed);
                    if (reporting) report();
                }
            },
            tbb::simple_partitioner());
    });
    if (reporting) line(count, std::chrono::duration<double>(Clock::now() - start).count());
}

std::vector<Photon> precomputeGlobal(std::vector<Photon> global, const PrecompSettings& s) {
    std::vector<uint64_t> sel = precompSelection(global.size(), s.fraction, s.pass.seed);
    sortAlongCurve(global, sel.begin(), sel.end());
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
    forEachPrecompChunk(out.size(), s.pass, s.progress, [&](uint64_t i0, uint64_t i1) {
        // A fresh lookup per chunk: its adaptive radius depends on the chunk only.
        PhotonLookup lookup(map, lp);
        for (uint64_t i = i0; i < i1; ++i) {
            Photon& p = out[i];
            std::array<double, 3> e = lookup.surfaceDensity(p.position(), p.normal());
            p.setFlux(e[0], e[1], e[2]);
            p.setCaustic(false);
            p.setDiscr(0);
            p.primary = 0;
        }
    });
    return out;
}

}  // namespace rp::pmap
