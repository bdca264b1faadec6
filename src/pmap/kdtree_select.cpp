// Histogram select for the kd-tree median, in place (see kdtree_select.h for why).
#include "pmap/kdtree_select.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace rp::pmap {

namespace {

// At or below this many photons the range fits in L1 and a histogram of even a few
// buckets costs more than counting each photon's place.
constexpr size_t kSmallRange = 24;
// Widest digit: 2048 counters (8 KiB) stay in L1 beside the streamed photons.
constexpr int kMaxDigitBits = 11;

// Digit width for a range of n photons: about n/4 buckets, so the histogram's clearing
// and prefix scan stay small beside the pass over the photons.
int digitBits(size_t n) {
    return std::clamp(static_cast<int>(std::bit_width(n)) - 2, 3, kMaxDigitBits);
}

void nthElement(Photon* first, Photon* nth, Photon* last, int axis) {
    std::nth_element(first, nth, last,
                     [axis](const Photon& a, const Photon& b) { return photonKeyLess(a, b, axis); });
}

// Sorts the m <= kSmallRange photons at p in key order (which puts every rank in place).
// Each photon's final place is counted from its first two key words (branch-free compares
// the compiler vectorises) and the photons are moved once. Why not std::nth_element: at
// this size its compares mispredict about half the time, and the bottom tree levels
// call it for every node (a quarter of the whole build). Photons whose first two words tie
// (same two coordinates: rare) are sorted on the whole key instead.
void sortSmall(Photon* p, size_t m, int axis) {
    const int second = (axis + 1) % 3;
    uint64_t key[kSmallRange];
    for (size_t i = 0; i < m; ++i)
        key[i] = uint64_t{orderedFloatBits(p[i].pos[axis])} << 32 |
                 orderedFloatBits(p[i].pos[second]);
    uint32_t rank[kSmallRange];
    uint32_t ties = 0;
    for (size_t i = 0; i < m; ++i) {
        const uint64_t x = key[i];
        uint32_t r = 0;
        for (size_t j = 0; j < i; ++j) {
            r += key[j] <= x;
            ties += key[j] == x;
        }
        for (size_t j = i + 1; j < m; ++j) r += key[j] < x;
        rank[i] = r;
    }
    if (ties) {
        std::sort(p, p + m,
                  [axis](const Photon& a, const Photon& b) { return photonKeyLess(a, b, axis); });
        return;
    }
    Photon sorted[kSmallRange];
    for (size_t i = 0; i < m; ++i) sorted[rank[i]] = p[i];
    std::memcpy(p, sorted, m * sizeof(Photon));
}

// Tight bounds of coordinate `c` over [first, last).
void coordRange(const Photon* first, const Photon* last, int c, float& lo, float& hi) {
    lo = hi = first->pos[c];
    for (const Photon* p = first + 1; p < last; ++p) {
        lo = std::min(lo, p->pos[c]);
        hi = std::max(hi, p->pos[c]);
    }
}

// Reorders the m photons at p in place into class 0, then 1, then 2 (cls(photon) in
// {0, 1, 2}), without branches on the class: every step does the same two swaps, some of
// them of a photon with itself. Invariant: [0, j0) class 0, [j0, j1) class 1,
// [j1, i) class 2; a class-1 photon swaps with the first class-2 one, a class-0 photon
// then further with the first class-1 one.
template <class Class>
void partition3(Photon* p, size_t m, Class cls) {
    size_t j0 = 0, j1 = 0;
    for (size_t i = 0; i < m; ++i) {
        const uint32_t c = cls(p[i]);
        const size_t a = c <= 1 ? j1 : i;
        const size_t b = c == 0 ? j0 : a;
        Photon x = p[i];
        p[i] = p[a];
        p[a] = x;
        Photon y = p[a];
        p[a] = p[b];
        p[b] = y;
        j1 += c <= 1;
        j0 += c == 0;
    }
}

}  // namespace

bool photonKeyLess(const Photon& a, const Photon& b, int axis) {
    for (int w = 0; w < kPhotonKeyWords; ++w) {
        const uint32_t x = photonKeyWord(a, axis, w), y = photonKeyWord(b, axis, w);
        if (x != y) return x < y;
    }
    return false;
}

void selectRank(Photon* p, size_t n, size_t k, int axis, float lo, float hi) {
    size_t first = 0, last = n;  // the range still to resolve; k lies in it
    int coord = axis;            // the coordinate selected on: key word (coord - axis) mod 3
    uint32_t count[size_t{1} << kMaxDigitBits];
    while (true) {
        const size_t m = last - first;
        if (m <= kSmallRange) {
            sortSmall(p + first, m, axis);
            return;
        }
        if (!(lo < hi)) {
            // Every photon left has the same coordinate: the next key word decides.
            coord = (coord + 1) % 3;
            if (coord == axis) {  // same position: the rest of the record (rare)
                nthElement(p + first, p + k, p + last, axis);
                return;
            }
            coordRange(p + first, p + last, coord, lo, hi);
            continue;
        }
        // Buckets by (x - lo) * scale: a rounded but monotone map of the coordinate, so a
        // photon in a lower bucket never has a larger coordinate, and equal coordinates
        // share a bucket. Cheaper per photon than bucketing the float's bits.
        const uint32_t lastBucket = (uint32_t{1} << digitBits(m)) - 1;
        const float scale = static_cast<float>(lastBucket + 1) / (hi - lo);
        if (!(scale > 0) || !std::isfinite(scale)) {  // range over/underflows float: rare
            nthElement(p + first, p + k, p + last, axis);
            return;
        }
        const float base = lo;
        const int c = coord;
        auto bucket = [=](const Photon& q) {
            // x >= lo, so the product is >= 0; x == hi can round to lastBucket + 1.
            return std::min(static_cast<uint32_t>((q.pos[c] - base) * scale), lastBucket);
        };
        std::fill_n(count, lastBucket + 1, 0u);
        for (size_t i = first; i < last; ++i) ++count[bucket(p[i])];
        // The bucket b holding rank k, and how many photons sort below it.
        uint32_t b = 0;
        size_t below = 0;
        while (below + count[b] <= k - first) below += count[b++];
        const size_t inBucket = count[b];
        if (inBucket == m) {
            // The bounds were loose: retry with the photons' own. lo and hi of those fall
            // in buckets 0 and lastBucket, so the next pass splits.
            coordRange(p + first, p + last, coord, lo, hi);
            continue;
        }
        partition3(p + first, m, [&](const Photon& q) {
            const uint32_t bk = bucket(q);
            return uint32_t{bk >= b} + uint32_t{bk > b};
        });
        last = first + below + inBucket;
        first = first + below;
        coordRange(p + first, p + last, coord, lo, hi);
    }
}

}  // namespace rp::pmap
