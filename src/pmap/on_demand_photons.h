// Photon records of a map file read and decoded as kd-tree walks first reach them
// (PhotonMap::load with onDemand). For maps that a run may search at only a few points:
// the renderer's caustic maps are looked up about once per primary ray, so a sensor grid
// of a hundred points reads a few hundred kB of a 27 MB map instead of decoding and
// checking a million photons (which took a tenth of a Cornell rtrace run).
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

#include "pmap/kdtree.h"
#include "pmap/lookup_heap.h"
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

    // The photon array as far as it is decoded: entries a findNearest returned are valid,
    // others may not be until all().
    std::span<const Photon> decoded() const { return {data_, n_}; }

    // Every photon, decoded and checked (records, then the kd-tree order); the work is done
    // once, by the first caller. Thread-safe.
    std::span<const Photon> all() const;

private:
    static constexpr int kBlockShift = 6;  // photons are read in blocks of 64 (1.7 kB)

    const Photon& at(size_t i) const {
        if (!done_[i >> kBlockShift].load(std::memory_order_acquire)) readBlock(i >> kBlockShift);
        return data_[i];
    }
    void readBlock(size_t block) const;
    // Reads records [first, first + count) into buf; InputError on a short read.
    void readRecords(size_t first, size_t count, unsigned char* buf) const;
    template <bool kFilter>
    size_t walk(const float q[3], const QueryNormal& qn, float maxDist2,
                PhotonHit* heap, size_t k) const;

    std::string path_;
    int fd_ = -1;
    uint64_t offset_ = 0;
    size_t n_ = 0;
    Photon* data_ = nullptr;  // n_ entries, constructed as their blocks are read
    std::unique_ptr<std::atomic<uint8_t>[]> done_;  // per block: decoded and checked
    mutable std::mutex readMutex_;
    mutable std::once_flag allOnce_;
};

}  // namespace rp::pmap
