// Photon tracing over fixed chunks of photon indices, spread over threads and cluster
// ranks, consumed in chunk order on the root. Chunk c is traced by rank c % ranks (round
// robin: chunks cost about the same, and every rank reaches the end together), so the
// root sees the same chunks in the same order for any number of ranks and threads, and
// the maps it builds are the same bit for bit. The global and caustic distribution
// (distribute.cpp) and the contribution distribution (contrib.cpp) both stream this way.
#pragma once

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "util/cluster.h"

namespace rp::pmap {

// Traces chunks [0, chunks): `trace(c)` returns chunk c's result (a T, run in parallel);
// the root hands every result to `consume(c, result)` in chunk order (serially), the
// other ranks send theirs to the root. T is written and read with
// `encode(ByteWriter&, const T&)` and `decode(ByteReader&, T&)`, found by argument-
// dependent lookup. `cluster` may be null (this process alone). Each rank holds at most
// a few chunks per thread in flight; the root also traces its own share. Returns the
// seconds the root spent decoding and consuming (its serial work per photon, which bounds
// how many ranks can feed it; waiting for chunks not included).
template <class T, class Trace, class Consume>
double streamChunks(Cluster* cluster, tbb::task_arena& arena, int threads, uint64_t chunks,
                    const Trace& trace, const Consume& consume) {
    if (chunks == 0) return 0;
    using Clock = std::chrono::steady_clock;
    Clock::duration serial{};
    const int ranks = cluster ? cluster->size() : 1;
    const int rank = cluster ? cluster->rank() : 0;
    // A chunk in flight: traced here (value), or the root's place holder for a chunk it
    // receives from the rank that traced it (empty).
    using Token = std::shared_ptr<std::optional<T>>;  // TBB tokens must be copyable
    // The root walks every chunk in order; another rank walks its own, c = rank + k*ranks.
    const bool root = rank == 0;
    uint64_t next = root ? 0 : uint64_t(rank);
    const uint64_t step = root ? 1 : uint64_t(ranks);
    // The root's window also holds the chunks in transit from other ranks.
    const size_t tokens = size_t(4 * std::max(1, threads) * (root ? ranks : 1));
    arena.execute([&] {
        tbb::parallel_pipeline(
            tokens,
            tbb::make_filter<void, uint64_t>(tbb::filter_mode::serial_in_order,
                                             [&](tbb::flow_control& fc) -> uint64_t {
                                                 if (next >= chunks) {
                                                     fc.stop();
                                                     return 0;
                                                 }
                                                 const uint64_t c = next;
                                                 next += step;
                                                 return c;
                                             }) &
                tbb::make_filter<uint64_t, std::pair<uint64_t, Token>>(
                    tbb::filter_mode::parallel,
                    [&](uint64_t c) {
                        auto t = std::make_shared<std::optional<T>>();
                        if (int(c % uint64_t(ranks)) == rank) t->emplace(trace(c));
                        return std::make_pair(c, t);
                    }) &
                tbb::make_filter<std::pair<uint64_t, Token>, void>(
                    tbb::filter_mode::serial_in_order, [&](const std::pair<uint64_t, Token>& ct) {
                        const auto& [c, t] = ct;
                        if (!root) {
                            ByteWriter w;
                            encode(w, **t);
                            cluster->send(0, w.bytes());
                            return;
                        }
                        Bytes bytes;
                        if (!t->has_value()) bytes = cluster->receive(int(c % uint64_t(ranks)));
                        const auto t0 = Clock::now();
                        if (!t->has_value()) {
                            ByteReader r(bytes);
                            decode(r, t->emplace());
                            RP_CHECK(r.done());
                        }
                        consume(c, **t);
                        t->reset();
                        serial += Clock::now() - t0;
                    }));
    });
    return std::chrono::duration<double>(serial).count();
}

}  // namespace rp::pmap
