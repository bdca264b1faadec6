// Polygon triangulation by even-odd trapezoidal decomposition (see triangulate.h).
//
// Why this method: RADIANCE decides what a polygon covers by counting edge crossings
// (face.c inface, even-odd), so seams, holes, overlapping edges and self-intersections
// all follow from that one rule. Cutting the projected plane into horizontal slabs at
// every vertex height (and at every edge crossing) leaves, in each slab, edges that do
// not cross; sorted by x, consecutive pairs (1st-2nd, 3rd-4th, ...) bound exactly the
// odd-count region. No case analysis of seams or ears is needed, so nothing depends on
// how the outline was drawn. Ear clipping, which this replaced, must decide which of
// two coincident seam vertices an ear may use, and got that wrong on real walls.
// Library triangulators (CGAL's constrained Delaunay, earcut) either do not follow the
// even-odd rule for seams or are not in Debian at a usable version; the decomposition
// is short and its correctness argument fits in this comment.
//
// Trapezoids of consecutive slabs with the same two edges are merged, and every
// trapezoid takes as extra corners the points that its neighbours above and below put
// on its top and bottom, so the triangles share edges exactly (no cracks for rays).
#include "geometry/triangulate.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace rp {

namespace {

struct P2 {
    double x, y;
};

double cross2(const P2& o, const P2& a, const P2& b) {  // (a-o) x (b-o)
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Projects the loop onto the plane of the two axes other than the normal's dominant
// one (RADIANCE's choice in face.c), relative to the first vertex (so 1 km offsets cost
// no precision), mirrored if needed so that the front side is counter-clockwise.
std::vector<P2> project(std::span<const Vec3> verts, const Vec3& normal) {
    int k = 2;
    if (std::fabs(normal.x) >= std::fabs(normal.y) && std::fabs(normal.x) >= std::fabs(normal.z))
        k = 0;
    else if (std::fabs(normal.y) >= std::fabs(normal.z))
        k = 1;
    int i = (k + 1) % 3, j = (k + 2) % 3;
    bool mirror = normal[k] < 0;
    std::vector<P2> pts(verts.size());
    for (size_t n = 0; n < verts.size(); ++n) {
        Vec3 r = verts[n] - verts[0];
        pts[n] = mirror ? P2{r[j], r[i]} : P2{r[i], r[j]};
    }
    return pts;
}

// Convex (weakly, allowing collinear runs) and winding once: every turn is a left turn
// and each coordinate changes direction at most twice around the loop.
bool isConvex(const std::vector<P2>& p) {
    size_t n = p.size();
    int xFlips = 0, yFlips = 0;
    double prevDx = 0, prevDy = 0;
    for (size_t s = 0; s < n + 1; ++s) {  // one extra step closes the flip count
        const P2& a = p[s % n];
        const P2& b = p[(s + 1) % n];
        const P2& c = p[(s + 2) % n];
        if (s < n && cross2(a, b, c) < 0) return false;
        double dx = b.x - a.x, dy = b.y - a.y;
        if (dx != 0) {
            if (prevDx != 0 && (dx > 0) != (prevDx > 0)) ++xFlips;
            prevDx = dx;
        }
        if (dy != 0) {
            if (prevDy != 0 && (dy > 0) != (prevDy > 0)) ++yFlips;
            prevDy = dy;
        }
    }
    return xFlips <= 2 && yFlips <= 2;
}

// A non-horizontal edge, stored from its lower to its upper end. Positions along it
// are computed from that canonical order, so the two sides of a seam (one edge walked
// both ways) give bit-identical points.
struct Edge {
    P2 lo, hi;
    uint32_t vlo, vhi;  // loop indices of the ends
};

double xAt(const Edge& e, double y) {
    if (y <= e.lo.y) return e.lo.x;
    if (y >= e.hi.y) return e.hi.x;
    return e.lo.x + (e.hi.x - e.lo.x) * ((y - e.lo.y) / (e.hi.y - e.lo.y));
}

// A trapezoid between edges `left` and `right`, from line `bot` up to line `top`.
struct Trapezoid {
    uint32_t left, right;
    uint32_t bot, top;
};

struct LinePoint {
    double x;
    Vec3 p;
    uint32_t vertex;
};

class SlabDecomposition {
public:
    SlabDecomposition(std::span<const Vec3> verts, const std::vector<P2>& pts) : verts_(verts) {
        size_t n = pts.size();
        for (size_t i = 0; i < n; ++i) {
            size_t j = (i + 1) % n;
            if (pts[i].y == pts[j].y) continue;  // horizontal: crosses no slab
            bool up = pts[i].y < pts[j].y;
            edges_.push_back(up ? Edge{pts[i], pts[j], uint32_t(i), uint32_t(j)}
                                : Edge{pts[j], pts[i], uint32_t(j), uint32_t(i)});
        }
        maxSplits_ = 64 * n + 1024;
        double size = 0;
        for (const P2& p : pts) size = std::fmax(size, std::fmax(std::fabs(p.x), std::fabs(p.y)));
        minArea2_ = 1e-14 * size * size;
    }

    Triangulation run() {
        sweep();
        return triangles();
    }

private:
    Vec3 pointAt(const Edge& e, double y) const {
        if (y <= e.lo.y) return verts_[e.vlo];
        if (y >= e.hi.y) return verts_[e.vhi];
        double t = (y - e.lo.y) / (e.hi.y - e.lo.y);
        return verts_[e.vlo] + (verts_[e.vhi] - verts_[e.vlo]) * t;
    }

    // Slabs between consecutive distinct vertex heights, bottom to top, with the edges
    // that span each.
    void sweep() {
        std::vector<double> ys;
        for (const Edge& e : edges_) {
            ys.push_back(e.lo.y);
            ys.push_back(e.hi.y);
        }
        std::sort(ys.begin(), ys.end());
        ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
        std::vector<uint32_t> order(edges_.size());
        for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](uint32_t a, uint32_t b) { return edges_[a].lo.y < edges_[b].lo.y; });
        if (ys.empty()) return;
        lineY_.push_back(ys[0]);
        std::vector<uint32_t> active;
        size_t next = 0;
        for (size_t k = 0; k + 1 < ys.size(); ++k) {
            double y0 = ys[k], y1 = ys[k + 1];
            std::erase_if(active, [&](uint32_t e) { return edges_[e].hi.y <= y0; });
            while (next < order.size() && edges_[order[next]].lo.y <= y0)
                active.push_back(order[next++]);
            slab(active, y0, y1);
        }
    }

    // One slab: split it where two of its edges cross, else pair its edges by x.
    void slab(const std::vector<uint32_t>& active, double y0, double y1) {
        struct At {
            double xb, xm, xt;  // x at the bottom, the middle and the top
            uint32_t e;
        };
        const double ym = 0.5 * (y0 + y1);
        std::vector<At> at;
        at.reserve(active.size());
        for (uint32_t e : active)
            at.push_back({xAt(edges_[e], y0), xAt(edges_[e], ym), xAt(edges_[e], y1), e});
        // Sorted at mid-height, where rounding at the ends (a cut made at a crossing puts
        // both edges at "the same" x) cannot swap them.
        std::sort(at.begin(), at.end(), [](const At& a, const At& b) {
            return a.xm < b.xm || (a.xm == b.xm && a.xt < b.xt);
        });
        // Neighbours out of order at the bottom or the top cross in that half; any
        // crossing shows as such a neighbouring pair.
        std::vector<double> cuts;
        for (size_t i = 0; i + 1 < at.size() && splits_ < maxSplits_; ++i) {
            const At &a = at[i], &b = at[i + 1];
            if (!(a.xb > b.xb) && !(a.xt > b.xt)) continue;
            double s = (b.xb - a.xb) / ((a.xt - a.xb) - (b.xt - b.xb));
            // Crossings within rounding of the slab's ends are left alone: their sliver
            // is far below any ray's resolution, and cutting there would only recurse
            // on rounding noise.
            if (!(s > 1e-9 && s < 1 - 1e-9)) continue;
            double y = y0 + (y1 - y0) * s;
            if (y > y0 && y < y1) cuts.push_back(y);
        }
        if (!cuts.empty()) {
            std::sort(cuts.begin(), cuts.end());
            cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
            splits_ += cuts.size();
            double lo = y0;
            for (double c : cuts) {
                slab(active, lo, c);
                lo = c;
            }
            slab(active, lo, y1);
            return;
        }
        pairEdges(at, y1);
    }

    // Consecutive pairs bound the inside. A trapezoid continues the one below when it
    // has the same two edges and neither side is shared with a neighbour (a seam), so
    // that points on a shared side always come from both trapezoids alike.
    template <class AtVec>
    void pairEdges(const AtVec& at, double y1) {
        uint32_t bot = uint32_t(lineY_.size() - 1);
        lineY_.push_back(y1);
        std::unordered_map<uint64_t, uint32_t> open;
        open.swap(open_);
        auto coincide = [&](size_t i, size_t j) {
            return at[i].xb == at[j].xb && at[i].xt == at[j].xt;
        };
        for (size_t i = 0; i + 1 < at.size(); i += 2) {
            if (at[i].xb >= at[i + 1].xb && at[i].xm >= at[i + 1].xm && at[i].xt >= at[i + 1].xt)
                continue;  // no area
            bool shared =
                (i > 0 && coincide(i - 1, i)) || (i + 2 < at.size() && coincide(i + 1, i + 2));
            uint32_t l = at[i].e, r = at[i + 1].e;
            uint64_t key = (uint64_t(l) << 32) | r;
            if (!shared) {
                auto it = open.find(key);
                if (it != open.end()) {
                    traps_[it->second].top = bot + 1;
                    open_.emplace(key, it->second);
                    continue;
                }
            }
            traps_.push_back({l, r, bot, bot + 1});
            if (!shared) open_.emplace(key, uint32_t(traps_.size() - 1));
        }
    }

    // Each trapezoid's corners go on its bottom and top lines; then each trapezoid is
    // cut into triangles between all the points on its bottom and top.
    Triangulation triangles() {
        std::vector<std::vector<LinePoint>> lines(lineY_.size());
        for (const Trapezoid& t : traps_)
            for (uint32_t line : {t.bot, t.top})
                for (uint32_t e : {t.left, t.right})
                    lines[line].push_back(
                        {xAt(edges_[e], lineY_[line]), pointAt(edges_[e], lineY_[line]), 0});
        Triangulation out;
        for (auto& line : lines) {
            std::stable_sort(line.begin(), line.end(),
                             [](const LinePoint& a, const LinePoint& b) { return a.x < b.x; });
            line.erase(
                std::unique(line.begin(), line.end(),
                            [](const LinePoint& a, const LinePoint& b) { return a.x == b.x; }),
                line.end());
            for (LinePoint& p : line) {
                p.vertex = uint32_t(out.vertices.size());
                out.vertices.push_back(p.p);
            }
        }
        for (const Trapezoid& t : traps_) {
            auto chain = [&](uint32_t line) {
                const std::vector<LinePoint>& pts = lines[line];
                // Corners at a crossing may come out a rounding apart in either order.
                double a = xAt(edges_[t.left], lineY_[line]),
                       b = xAt(edges_[t.right], lineY_[line]);
                if (a > b) std::swap(a, b);
                auto lo = std::lower_bound(pts.begin(), pts.end(), a,
                                           [](const LinePoint& p, double x) { return p.x < x; });
                auto hi = std::upper_bound(pts.begin(), pts.end(), b,
                                           [](double x, const LinePoint& p) { return x < p.x; });
                return std::span<const LinePoint>(lo, hi < lo ? lo : hi);
            };
            strip(chain(t.bot), lineY_[t.bot], chain(t.top), lineY_[t.top], out.triangles);
        }
        return out;
    }

    // Triangles between a bottom and a top chain (both left to right), advancing the
    // chain whose next point lies further left; triangles of zero area (to rounding,
    // relative to the polygon's size) are dropped.
    void strip(std::span<const LinePoint> b, double yb, std::span<const LinePoint> t, double yt,
               std::vector<TriIndices>& out) const {
        if (b.empty() || t.empty()) return;
        auto emit = [&](const LinePoint& p, double py, const LinePoint& q, double qy,
                        const LinePoint& r, double ry) {
            if (cross2({p.x, py}, {q.x, qy}, {r.x, ry}) > minArea2_)
                out.push_back({p.vertex, q.vertex, r.vertex});
        };
        size_t i = 0, j = 0;
        while (i + 1 < b.size() || j + 1 < t.size()) {
            bool bottom = j + 1 == t.size() || (i + 1 < b.size() && b[i + 1].x <= t[j + 1].x);
            if (bottom) {
                emit(b[i], yb, b[i + 1], yb, t[j], yt);
                ++i;
            } else {
                emit(b[i], yb, t[j + 1], yt, t[j], yt);
                ++j;
            }
        }
    }

    std::span<const Vec3> verts_;
    std::vector<Edge> edges_;
    std::vector<double> lineY_;  // heights of the slab boundaries so far, increasing
    std::vector<Trapezoid> traps_;
    std::unordered_map<uint64_t, uint32_t>
        open_;                           // (left, right) -> trapezoid reaching the last line
    size_t splits_ = 0, maxSplits_ = 0;  // bound on crossing splits for pathological input
    double minArea2_ = 0;                // twice the area below which a triangle is rounding noise
};

}  // namespace

Triangulation triangulatePolygon(std::span<const Vec3> verts, const Vec3& normal) {
    Triangulation out;
    size_t n = verts.size();
    if (n < 3) return out;
    std::vector<P2> pts = project(verts, normal);
    if (isConvex(pts)) {  // fan, skipping the zero-area triangles of collinear runs
        out.vertices.assign(verts.begin(), verts.end());
        for (uint32_t i = 1; i + 1 < n; ++i)
            if (cross2(pts[0], pts[i], pts[i + 1]) > 0) out.triangles.push_back({0, i, i + 1});
        return out;
    }
    return SlabDecomposition(verts, pts).run();
}

}  // namespace rp
