// Photon records of a map file read and decoded as kd-tree walks first reach them
// (PhotonMap::load with causticOnDemand). For maps that a run may search at only a few
// points: the renderer's caustic maps are looked up about once per primary ray, so the
// Cornell grid of 103 points reads 2,000 blocks (3.4 MB, 127k photons) of a 27 MB map
// instead of decoding and checking a million photons (a tenth of that rtrace run).
//
// Checks. Every record a walk visits is checked as the eager reader checks all of them
// (split axis, finite position) and so is its place in the tree (inside its ancestors'
// splits, as checkKdTreeOrder); a failure is the same InputError naming the file, raised
// by the search that meets it. all() decodes and checks the rest, as PhotonMap::read does.
// The file is read with pread, not mapped: a map overwritten in place while we run (as
// RADIANCE's mkpmap -fo does) then gives a "truncated" error instead of a SIGBUS.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"
#include "util/vec.h"

namespace rp::pmap {

class OnDemandPhotons {
public:
    // Photons [0, n) are the records at byte `offset` of `path`, whose size the caller
    // has checked. Throws InputError if the file cannot be opened.
    OnDemandPhotons(const std::string& path, uint64_t offset, uint64_t n);
    ~OnDemandPhotons();
    OnDemandPhotons(const OnDemandPhotons&) = delete;
    OnDemandPhotons& operator=(const OnDemandPhotons&) = delete;

    size_t size() const { return n_; }

    // As findNearestPhotons (kdtree.h) over the whole map, the same photons in the same
    // order, reading and checking the photons it visits. Thread-safe.
    size_t findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
                       std::span<PhotonHit> out) const;

    // Photon i (0-based), which a findNearest must have returned (or all() been called).
    const Photon& photon(size_t i) const {
        return blocks_[i >> kBlockShift].load(std::memory_order_acquire)[i & kBlockMask];
    }

    // Every photon, decoded and checked (records, then the kd-tree order), as one array;
    // the work is done once, by the first caller. Thread-safe.
    std::span<const Photon> all() const;

private:
    static constexpr int kBlockShift = 6;  // photons are read in blocks of 64 (1.7 kB)
    static constexpr size_t kBlockSize = size_t{1} << kBlockShift;
    static constexpr size_t kBlockMask = kBlockSize - 1;

    const Photon& at(size_t i) const {
        const Photon* b = blocks_[i >> kBlockShift].load(std::memory_order_acquire);
        if (!b) b = readBlock(i >> kBlockShift);
        return b[i & kBlockMask];
    }
    // Reads, decodes and checks block b into the pool (once); returns its photons.
    const Photon* readBlock(size_t b) const;
    struct Reader;  // the kd-tree walk's view of these photons (on_demand_photons.cpp)
    // Reads records [first, first + count) into buf; InputError on a short read.
    void readRecords(size_t first, size_t count, unsigned char* buf) const;

    std::string path_;
    int fd_ = -1;
    uint64_t offset_ = 0;
    size_t n_ = 0;
    // Per block: its decoded and checked photons, or null. Blocks read by walks sit in
    // pool chunks in the order read, so that fresh memory grows with what the walks
    // reach: an array for the whole map, touched all over, cost its size in zeroed pages.
    std::unique_ptr<std::atomic<const Photon*>[]> blocks_;
    mutable std::vector<Photon*> pool_;  // chunks of kPoolBlocks blocks
    mutable size_t poolUsed_ = 0;        // blocks used in the last chunk
    mutable Photon* all_ = nullptr;      // all(): every photon, in order
    mutable std::mutex readMutex_;
    mutable std::once_flag allOnce_;
};

}  // namespace rp::pmap
