// Histogram select for the kd-tree median, in place (see kdtree_select.h for why).
#include "pmap/kdtree_select.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <vector>

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
    std::nth_element(first, nth, last, [axis](const Photon& a, const Photon& b) {
        return photonKeyLess(a, b, axis);
    });
}

// Each of the m keys' place in their sorted order, equal keys in input order (branch-free
// compares the compiler vectorises). Returns whether any keys are equal.
template <class Key>
bool countRanks(const Key* key, size_t m, uint32_t* rank) {
    uint32_t ties = 0;
    for (size_t i = 0; i < m; ++i) {
        const Key x = key[i];
        uint32_t r = 0;
        for (size_t j = 0; j < i; ++j) {
            r += key[j] <= x;
            ties += key[j] == x;
        }
        for (size_t j = i + 1; j < m; ++j) r += key[j] < x;
        rank[i] = r;
    }
    return ties != 0;
}

// Sorts the m <= kSmallRange photons at p in key order (which puts every rank in place):
// each photon's place is counted from the first key word (the coordinate on axis), or,
// where coordinates repeat, the first two (photons on a floor in a cell split vertically:
// the split axis is the cell's widest, not the photons'), and the photons are moved once.
// Why not std::nth_element: at this size its compares mispredict about half the time, and
// the bottom tree levels call it for every node (a quarter of the whole build). Photons
// that share two coordinates (rare) are sorted on the whole key.
void sortSmall(Photon* p, size_t m, int axis) {
    uint32_t rank[kSmallRange];
    uint32_t key[kSmallRange];
    for (size_t i = 0; i < m; ++i) key[i] = orderedFloatBits(p[i].pos[axis]);
    if (countRanks(key, m, rank)) {
        const int second = (axis + 1) % 3;
        uint64_t key2[kSmallRange];
        for (size_t i = 0; i < m; ++i)
            key2[i] = uint64_t{key[i]} << 32 | orderedFloatBits(p[i].pos[second]);
        if (countRanks(key2, m, rank)) {
            std::sort(p, p + m, [axis](const Photon& a, const Photon& b) {
                return photonKeyLess(a, b, axis);
            });
            return;
        }
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

// Moves the photons of [first, last) for which left() holds before the others, in place;
// returns how many there are. Block-wise, after Edelkamp and Weiss's BlockQuicksort (ESA
// 2016): the misplaced photons of a block at each end are found without branches (their
// offsets written unconditionally, the count advanced by the predicate) and swapped in
// pairs. Why not a branch-free Lomuto loop: its swaps chain each photon's stores into the
// next iteration's loads, which stalled on 24-byte records (2x slower than this).
template <class Pred>
size_t partition2(Photon* first, Photon* last, Pred left) {
    constexpr size_t kBlock = 64;
    uint8_t offL[kBlock], offR[kBlock];
    size_t nL = 0, nR = 0, sL = 0, sR = 0;
    Photon* l = first;  // [first, l) hold left photons
    Photon* r = last;   // [r, last) hold the others
    while (size_t(r - l) > 2 * kBlock) {
        if (nL == 0) {
            sL = 0;
            for (size_t i = 0; i < kBlock; ++i) {
                offL[nL] = uint8_t(i);
                nL += !left(l[i]);
            }
        }
        if (nR == 0) {
            sR = 0;
            for (size_t i = 0; i < kBlock; ++i) {
                offR[nR] = uint8_t(i);
                nR += left(r[-1 - std::ptrdiff_t(i)]);
            }
        }
        const size_t k = std::min(nL, nR);
        for (size_t j = 0; j < k; ++j)
            std::swap(l[offL[sL + j]], r[-1 - std::ptrdiff_t(offR[sR + j])]);
        nL -= k;
        nR -= k;
        sL += k;
        sR += k;
        if (nL == 0) l += kBlock;
        if (nR == 0) r -= kBlock;
    }
    // The rest (a block with photons still misplaced included): [l, r) holds any mix.
    while (true) {
        while (l < r && left(*l)) ++l;
        while (l < r && !left(r[-1])) --r;
        if (l >= r) break;
        std::swap(*l, r[-1]);
    }
    return size_t(l - first);
}

// Ranges up to this size are partitioned through a scratch buffer on the stack (98 kB,
// in L2; uninitialised, so it costs nothing to set up) by a branch-free scatter: the
// lower tree levels are many small ranges, where the block partition's remainder loop
// would mispredict about half its branches.
constexpr size_t kScatterRange = 4096;

// The three-way partition of the m <= kScatterRange photons at p (cls() in {0, 1, 2};
// nBelow of class 0, nIn of class 1) by a scatter into scratch memory and a copy back,
// without branches on the class.
// Not inlined: the buffer must live in this leaf's frame only, not in the frames of the
// recursive tree build that calls it.
template <class Class>
[[gnu::noinline]] void scatter3(Photon* p, size_t m, size_t nBelow, size_t nIn, Class cls) {
    static_assert(std::is_trivially_copyable_v<Photon>);
    alignas(Photon) unsigned char scratch[kScatterRange * sizeof(Photon)];
    Photon* out = reinterpret_cast<Photon*>(scratch);
    size_t next[3] = {0, nBelow, nBelow + nIn};
    for (size_t i = 0; i < m; ++i) std::memcpy(out + next[cls(p[i])]++, p + i, sizeof(Photon));
    std::memcpy(p, out, m * sizeof(Photon));
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
        if (m <= kScatterRange) {
            scatter3(p + first, m, below, inBucket, [&](const Photon& q) {
                const uint32_t bk = bucket(q);
                return size_t{bk >= b} + size_t{bk > b};
            });
        } else {  // three-way partition as two: below b, then b before the rest
            partition2(p + first, p + last, [&](const Photon& q) { return bucket(q) < b; });
            partition2(p + first + below, p + last,
                       [&](const Photon& q) { return bucket(q) == b; });
        }
        last = first + below + inBucket;
        first = first + below;
        coordRange(p + first, p + last, coord, lo, hi);
    }
}

}  // namespace rp::pmap
