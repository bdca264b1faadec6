// The bounded max-heap of nearest-photon results of the kd-tree walks (kdtree.cpp,
// on_demand_photons.cpp), and their normal filter.
// RADIANCE compat: pmapkdt.c keeps a queue of maxGather+1 entries the same way. (The
// bucket index, lookup_index.cpp, collects candidates and selects instead; it keeps the
// same photons up to ties at the k-th distance.)
#pragma once

#include <cstddef>
#include <cstdint>

#include "pmap/kdtree.h"

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

}  // namespace rp::pmap
