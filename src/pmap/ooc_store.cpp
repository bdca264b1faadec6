// The out-of-core store (see ooc_store.h): resident top of the tree, per-cursor page
// caches, and the kd-tree walk over both.
#include "pmap/ooc_store.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <vector>

#include "pmap/kdtree_walk.h"
#include "pmap/photon_records.h"
#include "util/error.h"
#include "util/file_write.h"

namespace rp::pmap {

namespace {
constexpr size_t kReadChunkPhotons = size_t{1} << 16;  // resident part: photons per read
constexpr int kWays = 4;                               // pages a cache set can hold

// The largest 2^L - 1 not above both limits: a whole number of tree levels.
uint64_t wholeLevels(uint64_t limit, uint64_t n) {
    const uint64_t m = std::min(limit, n);
    if (m >= n) return n;
    return (uint64_t{1} << (std::bit_width(m + 1) - 1)) - 1;
}
}  // namespace

// A cursor's pages: a set-associative cache (kWays pages per set, least recently used
// replaced) over the pages of the non-resident part, photon p of that part being photon
// resident + p of the map. Each thread has its own (RADIANCE: -aC per process), so a page
// is never evicted under another thread's walk and no lock is taken.
class OutOfCoreStore::PageCache final : public PhotonStore::Cursor {
public:
    PageCache(const OutOfCoreStore& store, uint64_t cachePhotons)
        : store_(store), page_(store.options_.pagePhotons) {
        const uint64_t pages = std::max<uint64_t>(kWays, cachePhotons / page_);
        sets_ = static_cast<size_t>(pages / kWays);
        tags_.assign(sets_ * kWays, ~uint64_t{0});
        used_.assign(sets_ * kWays, 0);
        // Pages are written as read: the cache's memory grows with what the walks reach.
        data_.resize(sets_ * kWays * page_);
    }

    const Photon& at(uint64_t i) {
        const uint64_t page = i / page_;
        const size_t set = static_cast<size_t>((page * 0x9E3779B97F4A7C15ull) >> 32) % sets_;
        size_t way = set * kWays, victim = way;
        for (size_t w = set * kWays; w < (set + 1) * kWays; ++w) {
            if (tags_[w] == page) {
                used_[w] = ++clock_;
                return data_[w * page_ + i % page_];
            }
            if (used_[w] < used_[victim]) victim = w;
        }
        way = victim;
        const uint64_t first = page * page_;
        const size_t count = static_cast<size_t>(std::min<uint64_t>(page_, nonResident() - first));
        tags_[way] = ~uint64_t{0};  // invalid until read and checked
        store_.readPhotons(store_.resident_.size() + first, count, &data_[way * page_], raw_);
        tags_[way] = page;
        used_[way] = ++clock_;
        return data_[way * page_ + i % page_];
    }

    std::vector<PhotonHit> heap;  // the walk's result queue

private:
    uint64_t nonResident() const { return store_.n_ - store_.resident_.size(); }

    const OutOfCoreStore& store_;
    uint64_t page_;
    size_t sets_ = 1;
    std::vector<uint64_t> tags_;  // page held by each way (~0: none)
    std::vector<uint64_t> used_;  // last use, for replacement
    uint64_t clock_ = 0;
    BulkVector<Photon> data_;
    std::vector<unsigned char> raw_;  // a page's records as read
};

struct OutOfCoreStore::Reader {
    static constexpr bool kCheckOrder = true;
    const OutOfCoreStore& store;
    PageCache& cache;
    bool causticOnly, causticExcluded;
    // PhotonQuery::slab: the plane through `q` normal to `n` (unused while slab is 0).
    float q[3], n[3], slab;
    const Photon& at(size_t i) const {
        const uint64_t r = store.resident_.size();
        return i < r ? store.resident_[i] : cache.at(i - r);
    }
    void prefetch(size_t) const {}
    bool accepts(const Photon& p) const {
        return (!causticOnly || p.caustic()) && (!causticExcluded || !p.caustic()) &&
               (!(slab > 0) || std::fabs((p.pos[0] - q[0]) * n[0] + (p.pos[1] - q[1]) * n[1] +
                                         (p.pos[2] - q[2]) * n[2]) < slab) &&
               (!store.options_.keep || store.options_.keep(p));
    }
    [[noreturn]] void misplaced(size_t i) const {
        throw InputError(SourceLoc{store.path_, 0}, treeProblem(misplacedPhoton(i)));
    }
};

OutOfCoreStore::OutOfCoreStore(const std::string& path, uint64_t offset, uint64_t n,
                               Options options)
    : path_(path), offset_(offset), n_(n), options_(std::move(options)) {
    options_.pagePhotons = std::max<uint32_t>(options_.pagePhotons, 1);
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0)
        throw InputError(SourceLoc{path, 0},
                         fmt::format("can't open photon map file: {}", std::strerror(errno)));
    try {
        if (const uint32_t block = options_.checksumBlock) {
            const uint64_t blocks = checksumBlocks(n_, block);
            std::vector<unsigned char> bytes(4 * blocks);
            preadAll(offset_ + n_ * kPhotonRecordSize, bytes.data(), bytes.size(),
                     "truncated photon map (checksums incomplete)");
            checksums_.block = block;
            checksums_.decode(bytes.data(), blocks);
            verified_ = std::make_unique<std::atomic<bool>[]>(blocks);
        }
        resident_.resize(wholeLevels(options_.residentPhotons, n_));
        std::vector<unsigned char> raw;
        for (uint64_t i = 0; i < resident_.size(); i += kReadChunkPhotons)
            readPhotons(i, std::min<uint64_t>(kReadChunkPhotons, resident_.size() - i),
                        resident_.data() + i, raw);
    } catch (...) {
        ::close(fd_);
        throw;
    }
}

OutOfCoreStore::~OutOfCoreStore() {
    if (fd_ >= 0) ::close(fd_);
}

void OutOfCoreStore::preadAll(uint64_t at, unsigned char* dst, size_t want,
                              const char* truncated) const {
    if (!preadFully(fd_, at, dst, want)) throw InputError(SourceLoc{path_, 0}, truncated);
}

void OutOfCoreStore::readRaw(uint64_t first, size_t count, std::vector<unsigned char>& buf) const {
    buf.resize(count * kPhotonRecordSize);
    preadAll(offset_ + first * kPhotonRecordSize, buf.data(), buf.size(),
             fmt::format("truncated photon map (read error at photon {})", first).c_str());
}

void OutOfCoreStore::verifyBlocks(uint64_t first, size_t count) const {
    const uint32_t block = checksums_.block;
    if (!block || count == 0) return;
    std::vector<unsigned char> raw;
    for (uint64_t b = first / block; b <= (first + count - 1) / block; ++b) {
        if (verified_[b].load(std::memory_order_acquire)) continue;
        const uint64_t begin = b * block;
        const size_t n = size_t(std::min<uint64_t>(block, n_ - begin));
        readRaw(begin, n, raw);
        checksums_.check(path_, b, recordsChecksum(raw.data(), raw.size()), n_);
        verified_[b].store(true, std::memory_order_release);
    }
}

void OutOfCoreStore::readPhotons(uint64_t first, size_t count, Photon* dst,
                                 std::vector<unsigned char>& buf) const {
    verifyBlocks(first, count);
    readRaw(first, count, buf);
    for (size_t j = 0; j < count; ++j) dst[j] = decodePhoton(buf.data() + j * kPhotonRecordSize);
    if (const std::string problem = checkPhotonRecords({dst, count}, first); !problem.empty())
        throw InputError(SourceLoc{path_, 0}, treeProblem(problem));
    if (options_.numPrimaries)
        for (size_t j = 0; j < count; ++j)
            if (dst[j].primary >= options_.numPrimaries)
                throw InputError(SourceLoc{path_, 0},
                                 fmt::format("photon refers to primary ray {} of {}",
                                             dst[j].primary, options_.numPrimaries));
}

std::unique_ptr<PhotonStore::Cursor> OutOfCoreStore::makeCursor() const {
    return std::make_unique<PageCache>(*this, options_.cachePhotons);
}

size_t OutOfCoreStore::findNearest(Cursor& cursor, const PhotonQuery& q,
                                   std::vector<FoundPhoton>& out) const {
    PageCache& cache = static_cast<PageCache&>(cursor);
    if (cache.heap.size() < q.k) cache.heap.resize(q.k);
    const bool slab = q.slab > 0 && q.normal;
    const Reader reader{*this,
                        cache,
                        q.causticOnly,
                        q.causticExcluded,
                        {float(q.pos.x), float(q.pos.y), float(q.pos.z)},
                        {slab ? float(q.normal->x) : 0.f, slab ? float(q.normal->y) : 0.f,
                         slab ? float(q.normal->z) : 0.f},
                        slab ? q.slab : 0.f};
    const size_t n = findNearestInKdTree(reader, n_, q.pos, q.normal, q.maxDist2,
                                         std::span<PhotonHit>(cache.heap.data(), q.k));
    // The heap's first entry is the furthest, as the interface asks. A hit's page may
    // have left the cache during the walk; at() reads it again then.
    if (out.size() < n) out.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Photon& p = reader.at(cache.heap[i].index);
        FoundPhoton& f = out[i];
        f.dist2 = cache.heap[i].dist2;
        f.flux = p.flux;
        std::memcpy(f.norm, p.norm, 3);
        f.flags = p.flags;
        f.primary = p.primary;
    }
    return n;
}

std::string OutOfCoreStore::describe() const {
    return fmt::format("out of core ({} photons resident, {} cached per thread in pages of {})",
                       resident_.size(), options_.cachePhotons, options_.pagePhotons);
}

}  // namespace rp::pmap
