// External kd-tree build and heap-order writing (see kdtree_external.h).
#include "pmap/kdtree_external.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/kdtree_select.h"
#include "util/bulk_memory.h"
#include "util/error.h"

namespace rp::pmap {

namespace {

// Heap nodes per write of writeSubtreeHeap: 16384 photons (393 kB, 442 kB encoded).
constexpr uint64_t kNodesPerWrite = uint64_t{1} << 14;
// Photons per read or write of a part file (1.5 MB).
constexpr size_t kBlockPhotons = size_t{1} << 16;
// The sort key (6 words of 32 bits) in digits of 16 bits: 65536 counters per histogram.
constexpr int kDigits = 2 * kPhotonKeyWords;
constexpr size_t kDigitValues = size_t{1} << 16;

// Copies the photons of heap level `levelsBelow` under `node` (local numbering, root 1)
// whose level positions fall in [a, b) to out[position - a]. Subtrees outside the window
// are skipped, so a window costs about its own size plus the tree's height.
void gatherLevel(const Photon* inOrder, size_t m, uint64_t node, int levelsBelow, uint64_t a,
                 uint64_t b, Photon* out) {
    if (m == 0 || (node + 1) << levelsBelow <= a || node << levelsBelow >= b) return;
    const size_t nLeft = kdLeftSubtreeSize(m);
    if (levelsBelow == 0) {
        out[node - a] = inOrder[nLeft];
        return;
    }
    gatherLevel(inOrder, nLeft, 2 * node, levelsBelow - 1, a, b, out);
    gatherLevel(inOrder + nLeft + 1, m - nLeft - 1, 2 * node + 1, levelsBelow - 1, a, b, out);
}

// Digit d (0 = most significant) of p's sort key for `axis`.
uint32_t keyDigit(const Photon& p, int axis, int d) {
    const uint32_t w = photonKeyWord(p, axis, d / 2);
    return d % 2 ? w & 0xffffu : w >> 16;
}

// A median found by selectMedian: the first `digits` digits of its sort key, how many
// photons have smaller keys on those digits, and how many share them.
struct MedianPrefix {
    int digits = 0;
    std::array<uint32_t, kDigits> digit{};
    uint64_t below = 0;
    uint64_t ties = 0;
};

// -1, 0 or 1 as p's key on the prefix's digits is below, equal to or above it.
int comparePrefix(const Photon& p, int axis, const MedianPrefix& key) {
    for (int d = 0; d < key.digits; ++d) {
        const uint32_t v = keyDigit(p, axis, d);
        if (v != key.digit[size_t(d)]) return v < key.digit[size_t(d)] ? -1 : 1;
    }
    return 0;
}

// Calls fn(photon) for the n photons of f, in file order.
template <class Fn>
void forEachPhoton(const TempFile& f, uint64_t n, std::vector<Photon>& block, Fn fn) {
    block.resize(kBlockPhotons);
    for (uint64_t i = 0; i < n; i += kBlockPhotons) {
        const size_t m = size_t(std::min<uint64_t>(kBlockPhotons, n - i));
        f.readAt(i * sizeof(Photon), block.data(), m * sizeof(Photon));
        for (size_t j = 0; j < m; ++j) fn(block[j]);
    }
}

// Appends photons to a part file a block at a time.
class PartWriter {
public:
    explicit PartWriter(TempFile& f) : f_(f) { buf_.reserve(kBlockPhotons); }
    void put(const Photon& p) {
        buf_.push_back(p);
        if (buf_.size() == kBlockPhotons) flush();
    }
    void flush() {
        f_.append(buf_.data(), buf_.size() * sizeof(Photon));
        buf_.clear();
    }

private:
    TempFile& f_;
    std::vector<Photon> buf_;
};

// The photon of rank k on `axis` (in photonKeyLess's order) among the n of f, as a key
// prefix: one histogram pass per 16-bit digit, most significant first, each counting the
// photons that share the digits found so far, until one photon is left (two passes for
// distinct coordinates, more for photons on a plane) or the keys are exhausted.
MedianPrefix selectMedian(const TempFile& f, uint64_t n, uint64_t k, int axis,
                          std::vector<Photon>& block) {
    MedianPrefix key;
    std::vector<uint64_t> count(kDigitValues);
    uint64_t candidates = n;
    for (int d = 0; d < kDigits && candidates > 1; ++d) {
        std::fill(count.begin(), count.end(), 0);
        forEachPhoton(f, n, block, [&](const Photon& p) {
            if (comparePrefix(p, axis, key) == 0) ++count[keyDigit(p, axis, d)];
        });
        uint32_t v = 0;
        while (key.below + count[v] <= k) key.below += count[v++];
        key.digit[size_t(d)] = v;
        key.digits = d + 1;
        candidates = count[v];
    }
    key.ties = candidates;
    return key;
}

// Splits the n photons of `part` around its rank-k photon: those below to `left` (k of
// them), above to `right`; returns the median. Photons with the median's whole key are
// interchangeable (kdtree_select.h), so they are shared out in file order.
Photon partitionPart(const TempFile& part, uint64_t n, uint64_t k, int axis,
                     const MedianPrefix& key, TempFile& left, TempFile& right,
                     std::vector<Photon>& block) {
    PartWriter l(left), r(right);
    const uint64_t equalToLeft = k - key.below;
    uint64_t equal = 0;
    Photon median;
    forEachPhoton(part, n, block, [&](const Photon& p) {
        int c = comparePrefix(p, axis, key);
        if (c == 0) {
            if (equal == equalToLeft) median = p;
            c = equal < equalToLeft ? -1 : equal == equalToLeft ? 0 : 1;
            ++equal;
        }
        if (c < 0) l.put(p);
        if (c > 0) r.put(p);
    });
    l.flush();
    r.flush();
    RP_CHECK(equal == key.ties && left.size() == k * sizeof(Photon));
    return median;
}

void buildInCore(const TempFile& part, uint64_t n, uint64_t root, const float lo[3],
                 const float hi[3], HeapSink& sink, const ExternalBuildSettings& s) {
    BulkVector<Photon> photons;
    photons.resize(n);
    part.readAt(0, photons.data(), n * sizeof(Photon));
    buildKdTreeInOrder(photons, lo, hi, s.parallel);
    writeSubtreeHeap(photons, root, sink, s.parallel);
}

// Builds the subtree at heap node `root` from the n photons of `part` in cell lo / hi.
void buildPart(TempFile part, uint64_t n, uint64_t root, const float lo[3], const float hi[3],
               HeapSink& sink, const ExternalBuildSettings& s) {
    if (n == 0) return;
    if (n <= std::max<uint64_t>(s.inCorePhotons, 1)) {
        buildInCore(part, n, root, lo, hi, sink, s);
        return;
    }
    const int axis = kdSplitAxis(lo, hi);
    const uint64_t k = kdLeftSubtreeSize(n);
    std::vector<Photon> block;
    const MedianPrefix key = selectMedian(part, n, k, axis, block);
    TempFile left(s.folder, s.what), right(s.folder, s.what);
    Photon median = partitionPart(part, n, k, axis, key, left, right, block);
    { TempFile done = std::move(part); }  // its disk space back before the children's
    std::vector<Photon>().swap(block);
    median.setDiscr(axis);
    sink.write(root, std::span<const Photon>(&median, 1));

    // Children cells: the split plane bounds the left cell above and the right one below.
    float leftHi[3] = {hi[0], hi[1], hi[2]}, rightLo[3] = {lo[0], lo[1], lo[2]};
    leftHi[axis] = median.pos[axis];
    rightLo[axis] = median.pos[axis];
    buildPart(std::move(left), k, 2 * root, lo, leftHi, sink, s);
    buildPart(std::move(right), n - k - 1, 2 * root + 1, rightLo, hi, sink, s);
}

}  // namespace

void writeSubtreeHeap(std::span<const Photon> inOrder, uint64_t root, HeapSink& sink,
                      bool parallel) {
    const uint64_t m = inOrder.size();
    // Pieces: (level, first position on the level, count), at most kNodesPerWrite each.
    struct Piece {
        int level;
        uint64_t first, count;
    };
    std::vector<Piece> pieces;
    for (int level = 0; (uint64_t{1} << level) <= m; ++level) {
        const uint64_t width = std::min(uint64_t{1} << level, m + 1 - (uint64_t{1} << level));
        for (uint64_t i = 0; i < width; i += kNodesPerWrite)
            pieces.push_back({level, i, std::min(kNodesPerWrite, width - i)});
    }
    auto writePiece = [&](const Piece& p) {
        std::vector<Photon> buf(p.count);
        const uint64_t a = (uint64_t{1} << p.level) + p.first;  // local heap nodes [a, a + count)
        gatherLevel(inOrder.data(), m, 1, p.level, a, a + p.count, buf.data());
        sink.write((root << p.level) + p.first, buf);
    };
    if (parallel)
        tbb::parallel_for(size_t{0}, pieces.size(), [&](size_t i) { writePiece(pieces[i]); });
    else
        for (const Piece& p : pieces) writePiece(p);
}

void buildKdTreeExternal(TempFile photons, uint64_t n, const float lo[3], const float hi[3],
                         HeapSink& sink, const ExternalBuildSettings& settings) {
    RP_CHECK(photons.size() == n * sizeof(Photon));
    if (n > kMaxTreePhotons)
        throw InputError(
            SourceLoc{settings.what, 0},
            fmt::format("too many photons for one map ({}; at most {})", n, kMaxTreePhotons));
    buildPart(std::move(photons), n, 1, lo, hi, sink, settings);
}

}  // namespace rp::pmap
