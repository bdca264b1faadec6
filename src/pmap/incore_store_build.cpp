// Building the in-core store (incore_store.h): midpoint splits of a 2^21 grid per axis
// made in place on the map's photon records, then the leaf blocks filled from them while
// their memory is given back. The search (incore_store_search.cpp) only needs, per inner
// node, an axis and the exact extent of each child along it, so any tree that gives those
// works.
//
// Why these splits: a range of photons splits at the highest bit, over the three axes'
// cell numbers interleaved x, y, z, at which its photons differ, which is an axis-aligned
// plane at a cell boundary (the tree of sorted Morton codes, Karras 2012, "Maximizing
// parallelism in the construction of BVHs, octrees, and k-d trees"). Such splits suit
// photons on surfaces: bits along which a flat set does not vary are never split on.
//
// How: the records are sorted in place by Morton code, most significant byte first
// (American flag sort, McIlroy, Bostic and McIlroy 1993), with the codes computed from
// the positions whenever needed rather than stored: the build needs no memory beyond the
// records, so the peak of loading a map stays at their 24 bytes per photon. Buckets of at
// most a leaf's photons are not sorted further (a leaf's order does not matter), so a
// million photons take about three passes, where a partition per tree level would take
// one pass per level (18 for 20 M photons).
#include <fmt/format.h>
#include <sys/mman.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <utility>
#include <vector>

#include "pmap/incore_store.h"
#include "util/error.h"

namespace rp::pmap {

namespace {
constexpr uint32_t kLeafTag = 3;
// Photons per task in the parallel passes of the build.
constexpr size_t kGrain = size_t{1} << 14;
constexpr int kBitsPerAxis = 21;
constexpr uint32_t kMaxCell = (1u << kBitsPerAxis) - 1;
// Photon records converted between two releases of their memory.
constexpr size_t kReleaseChunk = size_t{1} << 16;

// Cell numbers in a 2^21 grid per axis over the photons' bounds. Non-decreasing in the
// coordinate (float arithmetic is monotonic), so photons in cells below a split never lie
// above those in cells above it: each split is a true plane.
struct Grid {
    float lo[3], scale[3];
    uint32_t cell(const Photon& p, int a) const {
        const float c = (p.pos[a] - lo[a]) * scale[a];
        return c > 0 ? std::min(kMaxCell, static_cast<uint32_t>(c)) : 0;  // NaN -> 0
    }
};

// kSpread8[b]: bit i of byte b moved to bit 3i.
constexpr std::array<uint32_t, 256> makeSpread8() {
    std::array<uint32_t, 256> t{};
    for (uint32_t v = 0; v < 256; ++v)
        for (int i = 0; i < 8; ++i) t[v] |= ((v >> i) & 1u) << (3 * i);
    return t;
}
constexpr std::array<uint32_t, 256> kSpread8 = makeSpread8();

// Spreads the 21 bits of a cell number to every third bit (bit i goes to bit 3i).
inline uint64_t spreadBits(uint32_t v) {
    return uint64_t{kSpread8[v & 255]} | uint64_t{kSpread8[(v >> 8) & 255]} << 24 |
           uint64_t{kSpread8[(v >> 16) & 31]} << 48;
}

// The photon's Morton code, shifted left by one so that eight whole bytes hold it: bit
// 3i + 3 - a holds bit i of axis a's cell number (x highest within each triple).
[[gnu::always_inline]] inline uint64_t mortonCode(const Grid& g, const Photon& p) {
    return (spreadBits(g.cell(p, 0)) << 3) | (spreadBits(g.cell(p, 1)) << 2) |
           (spreadBits(g.cell(p, 2)) << 1);
}
int axisOfBit(int bit) { return 2 - (bit - 1) % 3; }

// The byte of each photon's code at `shift` into digits[0, n) with their histogram; in
// parallel chunks for a large range.
std::array<size_t, 256> digitsOf(const Photon* a, uint8_t* digits, size_t n, int shift,
                                 const Grid& g, bool parallel) {
    auto run = [&](size_t b, size_t e) {
        std::array<size_t, 256> count{};
        for (size_t i = b; i < e; ++i) {
            const auto d = static_cast<uint8_t>(mortonCode(g, a[i]) >> shift);
            digits[i] = d;
            ++count[d];
        }
        return count;
    };
    if (!parallel || n <= kGrain) return run(0, n);
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, n, kGrain), std::array<size_t, 256>{},
        [&](const tbb::blocked_range<size_t>& r, std::array<size_t, 256> c) {
            const auto mine = run(r.begin(), r.end());
            for (int b = 0; b < 256; ++b) c[b] += mine[b];
            return c;
        },
        [](std::array<size_t, 256> x, const std::array<size_t, 256>& y) {
            for (int b = 0; b < 256; ++b) x[b] += y[b];
            return x;
        });
}

using Node = InCoreStore::Node;

// The sort and the tree in one recursion: after a range is sorted on one byte of the
// codes, the tree's splits within that byte fall at its buckets' boundaries, so the
// nodes are read off the bucket counts (no search, no code computed again).
struct TreeBuild {
    Photon* photons;
    uint8_t* digits;  // scratch: each photon's current byte, moved with it
    const Grid& grid;

    // Sorts photons [begin, begin + count) in place on the byte at `level` (0 = most
    // significant) of their codes; starts[b] is where bucket b begins (starts[256] the end).
    void sortByte(uint32_t begin, uint32_t count, int level, bool parallel,
                  std::array<uint32_t, 257>& starts) const {
        Photon* a = photons + begin;
        uint8_t* d = digits + begin;
        const std::array<size_t, 256> n = digitsOf(a, d, count, 56 - 8 * level, grid, parallel);
        starts[0] = begin;
        for (int b = 0; b < 256; ++b) starts[b + 1] = starts[b] + static_cast<uint32_t>(n[b]);
        std::array<uint32_t, 256> next;
        for (int b = 0; b < 256; ++b) next[b] = starts[b] - begin;
        // Each photon is moved straight to its bucket, the one it displaces carried on.
        for (int b = 0; b < 256; ++b)
            while (next[b] < starts[b + 1] - begin) {
                Photon x = a[next[b]];
                uint8_t digit = d[next[b]];
                while (digit != b) {
                    const uint32_t to = next[digit]++;
                    std::swap(x, a[to]);
                    std::swap(digit, d[to]);
                }
                a[next[b]++] = x;
            }
    }

    // Lays out, depth-first into `out`, the subtree of photons [begin, begin + count),
    // which are buckets [lo, hi) of the byte at `level`, sorted on it (`starts` as
    // sortByte's). Inner nodes' links are relative to out's start, leaves' links the
    // index of their first photon. A range of buckets splits at the highest bit in which
    // its first and last non-empty buckets differ; one bucket goes on to the next byte;
    // photons with identical codes split by count. Depth: at most 63 bit splits plus 32
    // count splits (within the search's stack).
    void layout(uint32_t begin, uint32_t count, int level, const std::array<uint32_t, 257>* starts,
                int lo, int hi, bool parallel, std::vector<Node>& out) const {
        const uint32_t id = static_cast<uint32_t>(out.size());
        if (count <= InCoreStore::kLeafSize) {
            out.push_back({0, 0, kLeafTag | (count << 2), begin});
            return;
        }
        while (starts && (*starts)[lo + 1] == (*starts)[lo]) ++lo;  // first non-empty
        while (starts && (*starts)[hi - 1] == (*starts)[hi]) --hi;  // last non-empty
        if (!starts || hi - lo == 1) {
            if (level + 1 >= 8) {  // identical codes: split by count
                out.push_back({0, 0, 0, 0});
                descend(begin, count / 2, count - count / 2, 8, nullptr, 0, 0, 0, 0, parallel, id,
                        out);
                return;
            }
            std::array<uint32_t, 257> next;
            sortByte(begin, count, level + 1, parallel, next);
            layout(begin, count, level + 1, &next, 0, 256, parallel, out);
            return;
        }
        const int bit = 31 - __builtin_clz(static_cast<unsigned>(lo ^ (hi - 1)));
        const int mid = ((lo >> bit) | 1) << bit;  // first bucket with the bit set
        const uint32_t nLeft = (*starts)[mid] - begin;
        out.push_back({0, 0, static_cast<uint32_t>(axisOfBit(56 - 8 * level + bit)), 0});
        descend(begin, nLeft, count - nLeft, level, starts, lo, mid, mid, hi, parallel, id, out);
    }

    // The two children of node `id`: [begin, begin + nLeft) as buckets [lo0, hi0), the
    // rest as [lo1, hi1); as two tasks for a large range.
    void descend(uint32_t begin, uint32_t nLeft, uint32_t nRight, int level,
                 const std::array<uint32_t, 257>* starts, int lo0, int hi0, int lo1, int hi1,
                 bool parallel, uint32_t id, std::vector<Node>& out) const {
        if (!(parallel && nLeft + nRight > kGrain)) {
            layout(begin, nLeft, level, starts, lo0, hi0, false, out);
            out[id].link = static_cast<uint32_t>(out.size());
            layout(begin + nLeft, nRight, level, starts, lo1, hi1, false, out);
            return;
        }
        std::vector<Node> l, r;
        tbb::task_group group;
        group.run([&] { layout(begin, nLeft, level, starts, lo0, hi0, true, l); });
        layout(begin + nLeft, nRight, level, starts, lo1, hi1, true, r);
        group.wait();
        auto append = [&](const std::vector<Node>& sub) {
            const uint32_t offset = static_cast<uint32_t>(out.size());
            for (Node n : sub) {
                if ((n.axisInfo & 3) != kLeafTag) n.link += offset;
                out.push_back(n);
            }
        };
        append(l);
        out[id].link = static_cast<uint32_t>(out.size());
        append(r);
    }
};

struct Bounds {
    float lo[3], hi[3];
};

// Gives back to the system the memory of the photons below `upTo`, whose records have
// been copied into the leaves and are not read again: whole pages inside the array only,
// so allocator data around it is not touched. `released` is the address up to which
// pages were given back (0 before the first call).
void releaseRecords(std::span<Photon> photons, uintptr_t& released, size_t upTo) {
    constexpr uintptr_t kPage = uintptr_t{2} << 20;
    const auto start = reinterpret_cast<uintptr_t>(photons.data());
    if (released == 0) released = (start + kPage - 1) / kPage * kPage;
    const uintptr_t to = (start + upTo * sizeof(Photon)) / kPage * kPage;
    if (to <= released) return;
    ::madvise(reinterpret_cast<void*>(released), to - released, MADV_DONTNEED);
    released = to;
}

}  // namespace

struct InCoreStore::Build {
    // Fills leaf `id` (node index) from its photons, recording its cell bounds.
    static void fillLeaf(InCoreStore& s, uint32_t id, const Photon* rec, Bounds& box);
};

void InCoreStore::Build::fillLeaf(InCoreStore& s, uint32_t id, const Photon* rec, Bounds& box) {
    Node& node = s.nodes_[id];
    const uint32_t first = node.link, count = node.axisInfo >> 2;
    const uint32_t c4 = paddedCount(count);
    float pos[3 * kLeafSize];
    int8_t nrm[3 * kLeafSize];
    const Photon& p0 = rec[0];
    for (int a = 0; a < 3; ++a) box.lo[a] = box.hi[a] = p0.pos[a];
    bool common = true;  // all photons have p0's normal
    for (uint32_t i = 0; i < c4; ++i) {
        const bool real = i < count;
        const Photon& ph = rec[real ? i : 0];
        for (int a = 0; a < 3; ++a) {
            const float v = real ? ph.pos[a] : 0.f;
            pos[a * c4 + i] = v;
            nrm[a * c4 + i] = real ? ph.norm[a] : int8_t{0};
            if (real) {
                box.lo[a] = std::min(box.lo[a], v);
                box.hi[a] = std::max(box.hi[a], v);
            }
        }
        common = common && ph.norm[0] == p0.norm[0] && ph.norm[1] == p0.norm[1] &&
                 ph.norm[2] == p0.norm[2];
        s.flux_[first + i] = real ? ph.flux : Colr{0, 0, 0, 0};
        if (s.attrs_.contrib) {
            s.flags_[first + i] = real ? ph.flags : uint8_t{0};
            s.primary_[first + i] = real ? ph.primary : 0;
        }
        if (s.attrs_.normals)
            s.norm_[first + i] = real ? std::array<int8_t, 3>{ph.norm[0], ph.norm[1], ph.norm[2]}
                                      : std::array<int8_t, 3>{0, 0, 0};
    }
    // Area per photon for the search's radius guess (incore_store_search.cpp): the two
    // largest extents of the leaf's box (photons lie on surfaces); unknown for one point.
    float ext[3] = {box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]};
    std::sort(ext, ext + 3);
    node.rightMin = count > 1 ? ext[2] * ext[1] / static_cast<float>(count) : 0.f;
    if (common) {
        const unsigned char b[4] = {static_cast<unsigned char>(p0.norm[0]),
                                    static_cast<unsigned char>(p0.norm[1]),
                                    static_cast<unsigned char>(p0.norm[2]), kCommonNormalFlag};
        std::memcpy(&node.leftMax, b, 4);
    }
    unsigned char* block = s.leaves_.data() + kLeafBytesPerSlot * size_t{first};
    std::memcpy(block, pos, 3 * c4 * sizeof(float));
    std::memcpy(block + 3 * c4 * sizeof(float), nrm, 3 * c4);
}

InCoreStore::InCoreStore(std::span<Photon> photons, Attributes attrs, bool parallel, bool consume)
    : attrs_(attrs) {
    const size_t n = photons.size();
    if (n > kMaxTreePhotons)
        throw InputError(
            fmt::format("too many photons for one map ({}; at most {})", n, kMaxTreePhotons));
    if (n == 0) return;
    size_ = n;
    photonBounds(photons, boundsLo_, boundsHi_);
    Grid g;
    for (int a = 0; a < 3; ++a) {
        g.lo[a] = boundsLo_[a];
        const float extent = boundsHi_[a] - boundsLo_[a];
        g.scale[a] = extent > 0 ? static_cast<float>(kMaxCell + 1) / extent : 0.f;
    }
    {
        BulkVector<uint8_t> digits(n);
        const TreeBuild build{photons.data(), digits.data(), g};
        nodes_.reserve(n / 16 + 1);
        build.layout(0, static_cast<uint32_t>(n), -1, nullptr, 0, 0, parallel, nodes_);
    }

    // Slots in depth-first order; the leaves' photons are already contiguous in that order.
    std::vector<uint32_t> leaves;  // node ids of the leaves, in order
    std::vector<uint32_t> firstPhoton;
    size_t numSlots = 0;
    for (uint32_t id = 0; id < nodes_.size(); ++id) {
        Node& node = nodes_[id];
        if ((node.axisInfo & 3) != kLeafTag) continue;
        leaves.push_back(id);
        firstPhoton.push_back(node.link);
        node.link = static_cast<uint32_t>(numSlots);
        numSlots += paddedCount(node.axisInfo >> 2);
    }
    if (numSlots > kMaxTreePhotons)
        throw InputError(fmt::format("too many photons for one map ({})", n));
    leaves_.resize(kLeafBytesPerSlot * numSlots);
    flux_.resize(numSlots);
    if (attrs_.contrib) {
        flags_.resize(numSlots);
        primary_.resize(numSlots);
    }
    if (attrs_.normals) norm_.resize(numSlots);

    // Leaves filled in runs of about kReleaseChunk photons, each run's records given back
    // before the next (the peak stays at the records' size).
    BulkVector<Bounds> bounds(nodes_.size());
    uintptr_t released = 0;
    for (size_t l0 = 0; l0 < leaves.size();) {
        size_t l1 = l0;
        while (l1 < leaves.size() && firstPhoton[l1] - firstPhoton[l0] < kReleaseChunk) ++l1;
        auto fill = [&](size_t b, size_t e) {
            for (size_t l = b; l < e; ++l)
                Build::fillLeaf(*this, leaves[l], photons.data() + firstPhoton[l],
                                bounds[leaves[l]]);
        };
        if (parallel)
            tbb::parallel_for(
                tbb::blocked_range<size_t>(l0, l1, 256),
                [&](const tbb::blocked_range<size_t>& r) { fill(r.begin(), r.end()); });
        else
            fill(l0, l1);
        if (consume) releaseRecords(photons, released, l1 < leaves.size() ? firstPhoton[l1] : n);
        l0 = l1;
    }

    // Inner nodes' extents, children before parents (both have larger ids): the left
    // child's highest and the right child's lowest coordinate along the split axis.
    for (size_t id = nodes_.size(); id-- > 0;) {
        Node& node = nodes_[id];
        if ((node.axisInfo & 3) == kLeafTag) continue;
        const Bounds& l = bounds[id + 1];
        const Bounds& r = bounds[node.link];
        const int axis = static_cast<int>(node.axisInfo);
        node.leftMax = l.hi[axis];
        node.rightMin = r.lo[axis];
        for (int a = 0; a < 3; ++a) {
            bounds[id].lo[a] = std::min(l.lo[a], r.lo[a]);
            bounds[id].hi[a] = std::max(l.hi[a], r.hi[a]);
        }
    }
    nodes_.shrink_to_fit();
}

InCoreStore InCoreStore::copyOf(std::span<const Photon> photons, Attributes attrs, bool parallel) {
    BulkVector<Photon> copy(photons.begin(), photons.end());
    return InCoreStore(copy, attrs, parallel, true);
}

}  // namespace rp::pmap
