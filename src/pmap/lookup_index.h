// A cache-friendly search index over a photon map's photons for k-nearest lookups at
// render time: a radix tree over Morton-ordered leaf buckets, with each leaf's positions
// and normals in one contiguous block. The map itself (kdtree.h, RADIANCE's heap order =
// file order) is not touched; the index only adds arrays next to it. Density estimates
// live in density.h.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <span>
#include <utility>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"
#include "util/colr.h"
#include "util/bulk_memory.h"  // BulkVector
#include "util/vec.h"

namespace rp::pmap {

// Why a second structure: RADIANCE's implicit heap visits one 24-byte photon per node, and
// the nodes of a subtree are spread over the whole array (node i's children at 2i, 2i+1),
// so below the first few levels every node visited is a cache miss. Here the photons of a
// leaf (at most kLeafSize) lie next to each other, nodes are in depth-first order (left
// child follows its parent), and whole leaves are tested with vectorisable loops. Searches
// return exactly the photons (and float distances) that findNearestPhotons returns on the
// map's tree, except for ties at the k-th distance.
//
// How a search runs (lookup_index.cpp): the leaf the query falls in gives a photon density
// and so a radius expected to hold about 1.6 k photons; every photon within it is
// collected (no heap: candidates are appended), larger radii follow if fewer than k were
// found, and the k nearest are selected at the end. On the Cornell box's final gather this
// needs about 6.3 leaves and 1.05 passes per k = 51 lookup (9.7 and 1.09 with leaves of
// 32, which measured 4 % slower overall; 48 was slower too: once the leaves of a lookup
// are fetched together, testing more photons costs less than walking to more leaves).
//
// Memory: per photon 12 bytes of position, 3 bytes of normal, 4 bytes of RGBE flux and a
// 4-byte index into the map's photon array (results name photons in file order), slots
// padded to multiples of 4 per leaf, plus 16-byte nodes: about 25.7 bytes/photon with
// kLeafSize 64 (memoryBytes()). The flux copy lets density estimates sum the photons found
// from leaf-ordered memory instead of one cache miss per photon in the map
// (findNearestSlots). The map's own 24 bytes/photon are unchanged. Reordering the map's
// photons into leaf order would save the index and copies but change what photons()
// returns and how files are written (a permutation on save); not done.
class PhotonIndex {
public:
    static constexpr uint32_t kLeafSize = 64;

    // Builds the index over `photons` (any order; results index into this span, which must
    // outlive nothing: positions, normals and flux are copied): photons sorted by Morton
    // code, a radix tree over the codes (lookup_index_build.cpp). The tree depends only on
    // the photons; `parallel` runs the per-photon and per-leaf passes as TBB tasks, with
    // the same result for any number of threads. Requires size() <= kMaxTreePhotons.
    explicit PhotonIndex(std::span<const Photon> photons, bool parallel = true);

    // As findNearestPhotons (kdtree.h): up to out.size() nearest photons with squared
    // distance < maxDist2 and passing the normal filter (kNormalTolerance; none when
    // `normal` is null), the radius shrinking to the furthest kept once `out` is full.
    // Returns the number found; out[0..n) is a max-heap on dist2 (out[0] furthest), with
    // indices into the photon span given to the constructor. Thread-safe; allocates only a
    // per-thread scratch buffer, once, for the largest k used on that thread.
    size_t findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
                       std::span<PhotonHit> out) const;

    // As findNearest, but out[].index are the index's slots (leaf order) instead of photon
    // indices; everything else (the photons found, distances, heap order) is the same,
    // since the heap never looks at indices. photonIndex() maps a slot to the photon, and
    // slotFlux() gives its flux without touching the map (same values as fluxRgb()).
    size_t findNearestSlots(const Vec3& pos, const Vec3* normal, float maxDist2,
                            std::span<PhotonHit> out) const;
    // The same search without the heap: the k nearest (fewer if the radius holds fewer) in
    // scratch[0..n), the furthest at [0] and the others in no particular order; scratch
    // grows as needed (no allocation once large enough). Density estimates need no more.
    size_t findNearestSlots(const Vec3& pos, const Vec3* normal, float maxDist2, size_t k,
                            std::vector<PhotonHit>& scratch) const;
    uint32_t photonIndex(uint32_t slot) const { return index_[slot]; }
    std::array<float, 3> slotFlux(uint32_t slot) const { return colrToRgb(flux_[slot]); }

    size_t size() const { return size_; }
    // Bytes held by the index (not counting the map's photons).
    size_t memoryBytes() const;

    struct Node {
        float leftMax;      // inner: largest coordinate along the split axis in the left child
                            // leaf: the photons' common normal, if any (leafCommonNormal)
        float rightMin;     // inner: smallest in the right child (leftMax <= rightMin)
                            // leaf: area per photon (the radius guess), 0 if unknown
        uint32_t axisInfo;  // inner: split axis 0..2; leaf: 3 | (photon count << 2)
        uint32_t link;      // inner: node index of the right child; leaf: first slot
    };
    // A leaf's normal filter can be tested once when all its photons have the same
    // (quantised) normal; the build records it in the leaf's otherwise unused leftMax as
    // bytes x, y, z and a flag byte.
    static constexpr uint8_t kCommonNormalFlag = 1;
    // Slots a leaf of `count` photons occupies: padded to the 4 lanes of the leaf loops.
    static uint32_t paddedCount(uint32_t count) { return (count + 3) & ~3u; }
    static bool leafCommonNormal(const Node& leaf, int8_t normal[3]) {
        unsigned char b[4];
        std::memcpy(b, &leaf.leftMax, 4);
        std::memcpy(normal, b, 3);
        return b[3] == kCommonNormalFlag;
    }
    struct Search;  // per-query state (lookup_index.cpp)

private:
    void build(std::span<const Photon> photons, bool parallel);
    template <bool kFilter>
    void searchNode(uint32_t node, float off[3], Search& s) const;

    size_t size_ = 0;
    std::vector<Node> nodes_;
    // Slots: each leaf's photons get slots first .. first + count, with `first` a multiple
    // of 4 and the count padded to one (the leaf loops take 4 lanes at a time). A leaf's
    // data is one contiguous block at leaves_[15 first ..]: positions x[c4] y[c4] z[c4]
    // (floats, c4 = padded count), then normals (x 127) likewise as int8, so a leaf test
    // reads one run of memory (the hardware prefetcher follows it; two separate arrays
    // cost a second cache miss per leaf, and a lookup visits about 8 leaves).
    static constexpr size_t kLeafBytesPerSlot = 3 * sizeof(float) + 3;
    BulkVector<unsigned char> leaves_;
    BulkVector<Colr> flux_;        // RGBE flux, by slot
    BulkVector<uint32_t> index_;   // slot -> photon index in the constructor's span
    float boundsLo_[3] = {0, 0, 0}, boundsHi_[3] = {0, 0, 0};
};

// Builds a map's PhotonIndex on first use, exactly once, whichever thread asks first (the
// others wait); the build runs in an isolated TBB arena region so a waiting TBB worker
// cannot re-enter it. Movable (the once-state lives on the heap) so it can sit beside a
// PhotonMap; the photons passed to get() must be the same every call.
class LazyPhotonIndex {
public:
    LazyPhotonIndex() : state_(std::make_unique<State>()) {}
    const PhotonIndex& get(std::span<const Photon> photons) const;

private:
    struct State {
        std::once_flag once;
        std::unique_ptr<PhotonIndex> index;
    };
    std::unique_ptr<State> state_;
};

}  // namespace rp::pmap
