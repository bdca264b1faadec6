// Bucket kd-tree index for nearest-photon lookups (see lookup_index.h): build (topology
// from counts, then median partitions as TBB tasks) and the k-nearest search.
#include "pmap/lookup_index.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>

#include "pmap/lookup_heap.h"
#include "util/error.h"

namespace rp::pmap {

namespace {
constexpr uint32_t kLeafTag = 3;
// Subtrees with fewer photons than this are built serially (task overhead would dominate).
constexpr uint32_t kParallelGrain = 1u << 14;

struct Range {
    uint32_t begin, count;
};

typedef float V4 __attribute__((vector_size(16)));
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
    auto layout = [&](auto& self, uint32_t begin, uint32_t count) -> uint32_t {
        const uint32_t id = static_cast<uint32_t>(nodes_.size());
        nodes_.push_back({0, 0, kLeafTag | (count << 2), begin});
        ranges.push_back({begin, count});
        if (count > kLeafSize) {
            const uint32_t nLeft = count / 2;
            self(self, begin, nLeft);
            const uint32_t right = self(self, begin + nLeft, count - nLeft);
            nodes_[id].link = right;
        }
        return id;
    };
    layout(layout, 0, static_cast<uint32_t>(n));

    // Pass 2: median partitions of a permutation, independent subtrees as tasks. Each
    // node's range is partitioned only by its own call, so the result is the same for any
    // number of threads.
    std::vector<uint32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    auto pos = [&](uint32_t i, int a) { return photons[i].pos[a]; };
    auto partition = [&](auto& self, uint32_t id) -> void {
        Node& node = nodes_[id];
        const Range r = ranges[id];
        if (r.count <= kLeafSize) return;
        uint32_t* p = perm.data() + r.begin;
        float lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::numeric_limits<float>::infinity();
            hi[a] = -std::numeric_limits<float>::infinity();
        }
        for (uint32_t i = 0; i < r.count; ++i)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], pos(p[i], a));
                hi[a] = std::max(hi[a], pos(p[i], a));
            }
        const float d0 = hi[0] - lo[0], d1 = hi[1] - lo[1], d2 = hi[2] - lo[2];
        const int axis = d0 >= d1 ? (d0 >= d2 ? 0 : 2) : (d1 >= d2 ? 1 : 2);
        const uint32_t nLeft = r.count / 2;
        std::nth_element(p, p + nLeft, p + r.count,
                         [&](uint32_t a, uint32_t b) { return pos(a, axis) < pos(b, axis); });
        float leftMax = -std::numeric_limits<float>::infinity();
        for (uint32_t i = 0; i < nLeft; ++i) leftMax = std::max(leftMax, pos(p[i], axis));
        node.leftMax = leftMax;
        node.rightMin = pos(p[nLeft], axis);
        node.axisInfo = static_cast<uint32_t>(axis);
        if (parallel && r.count > kParallelGrain) {
            tbb::task_group group;
            group.run([&] { self(self, id + 1); });
            self(self, node.link);
            group.wait();
        } else {
            self(self, id + 1);
            self(self, node.link);
        }
    };
    partition(partition, 0);

    for (int a = 0; a < 3; ++a) {
        boundsLo_[a] = std::numeric_limits<float>::infinity();
        boundsHi_[a] = -std::numeric_limits<float>::infinity();
    }
    for (const Photon& ph : photons)
        for (int a = 0; a < 3; ++a) {
            boundsLo_[a] = std::min(boundsLo_[a], ph.pos[a]);
            boundsHi_[a] = std::max(boundsHi_[a], ph.pos[a]);
        }

    // Leaves are scanned kLeafSize slots at a time (fixed trip count, so the loop
    // vectorises); the padding keeps the last leaf's over-read inside the arrays.
    const size_t padded = n + kLeafSize;
    x_.assign(padded, 0);
    y_.assign(padded, 0);
    z_.assign(padded, 0);
    nx_.assign(padded, 0);
    ny_.assign(padded, 0);
    nz_.assign(padded, 0);
    index_ = std::move(perm);
    auto fill = [&](size_t b, size_t e) {
        for (size_t s = b; s < e; ++s) {
            const Photon& ph = photons[index_[s]];
            x_[s] = ph.pos[0];
            y_[s] = ph.pos[1];
            z_[s] = ph.pos[2];
            nx_[s] = ph.norm[0];
            ny_[s] = ph.norm[1];
            nz_[s] = ph.norm[2];
        }
    };
    if (parallel)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 16),
                          [&](const tbb::blocked_range<size_t>& r) { fill(r.begin(), r.end()); });
    else
        fill(0, n);
}

size_t PhotonIndex::memoryBytes() const {
    return nodes_.capacity() * sizeof(Node) +
           (x_.capacity() + y_.capacity() + z_.capacity()) * sizeof(float) +
           nx_.capacity() + ny_.capacity() + nz_.capacity() +
           index_.capacity() * sizeof(uint32_t);
}

// Why the pruning is exact: `off` holds, per axis, |fl(q - bound)| for the nearest bound of
// the cell (0 inside its slab). Float subtraction, squaring and addition are monotonic, so
// the cell distance off0^2 + off1^2 + off2^2 evaluated in the same order as a photon's
// dist2 is never larger than that of any photon in the cell: skipping cells with
// distance >= maxDist2 never skips a photon the old search would accept.
template <bool kFilter>
void PhotonIndex::searchNode(uint32_t id, float off[3], Search& s) const {
    const Node& node = nodes_[id];
    if ((node.axisInfo & 3) == kLeafTag) {
        const uint32_t b = node.link, count = node.axisInfo >> 2;
        // GCC/Clang vector extensions, 4 lanes: -O2's cheap vectoriser leaves these loops
        // scalar. Each lane computes exactly the scalar expression (no reassociation, no
        // FMA), in the same order as kdtree.cpp, so distances are bit-identical.
        alignas(16) float d2[kLeafSize];
        [[maybe_unused]] alignas(16) float dots[kLeafSize];
        const V4 qx = {s.q[0], s.q[0], s.q[0], s.q[0]}, qy = {s.q[1], s.q[1], s.q[1], s.q[1]},
                 qz = {s.q[2], s.q[2], s.q[2], s.q[2]};
        for (uint32_t i = 0; i < kLeafSize; i += 4) {
            const V4 dx = qx - load4(x_.data() + b + i), dy = qy - load4(y_.data() + b + i),
                     dz = qz - load4(z_.data() + b + i);
            const V4 r = dx * dx + dy * dy + dz * dz;
            std::memcpy(d2 + i, &r, sizeof r);
        }
        if constexpr (kFilter) {
            const V4 n0 = {s.n[0], s.n[0], s.n[0], s.n[0]}, n1 = {s.n[1], s.n[1], s.n[1], s.n[1]},
                     n2 = {s.n[2], s.n[2], s.n[2], s.n[2]};
            for (uint32_t i = 0; i < kLeafSize; i += 4) {
                const V4 r = n0 * load4(nx_.data() + b + i) + n1 * load4(ny_.data() + b + i) +
                             n2 * load4(nz_.data() + b + i);
                std::memcpy(dots + i, &r, sizeof r);
            }
        }
        for (uint32_t i = 0; i < count; ++i) {
            if (d2[i] < s.maxDist2 && (!kFilter || dots[i] > kNormalTolerance))
                offerPhoton(s.heap, s.k, s.found, s.maxDist2, d2[i], index_[b + i]);
        }
        return;
    }
    const int axis = static_cast<int>(node.axisInfo);
    const float qa = s.q[axis];
    const float below = qa - node.leftMax;   // > 0: query above the left child's slab
    const float above = node.rightMin - qa;  // > 0: query below the right child's slab
    uint32_t nearId, farId;
    float cut;
    if (below < above) {  // nearer the left child
        nearId = id + 1;
        farId = node.link;
        cut = above;
    } else {
        nearId = node.link;
        farId = id + 1;
        cut = below;
    }
    searchNode<kFilter>(nearId, off, s);
    const float old = off[axis];
    off[axis] = std::max(old, cut);
    // Unscaled on purpose: any factor > 1 here (an earlier version had 4) prunes cells that
    // lie inside the search radius and loses near photons once k spans several leaves.
    const float rd = off[0] * off[0] + off[1] * off[1] + off[2] * off[2];
    if (rd < s.maxDist2) searchNode<kFilter>(farId, off, s);
    off[axis] = old;
}

size_t PhotonIndex::findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
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
