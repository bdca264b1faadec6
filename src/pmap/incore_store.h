// The in-memory photon store: photons in leaf buckets of a spatial tree, each leaf's
// positions and normals in one contiguous block, searched with vectorised leaf tests.
// The map file's kd-tree order (RADIANCE's heap, kdtree.h) is used only to write and
// check files; a loaded map keeps nothing in that order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iosfwd>
#include <optional>
#include <span>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"
#include "pmap/photon_store.h"
#include "util/bulk_memory.h"
#include "util/colr.h"
#include "util/vec.h"

namespace rp::pmap {

// Why not RADIANCE's heap: it visits one 24-byte photon per node, and the nodes of a
// subtree are spread over the whole array (node i's children at 2i, 2i+1), so below the
// first few levels every node visited is a cache miss. Here the photons of a leaf (at
// most kLeafSize) lie next to each other, nodes are in depth-first order (left child
// follows its parent), and whole leaves are tested with vectorisable loops.
//
// How a search runs (incore_store_search.cpp): the leaf the query falls in gives a photon
// density and so a radius expected to hold about 1.6 k photons; every photon within it is
// collected (no heap: candidates are appended), larger radii follow if fewer than k were
// found, and the k nearest are selected at the end. On the Cornell box's final gather this
// needs about 6.3 leaves and 1.05 passes per k = 51 lookup (leaves of 32 measured 4 %
// slower overall, 48 slower too: once the leaves of a lookup are fetched together,
// testing more photons costs less than walking to more leaves).
//
// Memory per photon: 12 bytes of position, 3 of normal and 4 of RGBE flux, slots padded
// to multiples of 4 per leaf, and 16-byte nodes: about 19.6 bytes. Contribution maps add
// the flags and primary index (5 bytes), volume maps a copy of the incident direction
// by slot (3 bytes) for the phase function. While the store is built from the map's
// 24-byte records, those are released as the leaves are filled, so the peak stays at
// about 24 bytes per photon.
class InCoreStore final : public PhotonStore {
public:
    static constexpr uint32_t kLeafSize = 64;

    // What a store keeps besides position, normal and flux, by map type.
    struct Attributes {
        bool normals = false;  // FoundPhoton::norm (volume maps)
        bool contrib = false;  // FoundPhoton::flags and ::primary (contribution maps)
    };
    static Attributes attributesFor(PhotonMapType type) {
        return {type == PhotonMapType::Volume,
                type == PhotonMapType::Contrib || type == PhotonMapType::PreCompContrib};
    }

    // Builds the store from `photons` (any order), which it reorders in place (midpoint
    // splits of a 2^21 grid per axis over their bounds, incore_store_build.cpp); with
    // `consume` their memory pages are given back to the system as the leaves are filled
    // (the caller only frees them afterwards). `parallel` runs the build as TBB tasks;
    // the result does not depend on the number of threads. At most kMaxTreePhotons.
    InCoreStore(std::span<Photon> photons, Attributes attrs, bool parallel = true,
                bool consume = false);
    // A store over a copy of `photons` (tests).
    static InCoreStore copyOf(std::span<const Photon> photons, Attributes attrs,
                              bool parallel = true);

    // The store as a file that a later run reads instead of building it again
    // (incore_store_index.cpp; PhotonMap::open keeps one beside each map): the arrays as
    // they are in memory, after `key`, the caller's identity of what the store was built
    // from. For this machine only (native byte order). readIndex gives nullopt unless the
    // bytes are complete and undamaged (CRC-32), for this key, these attributes and this
    // photon count, and make a tree the search can walk.
    using IndexKey = std::array<uint64_t, 3>;
    void writeIndex(std::ostream& out, const IndexKey& key) const;
    static std::optional<InCoreStore> readIndex(std::istream& in, const IndexKey& key,
                                                Attributes attrs, uint64_t photons);

    std::unique_ptr<Cursor> makeCursor() const override;
    size_t findNearest(Cursor& cursor, const PhotonQuery& q,
                       std::vector<FoundPhoton>& out) const override;
    uint64_t size() const override { return size_; }
    size_t memoryBytes() const override;
    std::string describe() const override { return "in core"; }

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
    struct Search;  // per-query state (incore_store_search.cpp)

private:
    InCoreStore() = default;  // readIndex
    struct Build;             // incore_store_build.cpp
    struct Index;             // incore_store_index.cpp
    template <bool kFilter>
    void searchNode(uint32_t node, float off[3], Search& s) const;
    // The k nearest as (dist2, slot) in scratch[0..n), the furthest at [0].
    size_t findNearestSlots(const PhotonQuery& q, std::vector<PhotonHit>& scratch) const;

    size_t size_ = 0;
    Attributes attrs_;
    std::vector<Node> nodes_;
    // Slots: each leaf's photons get slots first .. first + count, with `first` a multiple
    // of 4 and the count padded to one (the leaf loops take 4 lanes at a time). A leaf's
    // data is one contiguous block at leaves_[15 first ..]: positions x[c4] y[c4] z[c4]
    // (floats, c4 = padded count), then normals (x 127) likewise as int8, so a leaf test
    // reads one run of memory (the hardware prefetcher follows it; two separate arrays
    // cost a second cache miss per leaf, and a lookup visits about 8 leaves).
    static constexpr size_t kLeafBytesPerSlot = 3 * sizeof(float) + 3;
    BulkVector<unsigned char> leaves_;
    BulkVector<Colr> flux_;                   // RGBE flux, by slot
    BulkVector<uint8_t> flags_;               // Photon::flags by slot (contribution maps)
    BulkVector<uint32_t> primary_;            // primary index by slot (contribution maps)
    BulkVector<std::array<int8_t, 3>> norm_;  // normal by slot (volume maps)
    float boundsLo_[3] = {0, 0, 0}, boundsHi_[3] = {0, 0, 0};
};

}  // namespace rp::pmap
