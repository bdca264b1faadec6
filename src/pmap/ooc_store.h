// The out-of-core photon store: a map searched from its file, through RADIANCE's kd-tree
// (the file's heap order) and a bounded page cache per thread, for maps larger than
// memory (RADIANCE's out-of-core photon mapping, manual 3.2: -ac page size, -aC cache).
//
// Why the file's own order, not a second layout: a "3.1k" file is already a kd-tree whose
// top levels are the start of the file (node i's children at 2i, 2i+1), so the top of the
// tree is kept resident and shared by every thread (the first 2^L - 1 photons, L as large
// as the resident budget allows), and only the last few levels of a walk come from pages:
// a subtree's nodes at one depth are adjacent in the file, so a page of a few times the
// bandwidth holds the neighbours a lookup needs. The maps stay files RADIANCE reads.
//
// Checks. Every record a walk visits is checked as the eager reader checks them all
// (split axis, finite position) and so is its place in the tree (inside its ancestors'
// splits, as checkKdTreeOrder); a failure is an InputError naming the file, raised by the
// search that meets it. The file is read with pread, not mapped: a map overwritten in
// place while we run (as RADIANCE's mkpmap -fo does) then gives a "truncated" error
// instead of a SIGBUS.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"
#include "pmap/photon_store.h"
#include "pmap/record_checksums.h"
#include "util/bulk_memory.h"

namespace rp::pmap {

class OutOfCoreStore final : public PhotonStore {
public:
    struct Options {
        uint64_t residentPhotons = kDefaultCachePhotons;  // top of the tree kept in memory
        uint64_t cachePhotons = kDefaultCachePhotons;     // per thread (cursor)
        uint32_t pagePhotons = 200;                       // photons per page
        // Photons the search never returns (contribution maps: untracked sources); null
        // keeps all.
        std::function<bool(const Photon&)> keep;
        uint64_t numPrimaries = 0;  // contribution maps: photons' primary index below this
        // Records per checksum, which follow the records (record_checksums.h); 0: none.
        // Each block is checked the first time a read touches it.
        uint32_t checksumBlock = 0;
    };

    // Photons [0, n) are the records at byte `offset` of `path`, whose size the caller
    // has checked. Reads and checks the resident top of the tree now. Throws InputError
    // if the file cannot be opened or the records read are damaged.
    OutOfCoreStore(const std::string& path, uint64_t offset, uint64_t n, Options options);
    ~OutOfCoreStore() override;
    OutOfCoreStore(const OutOfCoreStore&) = delete;
    OutOfCoreStore& operator=(const OutOfCoreStore&) = delete;

    std::unique_ptr<Cursor> makeCursor() const override;
    size_t findNearest(Cursor& cursor, const PhotonQuery& q,
                       std::vector<FoundPhoton>& out) const override;
    uint64_t size() const override { return n_; }
    size_t memoryBytes() const override { return resident_.capacity() * sizeof(Photon); }
    std::string describe() const override;

private:
    class PageCache;  // a cursor's pages (ooc_store.cpp)
    struct Reader;    // the kd-tree walk's view of the photons through a cursor
    // Reads, decodes and checks photons [first, first + count) into dst (`buf` holds the
    // records as read).
    void readPhotons(uint64_t first, size_t count, Photon* dst,
                     std::vector<unsigned char>& buf) const;
    // Reads `want` bytes at byte `at` of the file (InputError `truncated` if it ends).
    void preadAll(uint64_t at, unsigned char* dst, size_t want, const char* truncated) const;
    // Reads the raw records [first, first + count) into buf.
    void readRaw(uint64_t first, size_t count, std::vector<unsigned char>& buf) const;
    // Checks the checksums of the blocks [first, first + count) touches, once each.
    void verifyBlocks(uint64_t first, size_t count) const;

    std::string path_;
    int fd_ = -1;
    uint64_t offset_ = 0;
    uint64_t n_ = 0;
    Options options_;
    BulkVector<Photon> resident_;  // photons [0, resident_.size())
    RecordChecksums checksums_;
    // Blocks whose checksum has been checked (by any thread).
    std::unique_ptr<std::atomic<bool>[]> verified_;
};

}  // namespace rp::pmap
