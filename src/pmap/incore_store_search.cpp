// The in-core store's k-nearest search (see incore_store.h; the build is in
// incore_store_build.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "pmap/incore_store.h"

namespace rp::pmap {

namespace {
constexpr uint32_t kLeafTag = 3;
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
// Eight lanes where the leaf loops can take them (AVX: one instruction per step; without
// it the compiler splits each into two four-lane ones).
typedef float V8 __attribute__((vector_size(32)));
typedef int32_t V8i __attribute__((vector_size(32)));
inline V8 load8(const float* p) {
    V8 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline V8 splat8(float f) { return V8{f, f, f, f, f, f, f, f}; }
inline uint32_t laneMask8(V8i m) {
#if defined(__AVX__)
    return static_cast<uint32_t>(__builtin_ia32_movmskps256(reinterpret_cast<V8>(m)));
#else
    uint32_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= (m[i] & 1u) << i;
    return bits;
#endif
}
// kAxisLane[a]: all ones in lane a.
constexpr V4i kAxisLane[3] = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}};
// Lane i of a comparison result (all ones or zero) becomes bit i.
inline uint32_t laneMask(V4i m) {
#if defined(__SSE2__)
    return static_cast<uint32_t>(__builtin_ia32_movmskps(reinterpret_cast<V4>(m)));
#else
    return (m[0] & 1u) | (m[1] & 2u) | (m[2] & 4u) | (m[3] & 8u);
#endif
}

}  // namespace

struct InCoreStore::Search {
    float q[3];
    float n[3];
    PhotonHit* buf;  // candidates, cap >= k + kLeafSize entries
    size_t cap;
    size_t k;
    size_t found;
    float maxDist2;
    // Non-zero: maxDist2 is only the limit, and the walk sets the pass's radius from the
    // first leaf it reaches (the query's own: nearer child first), guessed to hold about
    // kGuessMargin x guessK photons, reported in `bound`.
    size_t guessK = 0;
    float bound = 0;
    const uint8_t* causticFlags = nullptr;        // non-null: only photons whose caustic bit is
    uint8_t causticWanted = Photon::kCausticBit;  // this
    float slab = 0;  // > 0: only photons this near the plane through q normal to n
};

namespace {
struct Nearer {
    bool operator()(const PhotonHit& a, const PhotonHit& b) const { return a.dist2 < b.dist2; }
};
// Sorts a[lo..hi) by distance: for the few candidates left at the end of a selection.
void insertionSort(PhotonHit* a, size_t lo, size_t hi) {
    for (size_t i = lo + 1; i < hi; ++i) {
        const PhotonHit t = a[i];
        size_t j = i;
        for (; j > lo && t.dist2 < a[j - 1].dist2; --j) a[j] = a[j - 1];
        a[j] = t;
    }
}
// Moves the k nearest of a[0..n) (0 < k <= n) to a[0..k), the k-th nearest to a[k-1];
// tmp has room for n. Quickselect whose partitions write every candidate to both ends of
// tmp and advance one end: no branch on the coin-toss comparison (std::nth_element
// mispredicted about half of them) and, unlike an in-place branch-free swap, no store
// that the next step must wait for. Deterministic: the pivots depend only on the input.
void selectNearest(PhotonHit* a, PhotonHit* tmp, size_t n, size_t k) {
    size_t lo = 0, hi = n;
    const size_t target = k - 1;
    while (hi - lo > 16) {
        const float x = a[lo].dist2, y = a[lo + (hi - lo) / 2].dist2, z = a[hi - 1].dist2;
        const float pivot = std::max(std::min(x, y), std::min(std::max(x, y), z));
        // Nearer than the pivot to the front of tmp[lo, hi), the others to the back; if
        // nothing is nearer, split off the candidates at the pivot's distance instead, so
        // every pass makes progress.
        for (int pass = 0; pass < 2; ++pass) {
            size_t front = lo, back = hi;
            for (size_t i = lo; i < hi; ++i) {
                const PhotonHit t = a[i];
                const bool near = pass == 0 ? t.dist2 < pivot : t.dist2 <= pivot;
                tmp[front] = t;
                tmp[back - 1] = t;
                front += near;
                back -= !near;
            }
            std::copy(tmp + lo, tmp + hi, a + lo);
            if (front > lo || pass == 1) {
                if (front == hi) return;  // pass 1: every candidate is at the pivot's distance
                if (target < front)
                    hi = front;
                else
                    lo = front;
                break;
            }
        }
    }
    insertionSort(a, lo, hi);  // few left
}

// The k nearest of a[0..n) (0 < k <= n, every dist2 < bound or, after a cut, <= it) in
// a[0..k), the k-th nearest at a[0] and the others in no particular order; tmp has room
// for n. Why not a quickselect: density estimates need neither order nor the exact
// partition steps, only which candidates are among the k nearest. Squared distances are
// proportional to the disc area, so kBuckets equal steps of dist2 hold similar counts on
// a surface: one pass counts candidates per step (monotonic float arithmetic, so a nearer
// candidate never lands in a later step), the step holding the k-th is found from the
// counts, a second pass keeps every candidate of earlier steps and sets that step's few
// aside, and a short insertion sort picks the nearest of those. About 3x fewer
// instructions than the quickselect, which now serves only cuts of a full buffer.
void selectNearestBucketed(PhotonHit* a, PhotonHit* tmp, size_t n, size_t k, float bound) {
    constexpr uint32_t kBuckets = 64;
    uint32_t count[kBuckets] = {};
    const float scale = static_cast<float>(kBuckets) / bound;
    if (!(scale > 0 && scale < HUGE_VALF)) {  // unbounded or degenerate radius
        selectNearest(a, tmp, n, k);
        std::swap(a[0], a[k - 1]);
        return;
    }
    for (size_t i = 0; i < n; ++i)
        ++count[std::min<uint32_t>(static_cast<uint32_t>(a[i].dist2 * scale), kBuckets - 1)];
    uint32_t j = 0;
    size_t before = 0;  // candidates in steps < j
    while (before + count[j] < k) before += count[j++];
    // Steps < j to tmp[0, before), step j compacted in place to a[0, m) (written at or
    // below the element being read). Branch-free: both targets are always written.
    size_t front = 0, m = 0;
    for (size_t i = 0; i < n; ++i) {
        const PhotonHit t = a[i];
        const uint32_t b = std::min<uint32_t>(static_cast<uint32_t>(t.dist2 * scale), kBuckets - 1);
        tmp[front] = t;
        a[m] = t;
        front += b < j;
        m += b == j;
    }
    const size_t need = k - before;  // 1 <= need <= m
    PhotonHit* step = tmp + before;  // room for n - before >= m
    if (m > 32)  // a crowded step (photons stacked at one distance, or a tight cluster)
        selectNearest(a, step, m, need);
    else
        insertionSort(a, 0, m);
    // a[0, need) are the step's nearest, a[need - 1] the k-th nearest overall.
    std::copy(a, a + need, step);
    a[0] = step[need - 1];
    std::copy(tmp, tmp + before, a + 1);
    std::copy(step, step + need - 1, a + 1 + before);
}

// A guessed radius holds about this many times k photons on a uniformly lit surface
// (squared radius x 1.6): enough margin for the leaf-box density estimate's error, while
// the selection stays short. Queries near a surface's edge see about half the density
// and need a second, larger pass (findNearestSlots).
constexpr float kGuessMargin = 1.6f;
constexpr float kGuessGrowth = 4.0f;  // squared radius per further pass
}  // namespace

size_t InCoreStore::memoryBytes() const {
    return nodes_.capacity() * sizeof(Node) + leaves_.capacity() + flux_.capacity() * sizeof(Colr) +
           flags_.capacity() + primary_.capacity() * sizeof(uint32_t) + norm_.capacity() * 3;
}

// Why the pruning is exact: `off` holds, per axis, |fl(q - bound)| for the nearest bound of
// the cell (0 inside its slab). Float subtraction, squaring and addition are monotonic, so
// the cell distance off0^2 + off1^2 + off2^2 evaluated in the same order as a photon's
// dist2 is never larger than that of any photon in the cell: skipping cells with
// distance >= maxDist2 never skips a photon the old search would accept.
//
// The walk collects every photon within the radius s.maxDist2 into s.buf (see
// findNearestSlots), depth-first, nearer child first, as a loop with an explicit stack of
// far children so that the query, the radius and the count stay in registers. A far
// child is pushed only if its cell is within the radius, and tested again when popped
// (the radius shrinks when a full buffer is cut down to the k nearest).
template <bool kFilter>
void InCoreStore::searchNode(uint32_t root, float rootOff[3], Search& s) const {
    // The cell offsets live in one vector register (lane 3 zero): written to and read
    // back from a stack array with a per-node axis index, each descent step waited on
    // store-to-load forwarding (the largest single stall of the walk in perf).
    struct Pending {
        V4 off;
        uint32_t node;
        float rd;  // cell distance (squared) of the far child
    };
    // Depth <= 96 (incore_store_build.cpp: 63 bit splits plus 32 count splits).
    Pending stack[100];
    int top = 0;
    const float q0 = s.q[0], q1 = s.q[1], q2 = s.q[2];
    const V4 qx = splat(q0), qy = splat(q1), qz = splat(q2);
    const V8 qx8 = splat8(q0), qy8 = splat8(q1), qz8 = splat8(q2);
    [[maybe_unused]] const V4 n0 = splat(s.n[0]), n1 = splat(s.n[1]), n2 = splat(s.n[2]);
    [[maybe_unused]] const V4 tol = splat(kNormalTolerance);
    const float q[3] = {q0, q1, q2};
    PhotonHit* const buf = s.buf;
    const size_t k = s.k, cap = s.cap;
    size_t found = s.found;
    float maxDist2 = s.maxDist2;
    const Node* const nodes = nodes_.data();
    const unsigned char* const leaves = leaves_.data();
    const Colr* const flux = flux_.data();
    V4 off = {rootOff[0], rootOff[1], rootOff[2], 0.f};
    uint32_t id = root;

    // Leaf test. GCC/Clang vector extensions, 4 lanes: -O2's cheap vectoriser leaves these
    // loops scalar. Each lane computes exactly the scalar expression (no reassociation, no
    // FMA), in the same order as kdtree.cpp, so distances are bit-identical. The lanes that
    // pass both tests against the radius form a bit mask, and those photons are appended
    // in slot order (no unpredictable branch per photon).
    auto testLeaf = [&](const Node* node) {
        const uint32_t b = node->link, count = node->axisInfo >> 2;
        uint32_t c4 = paddedCount(count);
        const unsigned char* block = leaves + kLeafBytesPerSlot * size_t{b};
        const float* px = reinterpret_cast<const float*>(block);
        [[maybe_unused]] const int8_t* pn =
            reinterpret_cast<const int8_t*>(block + 3 * c4 * sizeof(float));
        alignas(16) float d2[kLeafSize];
        const V4 limit = splat(maxDist2);
        const V8 limit8 = splat8(maxDist2);
        uint64_t mask = 0;
        // A leaf whose photons share one normal (most leaves: photons on flat surfaces)
        // takes the filter once, with the same float expression as the lanes below.
        bool testNormals = kFilter;
        if constexpr (kFilter) {
            int8_t common[3];
            if (leafCommonNormal(*node, common)) {
                const float dot = s.n[0] * float(common[0]) + s.n[1] * float(common[1]) +
                                  s.n[2] * float(common[2]);
                if (!(dot > kNormalTolerance)) c4 = 0;  // no photon passes
                testNormals = false;
            }
        }
        if (testNormals) {
            for (uint32_t i = 0; i < c4; i += 4) {
                const V4 dx = qx - load4(px + i), dy = qy - load4(px + c4 + i),
                         dz = qz - load4(px + 2 * c4 + i);
                const V4 r = dx * dx + dy * dy + dz * dz;
                std::memcpy(d2 + i, &r, sizeof r);
                const V4 dot =
                    n0 * load4(pn + i) + n1 * load4(pn + c4 + i) + n2 * load4(pn + 2 * c4 + i);
                const V4i m = (r < limit) & (dot > tol);
                mask |= uint64_t{laneMask(m)} << i;
            }
        } else {
            // Most leaves take this loop (their photons share a normal); eight at a time,
            // each lane the same expression as four at a time.
            uint32_t i = 0;
            for (; i + 8 <= c4; i += 8) {
                const V8 dx = qx8 - load8(px + i), dy = qy8 - load8(px + c4 + i),
                         dz = qz8 - load8(px + 2 * c4 + i);
                const V8 r = dx * dx + dy * dy + dz * dz;
                std::memcpy(d2 + i, &r, sizeof r);
                mask |= uint64_t{laneMask8(r < limit8)} << i;
            }
            if (i < c4) {
                const V4 dx = qx - load4(px + i), dy = qy - load4(px + c4 + i),
                         dz = qz - load4(px + 2 * c4 + i);
                const V4 r = dx * dx + dy * dy + dz * dz;
                std::memcpy(d2 + i, &r, sizeof r);
                mask |= uint64_t{laneMask(r < limit)} << i;
            }
        }
        static_assert(kLeafSize <= 64, "the lane mask is one 64-bit word");
        if (count < 64) mask &= (uint64_t{1} << count) - 1;
        if (s.causticFlags)
            for (uint64_t m = mask; m; m &= m - 1) {
                const uint32_t i = static_cast<uint32_t>(__builtin_ctzll(m));
                if ((s.causticFlags[b + i] & Photon::kCausticBit) != s.causticWanted)
                    mask &= ~(uint64_t{1} << i);
            }
        if (s.slab > 0)
            for (uint64_t m = mask; m; m &= m - 1) {
                const uint32_t i = static_cast<uint32_t>(__builtin_ctzll(m));
                const float h = (px[i] - q0) * s.n[0] + (px[c4 + i] - q1) * s.n[1] +
                                (px[2 * c4 + i] - q2) * s.n[2];
                if (!(std::fabs(h) < s.slab)) mask &= ~(uint64_t{1} << i);
            }
        if (mask) {
            // Density estimates read the flux of the photons found (flux_, by slot) right
            // after the search: fetch this leaf's now, overlapped with the rest of the
            // walk (those loads were half of surfaceDensity's time as cache misses).
            __builtin_prefetch(flux + b);
            for (uint32_t o = 16; o < kLeafSize; o += 16) __builtin_prefetch(flux + b + o);
        }
        while (mask) {
            const uint32_t i = static_cast<uint32_t>(__builtin_ctzll(mask));
            mask &= mask - 1;
            buf[found++] = {d2[i], b + i};
        }
        if (found + kLeafSize > cap) {
            // Full (the radius was generous): keep the k nearest and shrink the radius to
            // the k-th, as a heap would have. Exact: every photon dropped, and every one
            // pruned from now on, is at least as far as k photons kept.
            selectNearest(buf, buf + cap, found, k);
            found = k;
            maxDist2 = buf[k - 1].dist2;
        }
    };

    // The walk runs ahead of the leaf tests: it collects up to kBatch leaves whose cells
    // are within the radius, their memory is requested all at once, and only then are
    // they tested. Why: a leaf's photons are one cache miss chain (about 6 lines), and
    // tested as soon as reached the misses of a lookup's ~10 leaves came one after the
    // other, and the first load of a leaf dominated the search (bench/README_profile.md).
    // The radius shrinks only when a full buffer is cut, so a leaf collected before a cut
    // is tested against its cell distance again.
    struct LeafRef {
        uint32_t node;
        float rd;  // squared distance to the leaf's cell
    };
    constexpr int kBatch = 16;
    LeafRef batch[kBatch];
    for (bool more = true; more;) {
        int nb = 0;
        while (nb < kBatch) {
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
                // The far cell's offsets: off with lane `axis` raised to the cut
                // (std::max(off[axis], cut)).
                const V4 c = splat(cut);
                const V4 farOff = ((off < c) & kAxisLane[axis]) ? c : off;
                const V4 sq = farOff * farOff;
                // Unscaled on purpose: any factor > 1 here (an earlier version had 4)
                // prunes cells that lie inside the search radius and loses near photons
                // once k spans several leaves.
                const float rd = sq[0] + sq[1] + sq[2];
                Pending& far = stack[top];
                far.off = farOff;
                far.node = farId;
                far.rd = rd;
                top += rd < maxDist2;  // the radius only shrinks: a cell outside stays out
                id = nearId;
                node = nodes + id;
            }
            const V4 sq = off * off;
            if (s.guessK) {
                // Far children passed on the way down were kept if within the limit;
                // those beyond the guessed radius are dropped when popped.
                const float guess = node->rightMin * static_cast<float>(s.guessK) *
                                    (kGuessMargin / static_cast<float>(kPi));
                if (guess > 0 && guess < maxDist2) maxDist2 = guess;
                s.bound = maxDist2;
                s.guessK = 0;
            }
            batch[nb++] = {id, sq[0] + sq[1] + sq[2]};
            // Next: the most recently deferred far child whose cell is still within the
            // radius.
            more = false;
            while (top > 0) {
                const Pending& far = stack[--top];
                if (far.rd < maxDist2) {
                    id = far.node;
                    off = far.off;
                    more = true;
                    break;
                }
            }
            if (!more) break;
        }
        for (int i = 0; i < nb; ++i) {
            const Node& leaf = nodes[batch[i].node];
            const uint32_t c4 = paddedCount(leaf.axisInfo >> 2);
            const unsigned char* block = leaves + kLeafBytesPerSlot * size_t{leaf.link};
            size_t bytes = 3 * sizeof(float) * c4;
            if constexpr (kFilter) {
                int8_t common[3];
                if (!leafCommonNormal(leaf, common)) bytes += 3 * c4;
            }
            for (size_t o = 0; o < bytes; o += 64) __builtin_prefetch(block + o);
            __builtin_prefetch(block + bytes - 1);
        }
        for (int i = 0; i < nb; ++i)
            if (batch[i].rd < maxDist2) testLeaf(nodes + batch[i].node);
    }
    s.found = found;
    s.maxDist2 = maxDist2;
}

size_t InCoreStore::findNearestSlots(const PhotonQuery& query,
                                     std::vector<PhotonHit>& scratch) const {
    const size_t k = query.k;
    const float maxDist2 = query.maxDist2;
    const Vec3& pos = query.pos;
    const Vec3* normal = query.normal;
    if (k == 0 || nodes_.empty()) return 0;
    const size_t cap = 4 * k + 2 * kLeafSize;
    if (scratch.size() < 2 * cap) scratch.resize(2 * cap);  // candidates, then selection room
    // RADIANCE compat: the query point and normal are compared in single precision.
    Search s{{static_cast<float>(pos.x), static_cast<float>(pos.y), static_cast<float>(pos.z)},
             {0, 0, 0},
             scratch.data(),
             cap,
             k,
             0,
             maxDist2};
    if (query.causticOnly) {
        if (flags_.empty()) return 0;  // flags are kept for contribution maps only
        s.causticFlags = flags_.data();
    } else if (query.causticExcluded && !flags_.empty()) {
        s.causticFlags = flags_.data();
        s.causticWanted = 0;
    }
    float rootOff[3];
    for (int a = 0; a < 3; ++a) {
        const float q = s.q[a];
        rootOff[a] =
            q < boundsLo_[a] ? boundsLo_[a] - q : (q > boundsHi_[a] ? q - boundsHi_[a] : 0);
    }
    if (!(rootOff[0] * rootOff[0] + rootOff[1] * rootOff[1] + rootOff[2] * rootOff[2] < maxDist2))
        return 0;
    if (normal) {
        s.n[0] = static_cast<float>(normal->x);
        s.n[1] = static_cast<float>(normal->y);
        s.n[2] = static_cast<float>(normal->z);
        s.slab = query.slab;
    }
    // Collect every photon within a guessed radius, larger passes until k are found or the
    // radius reaches maxDist2; then select the k nearest. The k nearest within maxDist2
    // are exactly the k nearest of a pass that found at least k (all photons nearer than
    // its radius were collected), so the guess changes the cost, never the result.
    // The first pass guesses its radius from the density of the leaf the query falls in
    // (its photons per unit area, stored at build time), on its way down to that leaf:
    // a separate descent for the guess would walk the tree twice.
    s.guessK = k;
    float bound = maxDist2;
    for (;;) {
        s.found = 0;
        s.maxDist2 = bound;
        s.bound = bound;  // unless guessed
        float off[3] = {rootOff[0], rootOff[1], rootOff[2]};
        if (normal)
            searchNode<true>(0, off, s);
        else
            searchNode<false>(0, off, s);
        bound = s.bound;
        if (s.found >= k || !(bound < maxDist2)) break;
        bound = std::min(maxDist2, bound * kGuessGrowth);
    }
    size_t n = s.found;
    if (n >= k) {
        selectNearestBucketed(s.buf, s.buf + cap, n, k, bound);
        n = k;
    } else if (n > 1) {
        std::swap(s.buf[0], *std::max_element(s.buf, s.buf + n, Nearer{}));
    }
    return n;
}

namespace {
struct InCoreCursor final : PhotonStore::Cursor {
    std::vector<PhotonHit> scratch;
};
}  // namespace

std::unique_ptr<PhotonStore::Cursor> InCoreStore::makeCursor() const {
    return std::make_unique<InCoreCursor>();
}

size_t InCoreStore::findNearest(Cursor& cursor, const PhotonQuery& q,
                                std::vector<FoundPhoton>& out) const {
    std::vector<PhotonHit>& hits = static_cast<InCoreCursor&>(cursor).scratch;
    const size_t n = findNearestSlots(q, hits);
    if (out.size() < n) out.resize(n);
    // Field by field: a record assembled on the stack and copied whole stalled on the
    // store forwarding of its 16 bytes.
    for (size_t i = 0; i < n; ++i) {
        const uint32_t slot = hits[i].index;
        FoundPhoton& f = out[i];
        f.dist2 = hits[i].dist2;
        f.flux = flux_[slot];
        f.flags = attrs_.contrib ? flags_[slot] : uint8_t{0};
        f.primary = attrs_.contrib ? primary_[slot] : 0;
        if (attrs_.normals)
            std::memcpy(f.norm, norm_[slot].data(), 3);
        else
            f.norm[0] = f.norm[1] = f.norm[2] = 0;
    }
    return n;
}

}  // namespace rp::pmap
