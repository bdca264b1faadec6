// RADIANCE's kd-tree over photons (pmapkdt.c), the order of "3.1k" map files: an implicit
// 1-based heap (children of node i at 2i and 2i+1), left-balanced, median split on the
// axis of largest cell extent, split axis in each photon's flag byte. Built here for
// mkpmap's files and checked here when files are read; searches go through the photon
// stores (photon_store.h), the out-of-core one walking this very order (kdtree_walk.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pmap/photon.h"
#include "util/bulk_memory.h"
#include "util/vec.h"

namespace rp::pmap {

// One result of a nearest-photon query: index into the tree array and squared distance.
struct PhotonHit {
    float dist2;
    uint32_t index;
};

// Normal filter: a photon is skipped when dot(n_query, norm_int8) <= kNormalTolerance.
// RADIANCE compat (pmapkdt.c, PMAP_NORM_TOL 0.02): RADIANCE draws the threshold as
// 0.02 * 127 * frandom() per photon test. We use its mean, 0.01 * 127, so that lookups are
// deterministic and independent of thread scheduling; photons nearly perpendicular to the
// query normal (cos < 0.01) are rejected, as RADIANCE does on average.
constexpr float kNormalTolerance = 0.01f * 127.0f;

// Largest map the tree indexes (32-bit photon indices, like RADIANCE's OOC data index).
constexpr uint64_t kMaxTreePhotons = 0xfffffffful;

// The kd-tree build in place, in in-order layout: the root's photon at
// kdLeftSubtreeSize(n), its left subtree's photons before it and its right subtree's
// after it, each subtree laid out the same way; split axes in the flag bytes (other flag
// bits, positions, normals, flux and primary are kept). The heap (file) order is one
// gather away (kdInOrderIndex); mkpmap writes files from this layout directly, so that a
// build needs no second photon array. lo / hi: the cell, the photons' bounds (second form)
// or a subtree's cell in a larger tree (the split axes depend on it). Ties are broken by
// photonKeyLess (kdtree_select.h): the tree depends on the photon set only, not on its
// order. With `parallel`, subtrees above a size threshold are built as TBB tasks; the
// result does not depend on the number of threads. Requires size() <= kMaxTreePhotons and
// finite positions.
void buildKdTreeInOrder(std::span<Photon> photons, const float lo[3], const float hi[3],
                        bool parallel = true);
void buildKdTreeInOrder(std::span<Photon> photons, bool parallel = true);

// Returns the photons reordered into RADIANCE's kd-tree (heap) order: buildKdTreeInOrder,
// then a gather into a new array (maps built in memory: precomputation, tests).
BulkVector<Photon> buildKdTree(std::vector<Photon> photons, bool parallel = true);

// Size of the left subtree of a left-balanced complete tree with n nodes: all levels
// full except the last, which fills left to right (RADIANCE compat: kdT_MedianPartition).
size_t kdLeftSubtreeSize(size_t n);
// RADIANCE compat (kdT_Build): the axis of the cell's largest extent, ties going to the
// later axis exactly as `d0 > d1 ? d0 > d2 ? 0 : 2 : d1 > d2 ? 1 : 2`.
int kdSplitAxis(const float lo[3], const float hi[3]);
// Where heap node `node` (1-based; children of i at 2i and 2i + 1) of a tree of n photons
// lies in the in-order layout of buildKdTreeInOrder (0-based). O(tree height).
size_t kdInOrderIndex(uint64_t node, size_t n);

// The lowest and highest coordinate per axis of the photons (+inf / -inf when empty).
void photonBounds(std::span<const Photon> photons, float lo[3], float hi[3]);

// Checks that `tree` is a valid kd-tree in heap order: split axes 0..2, finite positions,
// every photon in the left subtree of node i has pos[axis] <= node i's, every photon in the
// right subtree >=. Returns "" if valid, else a short description of the first violation.
std::string checkKdTree(std::span<const Photon> tree);
// The per-photon part of checkKdTree (split axis and finite position), without the order.
// Messages number the photons from `first` (for a part of a tree).
std::string checkPhotonRecords(std::span<const Photon> tree, size_t first = 0);
// checkKdTreeOrder's description of photon `index` (0-based) outside its ancestors' splits.
std::string misplacedPhoton(size_t index);
// The order part of checkKdTree alone, for photons whose records pass checkPhotonRecords.
std::string checkKdTreeOrder(std::span<const Photon> tree);

}  // namespace rp::pmap
