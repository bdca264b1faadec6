// Photon records read and checked as walks reach them (see on_demand_photons.h).
#include "pmap/on_demand_photons.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "pmap/kdtree_walk.h"
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
    for (size_t j = 0; j < count; ++j) dst[j] = decodePhoton(buf + j * kPhotonRecordSize);
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
                decodePhotons(raw.data(), n, all + i);
            }
            if (const std::string problem = checkKdTree({all, n_}); !problem.empty())
                throw InputError(SourceLoc{path_, 0}, treeProblem(problem));
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

// walkKdTree reading photons through at() and checking each one's place in the tree.
struct OnDemandPhotons::Reader {
    static constexpr bool kCheckOrder = true;
    const OnDemandPhotons& map;
    const Photon& at(size_t i) const { return map.at(i); }
    void prefetch(size_t) const {}
    [[noreturn]] void misplaced(size_t i) const {
        throw InputError(SourceLoc{map.path_, 0}, treeProblem(misplacedPhoton(i)));
    }
};

size_t OnDemandPhotons::findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
                                    std::span<PhotonHit> out) const {
    return findNearestInKdTree(Reader{*this}, n_, pos, normal, maxDist2, out);
}

}  // namespace rp::pmap
