// Ear clipping in the polygon's dominant-axis projection (see triangulate.h).
//
// Why our own: the polygons come with RADIANCE's seam convention for holes (duplicate
// vertices joined by a doubly-walked edge), and we want the exact handling of those
// duplicates spelled out rather than inferred from a general library.
#include "geometry/triangulate.h"

#include <cmath>

namespace rp {

namespace {

struct P2 {
    double x, y;
};

double cross2(const P2& o, const P2& a, const P2& b) {  // (a-o) x (b-o)
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool samePoint(const P2& a, const P2& b) { return a.x == b.x && a.y == b.y; }

// Closed point-in-triangle for a CCW triangle abc.
bool inTriangleClosed(const P2& p, const P2& a, const P2& b, const P2& c) {
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Does direction x->q point strictly into the corner of the CCW triangle at x, whose
// other corners are y (next) and z (previous)?
bool pointsIntoCorner(const P2& x, const P2& y, const P2& z, const P2& q) {
    return cross2(x, y, q) > 0 && cross2(x, q, z) > 0;
}

// Projects the loop onto the plane of the two axes other than the normal's dominant
// one, relative to the first vertex (so 1 km offsets cost no precision), and mirrors
// it if needed so that the front side is counter-clockwise in 2D.
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

class EarClipper {
public:
    explicit EarClipper(std::vector<P2> pts) : p_(std::move(pts)), prev_(p_.size()), next_(p_.size()) {
        size_t n = p_.size();
        for (size_t i = 0; i < n; ++i) {
            prev_[i] = uint32_t((i + n - 1) % n);
            next_[i] = uint32_t((i + 1) % n);
        }
    }

    Triangulation run() {
        Triangulation out;
        uint32_t remaining = uint32_t(p_.size());
        uint32_t i = 0;
        uint32_t misses = 0;  // consecutive vertices that were not ears
        int strictness = 0;   // 0: proper ears; 1: interior-only test; 2: any convex vertex
        while (remaining > 3) {
            uint32_t a = prev_[i], c = next_[i];
            double turn = cross2(p_[a], p_[i], p_[c]);
            bool clip = false;
            if (turn == 0) {
                clip = true;  // collinear run or seam spike: drop the vertex, no area lost
            } else if (turn > 0 && isEar(a, i, c, strictness)) {
                out.triangles.push_back({a, i, c});
                clip = true;
            }
            if (clip) {
                next_[a] = c;
                prev_[c] = a;
                --remaining;
                i = a;  // the neighbours' ear status changed; look at them first
                misses = 0;
                strictness = 0;
            } else {
                i = c;
                if (++misses > remaining) {  // a full lap without an ear
                    misses = 0;
                    if (strictness < 2) {
                        ++strictness;
                    } else {
                        // No convex vertex at all: the loop is self-intersecting beyond
                        // repair. Drop a vertex so that we terminate.
                        next_[a] = c;
                        prev_[c] = a;
                        --remaining;
                    }
                    out.clean = false;
                }
            }
        }
        uint32_t a = prev_[i], c = next_[i];
        if (cross2(p_[a], p_[i], p_[c]) > 0) out.triangles.push_back({a, i, c});
        return out;
    }

private:
    // Is (a, b, c) an ear: no remaining vertex inside, and no duplicate of a corner
    // (seam vertex) whose edges run into the triangle?
    bool isEar(uint32_t a, uint32_t b, uint32_t c, int strictness) const {
        if (strictness >= 2) return true;
        const P2 &pa = p_[a], &pb = p_[b], &pc = p_[c];
        double minX = std::fmin(pa.x, std::fmin(pb.x, pc.x)), maxX = std::fmax(pa.x, std::fmax(pb.x, pc.x));
        double minY = std::fmin(pa.y, std::fmin(pb.y, pc.y)), maxY = std::fmax(pa.y, std::fmax(pb.y, pc.y));
        for (uint32_t q = next_[c]; q != a; q = next_[q]) {
            const P2& pq = p_[q];
            if (pq.x < minX || pq.x > maxX || pq.y < minY || pq.y > maxY) continue;
            // A duplicate of a corner sits on the triangle: it blocks the ear only if
            // the polygon leaves it into the triangle (the other side of a seam).
            const P2* corner[3] = {&pa, &pb, &pc};
            bool dup = false;
            for (int k = 0; k < 3 && !dup; ++k) {
                if (!samePoint(pq, *corner[k])) continue;
                dup = true;
                const P2& y = *corner[(k + 1) % 3];
                const P2& z = *corner[(k + 2) % 3];
                if (pointsIntoCorner(pq, y, z, p_[prev_[q]]) ||
                    pointsIntoCorner(pq, y, z, p_[next_[q]]))
                    return false;
            }
            if (dup) continue;
            // Only reflex (or flat) vertices can lie in an ear of a simple polygon.
            if (cross2(p_[prev_[q]], pq, p_[next_[q]]) > 0) continue;
            if (strictness == 0) {
                if (inTriangleClosed(pq, pa, pb, pc)) return false;
            } else if (cross2(pa, pb, pq) > 0 && cross2(pb, pc, pq) > 0 && cross2(pc, pa, pq) > 0) {
                return false;
            }
        }
        return true;
    }

    std::vector<P2> p_;
    std::vector<uint32_t> prev_, next_;
};

}  // namespace

Triangulation triangulatePolygon(std::span<const Vec3> verts, const Vec3& normal) {
    Triangulation out;
    size_t n = verts.size();
    if (n < 3) return out;
    std::vector<P2> pts = project(verts, normal);
    if (isConvex(pts)) {  // fan, skipping the zero-area triangles of collinear runs
        for (uint32_t i = 1; i + 1 < n; ++i)
            if (cross2(pts[0], pts[i], pts[i + 1]) > 0) out.triangles.push_back({0, i, i + 1});
        return out;
    }
    return EarClipper(std::move(pts)).run();
}

}  // namespace rp
