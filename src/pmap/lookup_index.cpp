// Bucket kd-tree index for nearest-photon lookups (see lookup_index.h): build (topology
// from counts, then median partitions as TBB tasks) and the k-nearest search.
#include "pmap/lookup_index.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cstring>
#include <cstdint>
#include <limits>

#include "pmap/lookup_heap.h"
#include "util/error.h"

namespace rp::pmap {

namespace {
constexpr uint32_t kLeafTag = 3;
// Subtrees with fewer photons than this are built serially (task overhead would dominate).
constexpr uint32_t kParallelGrain = 1u << 14;
// Photons (or nodes) per task in the copying passes of the build.
constexpr size_t kCopyGrain = size_t{1} << 15;

struct Range {
    uint32_t begin, count;
};

// What the build partitions: a photon's position and its index, 16 bytes, so the median
// selections stream through one compact array instead of gathering 24-byte photons by
// index (a cache miss per comparison once the map is larger than the cache).
struct BuildRecord {
    float pos[3];
    uint32_t index;
};

typedef float V4 __attribute__((vector_size(16)));
typedef int32_t V4i __attribute__((vector_size(16)));
typedef int8_t V4i8 __attribute__((vector_size(4)));
inline V4 load4(const float* p) {
    V4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline V4 load4(const int8_t* p) {
    V4i8 v;
    std::memcpy(&v, p, sizeof v);
    return __builtin_convertvector(v, V4);
}
inline V4 splat(float f) { return V4{f, f, f, f}; }
// Lane i of a comparison result (all ones or zero) becomes bit i.
inline uint32_t laneMask(V4i m) {
#if defined(__SSE2__)
    return static_cast<uint32_t>(__builtin_ia32_movmskps(reinterpret_cast<V4>(m)));
#else
    return (m[0] & 1u) | (m[1] & 2u) | (m[2] & 4u) | (m[3] & 8u);
#endif
}

template <class F>
void forChunks(bool parallel, size_t n, F&& f) {
    if (parallel && n > kCopyGrain)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kCopyGrain),
                          [&](const tbb::blocked_range<size_t>& r) { f(r.begin(), r.end()); });
    else
        f(0, n);
}

// The lowest and highest coordinates of `count` records (lanes x, y, z; lane 3 holds the
// index bits and is ignored), accumulated in record order with exactly std::min/std::max's
// choice per lane (lo keeps its value unless v < lo; NaN never enters), so the result is
// what a scalar loop over the photons in this order gives. One record per step.
struct Box {
    V4 lo, hi;
};
Box recordBounds(const BuildRecord* p, uint32_t count) {
    const float inf = std::numeric_limits<float>::infinity();
    V4 lo = splat(inf), hi = splat(-inf);
    for (uint32_t i = 0; i < count; ++i) {
        V4 v;
        std::memcpy(&v, p + i, sizeof v);
        lo = v < lo ? v : lo;
        hi = hi < v ? v : hi;
    }
    return {lo, hi};
}

template <int kAxis>
void selectMedian(BuildRecord* p, uint32_t nLeft, uint32_t count) {
    std::nth_element(p, p + nLeft, p + count, [](const BuildRecord& a, const BuildRecord& b) {
        return a.pos[kAxis] < b.pos[kAxis];
    });
}
}  // namespace

struct PhotonIndex::Search {
    float q[3];
    float n[3];
    PhotonHit* heap;
    size_t k;
    size_t found;
    float maxDist2;
};

PhotonIndex::PhotonIndex(std::span<const Photon> photons, bool parallel) {
    build(photons, parallel);
}

void PhotonIndex::build(std::span<const Photon> photons, bool parallel) {
    const size_t n = photons.size();
    if (n > kMaxTreePhotons)
        throw InputError(
            fmt::format("too many photons for one map ({}; at most {})", n, kMaxTreePhotons));
    if (n == 0) return;

    // Pass 1, serial and cheap (one entry per node): the tree's shape. Splits are by count
    // (left half = floor(count/2)), so it depends only on n, and node numbers (depth-first,
    // left child right after its parent) are known before any photon is partitioned.
    std::vector<Range> ranges;
    ranges.reserve(2 * (n / (kLeafSize / 2) + 1));
    nodes_.reserve(ranges.capacity());
    size_t numSlots = 0;  // leaves' first slots: multiples of 4, in depth-first order
    auto layout = [&](auto& self, uint32_t begin, uint32_t count) -> uint32_t {
        const uint32_t id = static_cast<uint32_t>(nodes_.size());
        nodes_.push_back({0, 0, kLeafTag | (count << 2), static_cast<uint32_t>(numSlots)});
        ranges.push_back({begin, count});
        if (count <= kLeafSize) numSlots += (count + 3) & ~3u;
        if (count > kLeafSize) {
            const uint32_t nLeft = count / 2;
            self(self, begin, nLeft);
            const uint32_t right = self(self, begin + nLeft, count - nLeft);
            nodes_[id].link = right;
        }
        return id;
    };
    layout(layout, 0, static_cast<uint32_t>(n));
    nodes_.shrink_to_fit();  // the reservation above is an upper bound (about 2x)
    if (numSlots > kMaxTreePhotons)
        throw InputError(fmt::format("too many photons for one map ({})", n));

    // Pass 2: median partitions of work records (photon order to start with), independent
    // subtrees as tasks. Each node's range is partitioned only by its own call, so the
    // result is the same for any number of threads. nth_element on records makes the same
    // comparisons and moves as on a permutation of indices compared through the photons
    // (earlier versions), so the leaves hold the same photons in the same order.
    size_ = n;
    BulkVector<BuildRecord> work(n);
    forChunks(parallel, n, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            const Photon& ph = photons[i];
            work[i] = {{ph.pos[0], ph.pos[1], ph.pos[2]}, static_cast<uint32_t>(i)};
        }
    });
    // Each inner node gets the bounds of its photons from its parent, which scans each
    // child's range once after its median selection (that scan also gives leftMax).
    const Box root = recordBounds(work.data(), static_cast<uint32_t>(n));
    for (int a = 0; a < 3; ++a) {
        boundsLo_[a] = root.lo[a];
        boundsHi_[a] = root.hi[a];
    }
    auto partition = [&](auto& self, uint32_t id, const Box& box) -> void {
        Node& node = nodes_[id];
        const Range r = ranges[id];
        if (r.count <= kLeafSize) return;
        BuildRecord* p = work.data() + r.begin;
        const V4 extent = box.hi - box.lo;
        const float d0 = extent[0], d1 = extent[1], d2 = extent[2];
        const int axis = d0 >= d1 ? (d0 >= d2 ? 0 : 2) : (d1 >= d2 ? 1 : 2);
        const uint32_t nLeft = r.count / 2;
        if (axis == 0)
            selectMedian<0>(p, nLeft, r.count);
        else if (axis == 1)
            selectMedian<1>(p, nLeft, r.count);
        else
            selectMedian<2>(p, nLeft, r.count);
        const Box left = recordBounds(p, nLeft);
        const uint32_t nRight = r.count - nLeft;
        const Box right = nRight > kLeafSize ? recordBounds(p + nLeft, nRight) : Box{};
        node.leftMax = left.hi[axis];
        node.rightMin = p[nLeft].pos[axis];
        node.axisInfo = static_cast<uint32_t>(axis);
        if (parallel && r.count > kParallelGrain) {
            tbb::task_group group;
            group.run([&] { self(self, id + 1, left); });
            self(self, node.link, right);
            group.wait();
        } else {
            self(self, id + 1, left);
            self(self, node.link, right);
        }
    };
    partition(partition, 0, root);

    // Pass 3: the leaves' blocks, written leaf by leaf (in parallel; each leaf writes only
    // its own slots, including its padding, which is zeroed and never used).
    pos_.resize(3 * numSlots);
    nrm_.resize(3 * numSlots);
    flux_.resize(numSlots);
    index_.resize(numSlots);
    forChunks(parallel, nodes_.size(), [&](size_t b, size_t e) {
        for (size_t id = b; id < e; ++id) {
            const Node& node = nodes_[id];
            if ((node.axisInfo & 3) != kLeafTag) continue;
            const uint32_t first = node.link, count = node.axisInfo >> 2;
            const uint32_t c4 = (count + 3) & ~3u;
            float* pos = pos_.data() + 3 * size_t{first};
            int8_t* nrm = nrm_.data() + 3 * size_t{first};
            const BuildRecord* rec = work.data() + ranges[id].begin;
            for (uint32_t i = 0; i < c4; ++i) {
                if (i < count) {
                    const Photon& ph = photons[rec[i].index];
                    for (int a = 0; a < 3; ++a) {
                        pos[a * c4 + i] = rec[i].pos[a];
                        nrm[a * c4 + i] = ph.norm[a];
                    }
                    flux_[first + i] = ph.flux;
                    index_[first + i] = rec[i].index;
                } else {
                    for (int a = 0; a < 3; ++a) {
                        pos[a * c4 + i] = 0;
                        nrm[a * c4 + i] = 0;
                    }
                    flux_[first + i] = {0, 0, 0, 0};
                    index_[first + i] = 0;
                }
            }
        }
    });
}

size_t PhotonIndex::memoryBytes() const {
    return nodes_.capacity() * sizeof(Node) + pos_.capacity() * sizeof(float) +
           nrm_.capacity() + flux_.capacity() * sizeof(Colr) +
           index_.capacity() * sizeof(uint32_t);
}

// Why the pruning is exact: `off` holds, per axis, |fl(q - bound)| for the nearest bound of
// the cell (0 inside its slab). Float subtraction, squaring and addition are monotonic, so
// the cell distance off0^2 + off1^2 + off2^2 evaluated in the same order as a photon's
// dist2 is never larger than that of any photon in the cell: skipping cells with
// distance >= maxDist2 never skips a photon the old search would accept.
//
// The walk is depth-first, nearer child first, as a loop with an explicit stack of far
// children (the recursion of earlier versions, unrolled so that the query, the radius and
// the heap count stay in registers). A far child's cell distance is computed when it is
// pushed and compared with the radius when it is popped, i.e. after the near subtree, as
// the recursion did: the same cells are visited in the same order, so the heap receives
// the same offers.
template <bool kFilter>
void PhotonIndex::searchNode(uint32_t root, float rootOff[3], Search& s) const {
    struct Pending {
        uint32_t node;
        float rd;  // cell distance (squared) of the far child
        float off[3];
    };
    // Depth <= 32: each level halves the count (kMaxTreePhotons < 2^32).
    Pending stack[40];
    int top = 0;
    const float q0 = s.q[0], q1 = s.q[1], q2 = s.q[2];
    const V4 qx = splat(q0), qy = splat(q1), qz = splat(q2);
    [[maybe_unused]] const V4 n0 = splat(s.n[0]), n1 = splat(s.n[1]), n2 = splat(s.n[2]);
    [[maybe_unused]] const V4 tol = splat(kNormalTolerance);
    const float q[3] = {q0, q1, q2};
    PhotonHit* const heap = s.heap;
    const size_t k = s.k;
    size_t found = s.found;
    float maxDist2 = s.maxDist2;
    const Node* const nodes = nodes_.data();
    const float* const positions = pos_.data();
    const int8_t* const normals = nrm_.data();
    float off[3] = {rootOff[0], rootOff[1], rootOff[2]};
    uint32_t id = root;
    for (;;) {
        const Node* node = nodes + id;
        while ((node->axisInfo & 3) != kLeafTag) {
            const int axis = static_cast<int>(node->axisInfo);
            const float qa = q[axis];
            const float below = qa - node->leftMax;   // > 0: query above the left child's slab
            const float above = node->rightMin - qa;  // > 0: query below the right child's slab
            uint32_t nearId, farId;
            float cut;
            if (below < above) {  // nearer the left child
                nearId = id + 1;
                farId = node->link;
                cut = above;
            } else {
                nearId = node->link;
                farId = id + 1;
                cut = below;
            }
            Pending& far = stack[top++];
            far.node = farId;
            far.off[0] = off[0];
            far.off[1] = off[1];
            far.off[2] = off[2];
            far.off[axis] = std::max(off[axis], cut);
            // Unscaled on purpose: any factor > 1 here (an earlier version had 4) prunes
            // cells that lie inside the search radius and loses near photons once k spans
            // several leaves.
            far.rd = far.off[0] * far.off[0] + far.off[1] * far.off[1] + far.off[2] * far.off[2];
            id = nearId;
            node = nodes + id;
        }

        // Leaf. GCC/Clang vector extensions, 4 lanes: -O2's cheap vectoriser leaves these
        // loops scalar. Each lane computes exactly the scalar expression (no reassociation,
        // no FMA), in the same order as kdtree.cpp, so distances are bit-identical. The
        // lanes that pass both tests against the radius at leaf entry form a bit mask; only
        // those are offered, in slot order, each rechecked against the radius as it
        // shrinks, so the heap sees exactly the offers of a plain loop over the leaf
        // (without its unpredictable branch per photon).
        const uint32_t b = node->link, count = node->axisInfo >> 2;
        const uint32_t c4 = (count + 3) & ~3u;
        const float* px = positions + 3 * size_t{b};
        [[maybe_unused]] const int8_t* pn = normals + 3 * size_t{b};
        alignas(16) float d2[kLeafSize];
        const V4 limit = splat(maxDist2);
        uint32_t mask = 0;
        for (uint32_t i = 0; i < c4; i += 4) {
            const V4 dx = qx - load4(px + i), dy = qy - load4(px + c4 + i),
                     dz = qz - load4(px + 2 * c4 + i);
            const V4 r = dx * dx + dy * dy + dz * dz;
            std::memcpy(d2 + i, &r, sizeof r);
            V4i m = r < limit;
            if constexpr (kFilter) {
                const V4 dot = n0 * load4(pn + i) + n1 * load4(pn + c4 + i) +
                               n2 * load4(pn + 2 * c4 + i);
                m &= dot > tol;
            }
            mask |= laneMask(m) << i;
        }
        static_assert(kLeafSize == 32, "the lane mask is one 32-bit word");
        if (count < 32) mask &= (1u << count) - 1;
        while (mask) {
            const uint32_t i = static_cast<uint32_t>(__builtin_ctz(mask));
            mask &= mask - 1;
            if (d2[i] < maxDist2) offerPhoton(heap, k, found, maxDist2, d2[i], b + i);
        }

        // Next: the most recently deferred far child whose cell is still within the radius.
        for (;;) {
            if (top == 0) {
                s.found = found;
                s.maxDist2 = maxDist2;
                return;
            }
            const Pending& far = stack[--top];
            if (far.rd < maxDist2) {
                id = far.node;
                off[0] = far.off[0];
                off[1] = far.off[1];
                off[2] = far.off[2];
                break;
            }
        }
    }
}

size_t PhotonIndex::findNearestSlots(const Vec3& pos, const Vec3* normal, float maxDist2,
                                     std::span<PhotonHit> out) const {
    if (out.empty() || nodes_.empty()) return 0;
    // RADIANCE compat: the query point and normal are compared in single precision.
    Search s{{static_cast<float>(pos.x), static_cast<float>(pos.y), static_cast<float>(pos.z)},
             {0, 0, 0},
             out.data(),
             out.size(),
             0,
             maxDist2};
    float off[3];
    for (int a = 0; a < 3; ++a) {
        const float q = s.q[a];
        off[a] = q < boundsLo_[a] ? boundsLo_[a] - q : (q > boundsHi_[a] ? q - boundsHi_[a] : 0);
    }
    if (!(off[0] * off[0] + off[1] * off[1] + off[2] * off[2] < maxDist2)) return 0;
    if (normal) {
        s.n[0] = static_cast<float>(normal->x);
        s.n[1] = static_cast<float>(normal->y);
        s.n[2] = static_cast<float>(normal->z);
        searchNode<true>(0, off, s);
    } else {
        searchNode<false>(0, off, s);
    }
    return s.found;
}

size_t PhotonIndex::findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
                                std::span<PhotonHit> out) const {
    const size_t found = findNearestSlots(pos, normal, maxDist2, out);
    for (size_t i = 0; i < found; ++i) out[i].index = index_[out[i].index];
    return found;
}

const PhotonIndex& LazyPhotonIndex::get(std::span<const Photon> photons) const {
    std::call_once(state_->once, [&] {
        // Isolated: while this thread waits for its build tasks it must not pick up an
        // outer task that would call get() again and block on the same once_flag.
        tbb::this_task_arena::isolate(
            [&] { state_->index = std::make_unique<PhotonIndex>(photons, true); });
    });
    return *state_->index;
}

}  // namespace rp::pmap
