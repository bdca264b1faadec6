// Median selection for the kd-tree build, in place: a histogram of the coordinates
// (radix-select style) finds the bucket holding the median, then a block-wise three-way
// partition in place sets apart the photons below, in and above it; only that bucket is
// examined again. In place, so that a build needs no second photon buffer (mkpmap's
// memory is the photons and little else). Why not std::nth_element: on 24-byte photons
// its data-dependent comparisons mispredict about half the time.
//
// Ties are broken by a total order on the whole record (photonKeyWord), so which photons
// end up left of a median is a function of the photon set alone, not of the input order
// or the algorithm: the in-core and the external build (kdtree_external.h) give the same
// tree, and so the same file, for the same photons.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "pmap/photon.h"

namespace rp::pmap {

// The float's bits as an unsigned integer in the float's order (-0 counted as +0, so
// that floats that compare equal have equal keys). Finite values only.
inline uint32_t orderedFloatBits(float x) {
    const uint32_t u = std::bit_cast<uint32_t>(x + 0.0f);  // -0 + 0 = +0
    return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}

// The six 32-bit words of a photon's sort key for a split on `axis`, most significant
// first: the coordinate on axis, the next two coordinates (axis + 1, axis + 2, mod 3),
// then the rest of the record (normal and flag byte without the split axis, flux,
// primary). Photons are ordered by these words compared in turn.
constexpr int kPhotonKeyWords = 6;
inline uint32_t photonKeyWord(const Photon& p, int axis, int word) {
    if (word < 3) return orderedFloatBits(p.pos[(axis + word) % 3]);
    if (word == 5) return p.primary;
    unsigned char b[4];
    if (word == 3) {
        std::memcpy(b, p.norm, 3);
        b[3] = p.flags & ~Photon::kDiscrMask;
    } else {
        std::memcpy(b, p.flux.data(), 4);
    }
    return uint32_t{b[0]} << 24 | uint32_t{b[1]} << 16 | uint32_t{b[2]} << 8 | b[3];
}

// Whether a sorts before b in the order of photonKeyWord (a strict weak order; photons
// that differ only in their split axis are equivalent).
bool photonKeyLess(const Photon& a, const Photon& b, int axis);

// Partitions the n photons at p in place around rank k (0 <= k < n) in the order of
// photonKeyWord for `axis`: afterwards no photon before k sorts after p[k] and none
// after k sorts before it. lo / hi: bounds of the coordinates on axis (the cell's; finite,
// lo <= every coordinate <= hi). Positions must be finite.
void selectRank(Photon* p, size_t n, size_t k, int axis, float lo, float hi);

}  // namespace rp::pmap
