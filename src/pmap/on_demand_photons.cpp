// Photon records read and checked as walks reach them (see on_demand_photons.h).
#include "pmap/on_demand_photons.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <limits>
#include <new>
#include <vector>

#include "pmap/photon_records.h"
#include "util/bulk_memory.h"
#include "util/error.h"

namespace rp::pmap {

namespace {
constexpr size_t kAllChunkPhotons = size_t{1} << 18;  // all(): photons read per chunk (7 MB)
constexpr size_t kPoolBytes = size_t{2} << 20;        // one huge page per pool chunk
}  // namespace

OnDemandPhotons::OnDemandPhotons(const std::string& path, uint64_t offset, uint64_t n)
    : path_(path), offset_(offset), n_(n) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0)
        throw InputError(SourceLoc{path, 0},
                         fmt::format("can't open photon map file: {}", std::strerror(errno)));
    blocks_ = std::make_unique<std::atomic<const Photon*>[]>((n_ >> kBlockShift) + 1);
}

OnDemandPhotons::~OnDemandPhotons() {
    for (Photon* chunk : pool_) freeHugePages(chunk, kPoolBytes);
    if (all_) freeHugePages(all_, std::max<size_t>(n_, 1) * sizeof(Photon));
    if (fd_ >= 0) ::close(fd_);
}

void OnDemandPhotons::readRecords(size_t first, size_t count, unsigned char* buf) const {
    size_t want = count * kPhotonRecordSize, got = 0;
    const off_t at = static_cast<off_t>(offset_ + first * kPhotonRecordSize);
    while (got < want) {
        ssize_t r = ::pread(fd_, buf + got, want - got, at + static_cast<off_t>(got));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0)
            throw InputError(SourceLoc{path_, 0},
                             fmt::format("truncated photon map (read error at photon {})",
                                         first + got / kPhotonRecordSize));
        got += static_cast<size_t>(r);
    }
}

const Photon* OnDemandPhotons::readBlock(size_t block) const {
    std::lock_guard<std::mutex> lock(readMutex_);
    if (const Photon* b = blocks_[block].load(std::memory_order_relaxed)) return b;  // raced
    const size_t first = block << kBlockShift;
    const size_t count = std::min(n_ - first, kBlockSize);
    unsigned char buf[kBlockSize * kPhotonRecordSize];
    readRecords(first, count, buf);
    constexpr size_t kPoolBlocks = kPoolBytes / (kBlockSize * sizeof(Photon));
    if (pool_.empty() || poolUsed_ == kPoolBlocks) {
        pool_.push_back(static_cast<Photon*>(allocateHugePages(kPoolBytes)));
        poolUsed_ = 0;
    }
    Photon* dst = pool_.back() + poolUsed_ * kBlockSize;
    for (size_t j = 0; j < count; ++j)
        ::new (static_cast<void*>(dst + j)) Photon(decodePhoton(buf + j * kPhotonRecordSize));
    if (const std::string problem = checkPhotonRecords({dst, count}, first); !problem.empty())
        throw InputError(SourceLoc{path_, 0}, treeProblem(problem));
    ++poolUsed_;
    blocks_[block].store(dst, std::memory_order_release);
    return dst;
}

std::span<const Photon> OnDemandPhotons::all() const {
    std::call_once(allOnce_, [&] {
        std::lock_guard<std::mutex> lock(readMutex_);
        Photon* all =
            static_cast<Photon*>(allocateHugePages(std::max<size_t>(n_, 1) * sizeof(Photon)));
        try {
            std::vector<unsigned char> raw;
            for (size_t i = 0; i < n_; i += kAllChunkPhotons) {
                const size_t n = std::min(kAllChunkPhotons, n_ - i);
                raw.resize(n * kPhotonRecordSize);
                readRecords(i, n, raw.data());
                // Isolated: this thread holds the lock, and must not pick up a render task
                // that would wait for it while it waits for the loop.
                tbb::this_task_arena::isolate([&] {
                    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 14),
                                      [&](const tbb::blocked_range<size_t>& r) {
                                          for (size_t j = r.begin(); j < r.end(); ++j)
                                              ::new (static_cast<void*>(all + i + j)) Photon(
                                                  decodePhoton(raw.data() + j * kPhotonRecordSize));
                                      });
                });
            }
            const std::span<const Photon> photons(all, n_);
            std::string problem = checkPhotonRecords(photons);
            if (problem.empty()) problem = checkKdTreeOrder(photons);
            if (!problem.empty()) throw InputError(SourceLoc{path_, 0}, treeProblem(problem));
        } catch (...) {
            freeHugePages(all, std::max<size_t>(n_, 1) * sizeof(Photon));
            throw;
        }
        all_ = all;
        // Walks read the blocks not yet in the pool from here on.
        for (size_t b = 0; b <= (n_ >> kBlockShift); ++b)
            if (!blocks_[b].load(std::memory_order_relaxed))
                blocks_[b].store(all + (b << kBlockShift), std::memory_order_release);
    });
    return {all_, n_};
}

// findNearestPhotons' walk (kdtree.cpp knnSearch: same order, same offers, so the same
// photons), reading photons through at() and carrying each cell's bounds to check that
// every visited photon lies inside its ancestors' splits.
template <bool kFilter>
size_t OnDemandPhotons::walk(const float q[3], const QueryNormal& qn, float maxDist2,
                             PhotonHit* heap, size_t k) const {
    struct Pending {
        uint32_t node;
        float plane2;
        float lo[3], hi[3];
    };
    Pending stack[64];  // at most one pending subtree per level
    int top = 0;
    size_t found = 0, node = 1;
    const size_t n = n_;
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = -std::numeric_limits<float>::infinity();
        hi[a] = std::numeric_limits<float>::infinity();
    }
    while (true) {
        while (node <= n) {
            const Photon& p = at(node - 1);
            for (int a = 0; a < 3; ++a)
                if (!(p.pos[a] >= lo[a] && p.pos[a] <= hi[a]))
                    throw InputError(SourceLoc{path_, 0}, treeProblem(misplacedPhoton(node - 1)));
            const int axis = p.discr();
            const float d = q[axis] - p.pos[axis];
            const size_t farChild = 2 * node + (d >= 0 ? 0 : 1);
            if (farChild <= n && d * d < maxDist2) {
                Pending& f = stack[top++];
                f.node = static_cast<uint32_t>(farChild);
                f.plane2 = d * d;
                for (int a = 0; a < 3; ++a) f.lo[a] = lo[a], f.hi[a] = hi[a];
                (d >= 0 ? f.hi : f.lo)[axis] = p.pos[axis];  // the far side of the split
            }
            const float dx = q[0] - p.pos[0], dy = q[1] - p.pos[1], dz = q[2] - p.pos[2];
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < maxDist2 && (!kFilter || qn.accepts(p)))
                offerPhoton(heap, k, found, maxDist2, d2, static_cast<uint32_t>(node - 1));
            (d >= 0 ? lo : hi)[axis] = p.pos[axis];
            node = 2 * node + (d >= 0 ? 1 : 0);
        }
        do {
            if (top == 0) return found;
            --top;
        } while (stack[top].plane2 >= maxDist2);
        node = stack[top].node;
        for (int a = 0; a < 3; ++a) lo[a] = stack[top].lo[a], hi[a] = stack[top].hi[a];
    }
}

size_t OnDemandPhotons::findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
                                    std::span<PhotonHit> out) const {
    if (out.empty() || n_ == 0) return 0;
    // RADIANCE compat: the query point and normal are compared in single precision.
    const float q[3] = {static_cast<float>(pos.x), static_cast<float>(pos.y),
                        static_cast<float>(pos.z)};
    if (!normal) return walk<false>(q, QueryNormal{}, maxDist2, out.data(), out.size());
    const QueryNormal qn{{static_cast<float>(normal->x), static_cast<float>(normal->y),
                          static_cast<float>(normal->z)}};
    return walk<true>(q, qn, maxDist2, out.data(), out.size());
}

}  // namespace rp::pmap
