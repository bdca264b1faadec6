// kd-tree build (median partitions in place, TBB tasks over subtrees), validation,
// and the order checks (searches: photon_store.h).
#include "pmap/kdtree.h"

#include <fmt/format.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "pmap/kdtree_select.h"
#include "util/bulk_memory.h"
#include "util/error.h"

namespace rp::pmap {

namespace {

// Subtrees smaller than this are built serially (task overhead would dominate).
constexpr size_t kParallelGrain = size_t{1} << 14;

// Runs left() and right(): as two TBB tasks when `fork`, else one after the other.
template <class Left, class Right>
void forkJoin(bool fork, Left&& left, Right&& right) {
    if (fork) {
        tbb::task_group group;
        group.run(left);
        right();
        group.wait();
    } else {
        left();
        right();
    }
}

// Builds the subtree of the n photons at p in place, in in-order layout (its median at
// kdLeftSubtreeSize(n), with its split axis set). The cell bounds lo/hi are narrowed at
// each split, as RADIANCE does, rather than recomputed from the photons, so the split axes
// are the ones RADIANCE would choose for the same medians. The two children's ranges are
// disjoint, so they are built at once.
void buildSubtree(Photon* p, size_t n, const float lo[3], const float hi[3], bool parallel) {
    if (n == 0) return;
    const int axis = kdSplitAxis(lo, hi);
    if (n == 1) {  // a leaf (half of all nodes): no selection, no empty children to visit
        p[0].setDiscr(axis);
        return;
    }
    const size_t nLeft = kdLeftSubtreeSize(n);
    selectRank(p, n, nLeft, axis, lo[axis], hi[axis]);
    Photon& median = p[nLeft];
    median.setDiscr(axis);

    // Children cells: the split plane bounds the left cell above and the right one below.
    const float split = median.pos[axis];
    float leftHi[3] = {hi[0], hi[1], hi[2]}, rightLo[3] = {lo[0], lo[1], lo[2]};
    leftHi[axis] = split;
    rightLo[axis] = split;
    // Recursion depth is the tree height (<= 33 for kMaxTreePhotons).
    const bool fork = parallel && n > kParallelGrain;
    forkJoin(
        fork, [&] { buildSubtree(p, nLeft, lo, leftHi, fork); },
        [&] { buildSubtree(p + nLeft + 1, n - nLeft - 1, rightLo, hi, fork); });
}

// Copies the in-order layout of buildSubtree (range [s, s + n) of inOrder) into heap order:
// node `root` (1-based) of the subtree gets the median at s + kdLeftSubtreeSize(n).
void gatherHeap(const Photon* inOrder, size_t s, size_t n, size_t root, Photon* out,
                bool parallel) {
    if (n == 0) return;
    if (n == 1) {
        out[root - 1] = inOrder[s];
        return;
    }
    const size_t nLeft = kdLeftSubtreeSize(n);
    out[root - 1] = inOrder[s + nLeft];
    const bool fork = parallel && n > kParallelGrain;
    forkJoin(
        fork, [&] { gatherHeap(inOrder, s, nLeft, 2 * root, out, fork); },
        [&] { gatherHeap(inOrder, s + nLeft + 1, n - nLeft - 1, 2 * root + 1, out, fork); });
}

void checkTreeSize(size_t n) {
    if (n > kMaxTreePhotons)
        throw InputError(
            fmt::format("too many photons for one map ({}; at most {})", n, kMaxTreePhotons));
}

}  // namespace

size_t kdLeftSubtreeSize(size_t n) {
    size_t full = size_t{1} << (std::bit_width(n) - 1);  // largest power of 2 <= n
    size_t half = full >> 1;                             // last-level slots under the left child
    size_t lastLevel = n - (full - 1);                   // nodes on the (partial) last level
    return (half ? half - 1 : 0) + std::min(lastLevel, half);
}

int kdSplitAxis(const float lo[3], const float hi[3]) {
    const float d0 = hi[0] - lo[0], d1 = hi[1] - lo[1], d2 = hi[2] - lo[2];
    return d0 > d1 ? (d0 > d2 ? 0 : 2) : (d1 > d2 ? 1 : 2);
}

size_t kdInOrderIndex(uint64_t node, size_t n) {
    // Down from the root along node's bits, keeping the current subtree's first in-order
    // position s and size m.
    size_t s = 0, m = n;
    for (int bit = std::bit_width(node) - 2; bit >= 0; --bit) {
        const size_t nLeft = kdLeftSubtreeSize(m);
        if ((node >> bit) & 1) {
            s += nLeft + 1;
            m -= nLeft + 1;
        } else {
            m = nLeft;
        }
    }
    return s + kdLeftSubtreeSize(m);
}

void buildKdTreeInOrder(std::span<Photon> photons, const float lo[3], const float hi[3],
                        bool parallel) {
    checkTreeSize(photons.size());
    buildSubtree(photons.data(), photons.size(), lo, hi, parallel);
}

void buildKdTreeInOrder(std::span<Photon> photons, bool parallel) {
    float lo[3], hi[3];
    photonBounds(photons, lo, hi);
    buildKdTreeInOrder(photons, lo, hi, parallel);
}

BulkVector<Photon> buildKdTree(std::vector<Photon> photons, bool parallel) {
    const size_t n = photons.size();
    checkTreeSize(n);
    buildKdTreeInOrder(photons, parallel);
    // On huge pages (BulkVector): 4 KiB page faults on this fresh array cost about as much
    // as the median partitions (util/bulk_memory.h).
    BulkVector<Photon> out(n);
    gatherHeap(photons.data(), 0, n, 1, out.data(), parallel);
    return out;
}

namespace {
// Depth-first over the implicit tree with the cell's bounds changed in place and restored
// on the way back (no per-node copies: a map load checks every photon). Returns the
// 1-based node of the first photon outside its ancestors' splits, or 0.
// Subtrees of at least this many nodes are checked as TBB tasks.
constexpr size_t kCheckGrain = size_t{1} << 16;

size_t firstMisplaced(const Photon* tree, size_t n, size_t node, float lo[3], float hi[3]) {
    const Photon& p = tree[node - 1];
    for (int a = 0; a < 3; ++a)
        if (!(p.pos[a] >= lo[a] && p.pos[a] <= hi[a])) return node;
    const int axis = p.discr();
    const float v = p.pos[axis];
    // A subtree rooted at depth d holds about n / 2^d nodes: large ones in parallel, each
    // with its own cell; the smaller misplaced node of the two is reported either way, so
    // the message does not depend on threads.
    if (2 * node + 1 <= n && (n >> std::bit_width(node)) >= kCheckGrain) {
        float lhi[3] = {hi[0], hi[1], hi[2]}, rlo[3] = {lo[0], lo[1], lo[2]};
        float llo[3] = {lo[0], lo[1], lo[2]}, rhi[3] = {hi[0], hi[1], hi[2]};
        lhi[axis] = v;
        rlo[axis] = v;
        size_t left = 0, right = 0;
        tbb::task_group group;
        group.run([&] { left = firstMisplaced(tree, n, 2 * node, llo, lhi); });
        right = firstMisplaced(tree, n, 2 * node + 1, rlo, rhi);
        group.wait();
        if (left && right) return std::min(left, right);
        return left ? left : right;
    }
    if (2 * node <= n) {
        const float old = hi[axis];
        hi[axis] = v;
        const size_t bad = firstMisplaced(tree, n, 2 * node, lo, hi);
        hi[axis] = old;
        if (bad) return bad;
    }
    if (2 * node + 1 <= n) {
        const float old = lo[axis];
        lo[axis] = v;
        const size_t bad = firstMisplaced(tree, n, 2 * node + 1, lo, hi);
        lo[axis] = old;
        if (bad) return bad;
    }
    return 0;
}
}  // namespace

void photonBounds(std::span<const Photon> photons, float lo[3], float hi[3]) {
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::numeric_limits<float>::infinity();
        hi[a] = -std::numeric_limits<float>::infinity();
    }
    for (const Photon& p : photons)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p.pos[a]);
            hi[a] = std::max(hi[a], p.pos[a]);
        }
}

std::string checkPhotonRecords(std::span<const Photon> tree, size_t first) {
    for (size_t i = 0; i < tree.size(); ++i) {
        const Photon& p = tree[i];
        if (p.discr() > 2) return fmt::format("photon {} has split axis 3", first + i);
        if (!(std::isfinite(p.pos[0]) && std::isfinite(p.pos[1]) && std::isfinite(p.pos[2])))
            return fmt::format("photon {} has a non-finite position", first + i);
    }
    return {};
}

std::string misplacedPhoton(size_t index) {
    return fmt::format("photon {} lies on the wrong side of an ancestor's split", index);
}

std::string checkKdTree(std::span<const Photon> tree) {
    // Per photon first (a flat loop), so that the order walk only compares ordered floats
    // and reads valid split axes.
    if (std::string problem = checkPhotonRecords(tree); !problem.empty()) return problem;
    return checkKdTreeOrder(tree);
}

std::string checkKdTreeOrder(std::span<const Photon> tree) {
    const size_t n = tree.size();
    if (n == 0) return {};
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = -std::numeric_limits<float>::infinity();
        hi[a] = std::numeric_limits<float>::infinity();
    }
    if (const size_t bad = firstMisplaced(tree.data(), n, 1, lo, hi))
        return misplacedPhoton(bad - 1);
    return {};
}

}  // namespace rp::pmap
