// The k-nearest walk over a kd-tree in RADIANCE's heap order, shared by the in-memory tree
// (kdtree.cpp findNearestPhotons) and the out-of-core store (ooc_store.cpp), with its
// bounded max-heap of results and its normal filter.
// RADIANCE compat: pmapkdt.c keeps a queue of maxGather+1 entries the same way. (The
// in-core store, incore_store_search.cpp, collects candidates and selects instead; it keeps the
// same photons up to ties at the k-th distance.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include "pmap/kdtree.h"
#include "util/vec.h"

namespace rp::pmap {

// Query normal scaled for comparison with the int8 photon normals (kNormalTolerance).
struct QueryNormal {
    float n[3];
    bool accepts(const Photon& p) const {
        return n[0] * p.norm[0] + n[1] * p.norm[1] + n[2] * p.norm[2] > kNormalTolerance;
    }
};

// Offers photon `idx` at squared distance d2 (< maxDist2, checked by the caller) to the
// heap heap[0..found) of capacity k (1-based positions internally; heap[0] is the
// furthest). Once the heap is full, maxDist2 shrinks to the furthest kept, so later
// candidates must be strictly nearer.
inline void offerPhoton(PhotonHit* heap, size_t k, size_t& found, float& maxDist2, float d2,
                        uint32_t idx) {
    if (found < k) {
        size_t i = ++found;  // sift up
        while (i > 1 && heap[(i >> 1) - 1].dist2 <= d2) {
            heap[i - 1] = heap[(i >> 1) - 1];
            i >>= 1;
        }
        heap[i - 1] = {d2, idx};
        if (found == k) maxDist2 = heap[0].dist2;
    } else {
        size_t i = 1;  // replace the furthest and sift down
        const size_t half = k >> 1;
        while (i <= half) {
            size_t j = i << 1;
            // The larger child, chosen without a branch (which one is unpredictable).
            if (j < k) j += static_cast<size_t>(heap[j - 1].dist2 < heap[j].dist2);
            if (d2 >= heap[j - 1].dist2) break;
            heap[i - 1] = heap[j - 1];
            i = j;
        }
        heap[i - 1] = {d2, idx};
        maxDist2 = heap[0].dist2;
    }
}

// Iterative search with an explicit stack of far subtrees. Each photon is tested on the way
// down (pre-order) where RADIANCE's recursion tests it after both subtrees; the photons
// found are the same (the k nearest within the radius; among equal distances either may be
// kept) and pre-order with a prefetch of the near grandchildren measured ~1.5x faster.
// `tree` gives photon i (0-based, heap order) by tree.at(i), takes prefetch hints by
// tree.prefetch(i) and may refuse photons by tree.accepts(photon) (filters beyond the
// normal's). With Tree::kCheckOrder the walk carries each cell's bounds and calls
// tree.misplaced(i) (which must throw) for a visited photon outside them: the photons it
// sees are then checked as checkKdTreeOrder would, which maps searched out of core need.
template <bool kFilter, class Tree>
size_t walkKdTree(const Tree& tree, size_t n, const float q[3], const QueryNormal& qn,
                  float maxDist2, PhotonHit* heap, size_t k) {
    struct Cell {
        float lo[3], hi[3];
    };
    struct NoCell {};
    using CellOrNone = std::conditional_t<Tree::kCheckOrder, Cell, NoCell>;
    struct Pending {
        uint32_t node;  // 1-based heap index of a subtree still to visit
        float plane2;   // squared distance from the query to the plane that separated it
        [[no_unique_address]] CellOrNone cell;  // its bounds, when checked
    };
    // Deep enough for any tree of kMaxTreePhotons (at most one pending subtree per level).
    Pending stack[64];
    int top = 0;
    size_t found = 0, node = 1;
    [[maybe_unused]] CellOrNone cell;
    if constexpr (Tree::kCheckOrder)
        for (int a = 0; a < 3; ++a) {
            cell.lo[a] = -std::numeric_limits<float>::infinity();
            cell.hi[a] = std::numeric_limits<float>::infinity();
        }
    while (true) {
        // Descend towards the query, remembering far subtrees that might still matter.
        while (node <= n) {
            const Photon& p = tree.at(node - 1);
            if constexpr (Tree::kCheckOrder)
                for (int a = 0; a < 3; ++a)
                    if (!(p.pos[a] >= cell.lo[a] && p.pos[a] <= cell.hi[a]))
                        tree.misplaced(node - 1);
            const int axis = p.discr();
            const float d = q[axis] - p.pos[axis];
            const size_t nearChild = 2 * node + (d >= 0 ? 1 : 0);
            const size_t farChild = 2 * node + (d >= 0 ? 0 : 1);
            // The near child's two children are adjacent: fetch them while we work here.
            if (2 * nearChild <= n) tree.prefetch(2 * nearChild - 1);
            if (farChild <= n && d * d < maxDist2) {
                Pending& far = stack[top++];
                far.node = static_cast<uint32_t>(farChild);
                far.plane2 = d * d;
                if constexpr (Tree::kCheckOrder) {
                    far.cell = cell;
                    (d >= 0 ? far.cell.hi : far.cell.lo)[axis] = p.pos[axis];
                }
            }
            const float dx = q[0] - p.pos[0], dy = q[1] - p.pos[1], dz = q[2] - p.pos[2];
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < maxDist2 && (!kFilter || qn.accepts(p)) && tree.accepts(p))
                offerPhoton(heap, k, found, maxDist2, d2, static_cast<uint32_t>(node - 1));
            if constexpr (Tree::kCheckOrder) (d >= 0 ? cell.lo : cell.hi)[axis] = p.pos[axis];
            node = nearChild;
        }
        // Resume at the most recent far subtree still within the (shrunken) radius.
        do {
            if (top == 0) return found;
            --top;
        } while (stack[top].plane2 >= maxDist2);
        node = stack[top].node;
        if constexpr (Tree::kCheckOrder) cell = stack[top].cell;
    }
}

// findNearestPhotons' interface over walkKdTree: the query in single precision (RADIANCE
// compat) and the normal filter only when `normal` is given.
template <class Tree>
size_t findNearestInKdTree(const Tree& tree, size_t n, const Vec3& pos, const Vec3* normal,
                           float maxDist2, std::span<PhotonHit> out) {
    if (out.empty() || n == 0) return 0;
    const float q[3] = {static_cast<float>(pos.x), static_cast<float>(pos.y),
                        static_cast<float>(pos.z)};
    if (!normal)
        return walkKdTree<false>(tree, n, q, QueryNormal{}, maxDist2, out.data(), out.size());
    const QueryNormal qn{{static_cast<float>(normal->x), static_cast<float>(normal->y),
                          static_cast<float>(normal->z)}};
    return walkKdTree<true>(tree, n, q, qn, maxDist2, out.data(), out.size());
}

}  // namespace rp::pmap
