// Histogram select for the kd-tree median (see kdtree_select.h for why).
#include "pmap/kdtree_select.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace rp::pmap {

namespace {

// At or below this many photons the range fits in L1 and a histogram of even a few
// buckets costs more than std::nth_element's comparisons.
constexpr size_t kSmallRange = 24;
// Widest digit: 2048 counters (8 KiB) stay in L1 beside the streamed photons.
constexpr int kMaxDigitBits = 11;
static_assert(kSmallRange < 32, "sortSmall marks ranks in a 32-bit mask");
static_assert(kMaxDigitBits <= 16, "bucket numbers are kept as uint16_t");

// Digit width for a range of n photons: about n/4 buckets, so the histogram's clearing
// and prefix scan stay small beside the pass over the photons.
int digitBits(size_t n) {
    return std::clamp(static_cast<int>(std::bit_width(n)) - 2, 3, kMaxDigitBits);
}

void nthElement(Photon* first, Photon* nth, Photon* last, int axis) {
    std::nth_element(first, nth, last, [axis](const Photon& a, const Photon& b) {
        return a.pos[axis] < b.pos[axis];
    });
}

// Sorts the m <= kSmallRange photons at p on `axis`, equal coordinates keeping their
// order (which puts every rank in place, k's included). Each photon's final place is counted
// (branch-free compares the compiler vectorises) and the photons are moved once. Why not
// std::nth_element: at this size its compares mispredict about half the time, and the
// bottom tree levels call it for every node (a quarter of the whole build).
void sortSmall(Photon* p, size_t m, size_t k, int axis) {
    float key[kSmallRange];
    for (size_t i = 0; i < m; ++i) key[i] = p[i].pos[axis];
    uint32_t rank[kSmallRange];
    uint32_t seen = 0;
    for (size_t i = 0; i < m; ++i) {
        const float x = key[i];
        uint32_t r = 0;
        for (size_t j = 0; j < i; ++j) r += key[j] <= x;  // earlier equal ones go first
        for (size_t j = i + 1; j < m; ++j) r += key[j] < x;
        rank[i] = r;
        seen |= uint32_t{1} << (r & 31);
    }
    if (seen != (uint32_t{1} << m) - 1) {  // NaN: the counts are no permutation
        nthElement(p, p + k, p + m, axis);
        return;
    }
    Photon sorted[kSmallRange];
    for (size_t i = 0; i < m; ++i) sorted[rank[i]] = p[i];
    std::memcpy(p, sorted, m * sizeof(Photon));
}

// Tight bounds of the coordinates of [first, last).
void coordRange(const Photon* first, const Photon* last, int axis, float& lo, float& hi) {
    lo = hi = first->pos[axis];
    for (const Photon* p = first + 1; p < last; ++p) {
        lo = std::min(lo, p->pos[axis]);
        hi = std::max(hi, p->pos[axis]);
    }
}

}  // namespace

Photon* selectRank(Photon* src, Photon* dst, uint16_t* bins, size_t n, size_t k, int axis,
                   float lo, float hi) {
    Photon* cur = src;    // the buffer that holds the answer
    Photon* other = dst;  // scratch for the next scatter
    bool scattered = false;
    size_t first = 0, last = n;  // the range still to resolve; k lies in it
    uint32_t count[size_t{1} << kMaxDigitBits];
    while (true) {
        const size_t m = last - first;
        if (m <= kSmallRange) {
            sortSmall(cur + first, m, k - first, axis);
            return cur;
        }
        if (!(lo < hi)) return cur;  // all coordinates equal (lo <= each <= hi)
        // Buckets by (x - lo) * scale: a rounded but monotone map of the coordinate, so a
        // photon in a lower bucket never has a larger coordinate, and equal coordinates
        // share a bucket. Cheaper per photon than bucketing the float's bits.
        const uint32_t lastBucket = (uint32_t{1} << digitBits(m)) - 1;
        const float scale = static_cast<float>(lastBucket + 1) / (hi - lo);
        if (!(scale > 0) || !std::isfinite(scale)) {  // range over/underflows float: rare
            nthElement(cur + first, cur + k, cur + last, axis);
            return cur;
        }
        const float base = lo;
        auto bucket = [=](const Photon& p) {
            // x >= lo, so the product is >= 0; x == hi can round to lastBucket + 1.
            return std::min(static_cast<uint32_t>((p.pos[axis] - base) * scale), lastBucket);
        };
        std::fill_n(count, lastBucket + 1, 0u);
        for (size_t i = first; i < last; ++i) {
            const uint32_t bk = bucket(cur[i]);
            bins[i] = static_cast<uint16_t>(bk);  // kept for the scatter: saves recomputing it
            ++count[bk];
        }
        // The bucket b holding rank k, and how many photons sort below it.
        uint32_t b = 0;
        size_t below = 0;
        while (below + count[b] <= k - first) below += count[b++];
        const size_t inBucket = count[b];
        if (inBucket == m) {
            // The cell bounds were loose: retry with the photons' own. lo and hi of
            // those fall in buckets 0 and lastBucket, so the next pass splits.
            coordRange(cur + first, cur + last, axis, lo, hi);
            continue;
        }
        // Three-way scatter, branch-free: c = 0 below b, 1 in b, 2 above.
        size_t next[3] = {first, first + below, first + below + inBucket};
        for (size_t i = first; i < last; ++i) {
            const uint32_t bk = bins[i];
            const size_t c = size_t{bk >= b} + size_t{bk > b};
            std::memcpy(other + next[c]++, cur + i, sizeof(Photon));
        }
        if (!scattered) {
            // The first scatter moved every photon: the answer now lives in the other buffer.
            std::swap(cur, other);
            scattered = true;
        } else {
            // Later scatters only cover the (small) bucket's range: copy it back.
            std::memcpy(cur + first, other + first, m * sizeof(Photon));
        }
        last = first + below + inBucket;
        first = first + below;
        coordRange(cur + first, cur + last, axis, lo, hi);
    }
}

}  // namespace rp::pmap
