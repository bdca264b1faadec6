// Subdivision and exact clipping of flat polygon sources (see source_polygon.h).
#include "render/source_polygon.h"

#include <array>
#include <cmath>
#include <span>

namespace rp::render {

namespace {

using Cell = PolygonCell;
using Piece = PolygonPiece;

// RADIANCE compat (srcsamp.c flt_partit): halve the cell across its longer side while
// it is larger than (ds / weight) times its distance, at most MAXSPART leaves.
void partition(const PlanarRegion& r, const Vec3& from, const Cell& c, int maxParts, double scale,
               PolygonScratch& leaves) {
    Vec3 centre = r.at(0.5 * (c.u0 + c.u1), 0.5 * (c.v0 + c.v1));
    double d2 = lengthSquared(from - centre);
    double du2 = (c.u1 - c.u0) * scale, dv2 = (c.v1 - c.v0) * scale;
    du2 *= du2;
    dv2 *= dv2;
    if (maxParts < 2 || (d2 >= du2 && d2 >= dv2)) {
        leaves.cells[size_t(leaves.cellCount++)] = c;  // maxParts halves: 64 leaves at most
        return;
    }
    Cell lo = c, hi = c;
    if (du2 > dv2) {
        lo.u1 = hi.u0 = 0.5 * (c.u0 + c.u1);
    } else {
        lo.v1 = hi.v0 = 0.5 * (c.v0 + c.v1);
    }
    partition(r, from, lo, maxParts / 2, scale, leaves);
    partition(r, from, hi, maxParts / 2, scale, leaves);
}

// Clips the polygon in `p` against axis `axis` (0: u, 1: v) keeping sign*(x - bound) >= 0.
void clipAgainst(Piece& p, int axis, double bound, double sign) {
    Piece out;
    for (int i = 0; i < p.n; ++i) {
        int j = (i + 1) % p.n;
        double a = sign * (p.uv[size_t(2 * i + axis)] - bound);
        double b = sign * (p.uv[size_t(2 * j + axis)] - bound);
        if (a >= 0) {
            out.uv[size_t(2 * out.n)] = p.uv[size_t(2 * i)];
            out.uv[size_t(2 * out.n + 1)] = p.uv[size_t(2 * i + 1)];
            ++out.n;
        }
        if ((a >= 0) != (b >= 0)) {
            double t = a / (a - b);
            for (int k = 0; k < 2; ++k)
                out.uv[size_t(2 * out.n + k)] =
                    p.uv[size_t(2 * i + k)] +
                    t * (p.uv[size_t(2 * j + k)] - p.uv[size_t(2 * i + k)]);
            ++out.n;
        }
    }
    p.uv = out.uv;
    p.n = out.n;
}

// Area and centroid of a convex piece (fan from its first corner).
void measure(Piece& p) {
    p.area = p.cu = p.cv = 0;
    for (int k = 1; k + 1 < p.n; ++k) {
        double ax = p.uv[0], ay = p.uv[1];
        double bx = p.uv[size_t(2 * k)], by = p.uv[size_t(2 * k + 1)];
        double cx = p.uv[size_t(2 * k + 2)], cy = p.uv[size_t(2 * k + 3)];
        double a = 0.5 * ((bx - ax) * (cy - ay) - (cx - ax) * (by - ay));
        p.area += a;
        p.cu += a * (ax + bx + cx) / 3;
        p.cv += a * (ay + by + cy) / 3;
    }
    if (p.area > 0) {
        p.cu /= p.area;
        p.cv /= p.area;
    }
}

bool insidePiece(const Piece& p, double u, double v) {
    for (int i = 0; i < p.n; ++i) {
        int j = (i + 1) % p.n;
        double ex = p.uv[size_t(2 * j)] - p.uv[size_t(2 * i)];
        double ey = p.uv[size_t(2 * j + 1)] - p.uv[size_t(2 * i + 1)];
        if (ex * (v - p.uv[size_t(2 * i + 1)]) - ey * (u - p.uv[size_t(2 * i)]) < 0) return false;
    }
    return true;
}

// A uniform point of a convex piece.
void uniformInPiece(const Piece& p, Rng& rng, double& u, double& v) {
    double pick = rng.uniform() * p.area;
    int k = 1;
    double a = 0;
    for (; k + 1 < p.n; ++k) {
        double ax = p.uv[0], ay = p.uv[1];
        double bx = p.uv[size_t(2 * k)], by = p.uv[size_t(2 * k + 1)];
        double cx = p.uv[size_t(2 * k + 2)], cy = p.uv[size_t(2 * k + 3)];
        a = 0.5 * ((bx - ax) * (cy - ay) - (cx - ax) * (by - ay));
        if (pick < a || k + 2 >= p.n) break;
        pick -= a;
    }
    double s = rng.uniform(), t = rng.uniform();
    if (s + t > 1) {
        s = 1 - s;
        t = 1 - t;
    }
    u = p.uv[0] + s * (p.uv[size_t(2 * k)] - p.uv[0]) + t * (p.uv[size_t(2 * k + 2)] - p.uv[0]);
    v = p.uv[1] + s * (p.uv[size_t(2 * k + 1)] - p.uv[1]) + t * (p.uv[size_t(2 * k + 3)] - p.uv[1]);
}

// One sample toward `target` standing for `area` of the source (normal `nrm`, facing
// `from`), none if degenerate or seen edge-on.
// RADIANCE compat (srcsamp.c nextssamp, sflatform): the cell's solid angle is its area
// times the cosine at the source over the squared distance, all taken at the sample
// point, not the exact solid angle of the cell. The two agree once cells are small
// (-ds subdivides them below ds times their distance); for a whole near source at -ds 0
// RADIANCE's estimate is what its users' renderings show (e.g. 17.0 where the exact
// value is 13.7 at 0.74 m below a 1.16 x 0.55 m luminaire, test DirectPolygon).
void addSample(std::vector<SourceSample>& out, const Vec3& from, const Vec3& target,
               const Vec3& nrm, double area) {
    SourceSample s;
    s.target = target;
    const Vec3 d = target - from;
    s.dist = length(d);
    if (!(s.dist > 0) || !(area > 0)) return;
    s.dir = d / s.dist;
    const double cosSrc = -dot(s.dir, nrm);
    if (!(cosSrc > 0)) return;
    s.omega = area * cosSrc / (s.dist * s.dist);
    out.push_back(s);
}

}  // namespace

void samplePolygon(const PlanarRegion& r, const Vec3& from, double ds, double weight, double jitter,
                   Rng& rng, PolygonScratch& scratch, std::vector<SourceSample>& out) {
    std::vector<Piece>& pieces = scratch.pieces;
    if (ds <= 0) {
        // RADIANCE compat (srcsamp.c nopart): without subdivision the whole source is one
        // sample at its centre (a 3 x 1 m window 1 m away: 3 sr instead of the true 1.5).
        addSample(out, from, r.centre, r.normal, r.area);
        return;
    }
    scratch.cellCount = 0;
    const Cell whole{r.u0, r.u1, r.v0, r.v1};
    partition(r, from, whole, kMaxSourceParts, std::fmax(weight, 1e-6) / ds, scratch);
    const std::span<const Cell> cells(scratch.cells.data(), size_t(scratch.cellCount));

    // Fast path: a polygon that fills its bounding rectangle (the usual rectangular
    // luminaire or window) needs no clipping; each cell is a rectangle of the source.
    const double boxArea = (r.u1 - r.u0) * (r.v1 - r.v0);
    if (std::fabs(r.area - boxArea) <= 1e-9 * boxArea) {
        for (const Cell& c : cells) {
            double su = 0.5 * (c.u0 + c.u1), sv = 0.5 * (c.v0 + c.v1);
            if (jitter > 0) {
                su += jitter * (rng.uniform() - 0.5) * (c.u1 - c.u0);
                sv += jitter * (rng.uniform() - 0.5) * (c.v1 - c.v0);
            }
            addSample(out, from, r.at(su, sv), r.normal, (c.u1 - c.u0) * (c.v1 - c.v0));
        }
        return;
    }

    for (const Cell& c : cells) {
        pieces.clear();
        double total = 0, cu = 0, cv = 0;
        for (const auto& t : r.tris) {
            double tu0 = std::fmin(t[0], std::fmin(t[2], t[4]));
            double tu1 = std::fmax(t[0], std::fmax(t[2], t[4]));
            double tv0 = std::fmin(t[1], std::fmin(t[3], t[5]));
            double tv1 = std::fmax(t[1], std::fmax(t[3], t[5]));
            if (tu1 <= c.u0 || tu0 >= c.u1 || tv1 <= c.v0 || tv0 >= c.v1) continue;
            Piece p;
            for (size_t k = 0; k < 6; ++k) p.uv[k] = t[k];
            p.n = 3;
            clipAgainst(p, 0, c.u0, 1);
            if (p.n >= 3) clipAgainst(p, 0, c.u1, -1);
            if (p.n >= 3) clipAgainst(p, 1, c.v0, 1);
            if (p.n >= 3) clipAgainst(p, 1, c.v1, -1);
            if (p.n < 3) continue;
            measure(p);
            if (!(p.area > 0)) continue;
            total += p.area;
            cu += p.area * p.cu;
            cv += p.area * p.cv;
            pieces.push_back(p);
        }
        if (pieces.empty() || total <= 1e-12 * r.area) continue;
        cu /= total;
        cv /= total;
        auto inside = [&](double u, double v) {
            for (const Piece& p : pieces)
                if (insidePiece(p, u, v)) return true;
            return false;
        };
        if (!inside(cu, cv)) {  // a non-convex covered part: use its largest piece
            const Piece* big = &pieces[0];
            for (const Piece& p : pieces)
                if (p.area > big->area) big = &p;
            cu = big->cu;
            cv = big->cv;
        }
        double su = cu, sv = cv;
        if (jitter > 0) {
            double pick = rng.uniform() * total;
            const Piece* chosen = &pieces.back();
            for (const Piece& p : pieces) {
                if (pick < p.area) {
                    chosen = &p;
                    break;
                }
                pick -= p.area;
            }
            double qu, qv;
            uniformInPiece(*chosen, rng, qu, qv);
            su = cu + jitter * (qu - cu);
            sv = cv + jitter * (qv - cv);
            if (!inside(su, sv)) {
                su = qu;
                sv = qv;
            }
        }
        addSample(out, from, r.at(su, sv), r.normal, total);
    }
}

}  // namespace rp::render
