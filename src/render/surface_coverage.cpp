#include "render/surface_coverage.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "material/material.h"
#include "pmap/edge_estimate.h"
#include "scene/primitive.h"

namespace rp::render {

namespace {
constexpr int kRimProbes = 16;
constexpr int kDiscProbes = 64;
constexpr int kEdgeDirections = 64;
constexpr int kEdgeMisfits = 2;
constexpr int kEdgeSearch = 3;  // directions tried either side of the likeliest
constexpr int kEdgeBisections = 10;
// Surfaces passed on the way down (antimatter, glass) before a probe gives up.
constexpr int kMaxProbePasses = 8;

// Unit-disc positions of the probes (equal areas each: radius sqrt((i + 1/2) / n), turned
// by the golden angle) and the directions tried for an edge, computed once.
struct ProbeTables {
    double x[kDiscProbes], y[kDiscProbes];
    double c[kEdgeDirections], s[kEdgeDirections];
    double rimC[kRimProbes], rimS[kRimProbes];
    ProbeTables() {
        const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
        for (int i = 0; i < kDiscProbes; ++i) {
            const double rho = std::sqrt((i + 0.5) / kDiscProbes);
            x[i] = rho * std::cos(golden * i);
            y[i] = rho * std::sin(golden * i);
        }
        for (int j = 0; j < kEdgeDirections; ++j) {
            c[j] = std::cos(2 * std::numbers::pi * j / kEdgeDirections);
            s[j] = std::sin(2 * std::numbers::pi * j / kEdgeDirections);
        }
        for (int i = 0; i < kRimProbes; ++i) {
            rimC[i] = std::cos(2 * std::numbers::pi * i / kRimProbes);
            rimS[i] = std::sin(2 * std::numbers::pi * i / kRimProbes);
        }
    }
};
const ProbeTables& probeTables() {
    static const ProbeTables tables;
    return tables;
}
}  // namespace

SurfaceCoverage::SurfaceCoverage(const material::MaterialTable& materials,
                                 const SceneGeometry& geometry, const Hit& hit, const Vec3& normal)
    : materials_(materials), geometry_(geometry), hit_(hit), point_(hit.point), normal_(normal) {}

double SurfaceCoverage::polygonClearance() const {
    const Scene& scene = materials_.scene();
    if (hit_.objectSpace || hit_.prim < 0 || size_t(hit_.prim) >= scene.prims.size()) return 0;
    const Primitive& p = scene.prims[size_t(hit_.prim)];
    if (p.type != PrimType::Polygon || p.rargs.size() < 9 || p.rargs.size() % 3) return 0;
    const size_t n = p.rargs.size() / 3;
    auto vertex = [&](size_t i) {
        return Vec3{p.rargs[3 * i], p.rargs[3 * i + 1], p.rargs[3 * i + 2]};
    };
    double nearest = HUGE_VAL;
    for (size_t i = 0; i < n; ++i) {
        const Vec3 a = vertex(i), ab = vertex((i + 1) % n) - a;
        const double len2 = dot(ab, ab);
        const double t = len2 > 0 ? std::clamp(dot(point_ - a, ab) / len2, 0.0, 1.0) : 0.0;
        nearest = std::min(nearest, length(point_ - (a + ab * t)));
    }
    return nearest;
}

bool SurfaceCoverage::covered(const Vec3& at, double slab) const {
    Ray r{at + normal_ * slab, -normal_, 2 * slab};
    for (int pass = 0; pass < kMaxProbePasses; ++pass) {
        const std::optional<Hit> hit = geometry_.closestHit(r);
        if (!hit) return false;
        const int32_t m = chainMaterial(materials_.scene(), hit->modifier);
        const material::MaterialRecord* rec = m == kVoid ? nullptr : &materials_[m];
        if (rec && rec->params && material::storesPhotons(*rec->params)) return true;
        if (rec && !rec->antimatter && rec->plugsLeaks) return false;
        const double left = r.tmax - hit->t;
        if (!(left > 0)) return false;
        r = spawnRay(*hit, r.dir, left);
    }
    return false;
}

pmap::DiscCoverage::Part SurfaceCoverage::part(double radius2, double slab) const {
    const double radius = std::sqrt(radius2);
    if (polygonClearance() > radius) return {};
    if (!covered(point_, slab)) return {0, false};  // off every surface (rtrace -I in air)
    if (!framed_) {
        orthonormalFrame(normal_, e1_, e2_);
        framed_ = true;
    }
    const ProbeTables& t = probeTables();
    bool whole = true;
    for (int i = 0; i < kRimProbes && whole; ++i)
        whole = covered(point_ + (e1_ * t.rimC[i] + e2_ * t.rimS[i]) * radius, slab);
    if (whole) return {};
    bool in[kDiscProbes];
    int n = 0;
    for (int i = 0; i < kDiscProbes; ++i) {
        in[i] = covered(point_ + (e1_ * t.x[i] + e2_ * t.y[i]) * radius, slab);
        n += in[i] ? 1 : 0;
    }
    return straightEdge(in, double(n) / kDiscProbes, radius, slab);
}

pmap::DiscCoverage::Part SurfaceCoverage::straightEdge(const bool* in, double fraction,
                                                       double radius, double slab) const {
    const ProbeTables& t = probeTables();
    const double delta = pmap::edgeOffsetOfFraction(fraction);
    // A straight edge's normal points at the uncovered probes' centroid: the directions
    // next to that one are tried.
    double mx = 0, my = 0;
    for (int i = 0; i < kDiscProbes; ++i)
        if (!in[i]) {
            mx += t.x[i];
            my += t.y[i];
        }
    const int centre =
        int(std::lround(std::atan2(my, mx) / (2 * std::numbers::pi) * kEdgeDirections));
    int best = kDiscProbes, bestDirection = 0;
    for (int step = -kEdgeSearch; step <= kEdgeSearch; ++step) {
        const int j = ((centre + step) % kEdgeDirections + kEdgeDirections) % kEdgeDirections;
        int misfits = 0;
        for (int i = 0; i < kDiscProbes && misfits < best; ++i)
            misfits += (t.x[i] * t.c[j] + t.y[i] * t.s[j] < delta) != in[i];
        if (misfits < best) {
            best = misfits;
            bestDirection = j;
        }
    }
    if (best > kEdgeMisfits) return {fraction, false};
    // The query is on the surface; the rim beyond the edge must not be.
    const Vec3 out = (e1_ * t.c[bestDirection] + e2_ * t.s[bestDirection]) * radius;
    if (covered(point_ + out, slab)) return {fraction, false};
    double lo = 0, hi = 1;
    for (int i = 0; i < kEdgeBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        (covered(point_ + out * mid, slab) ? lo : hi) = mid;
    }
    return {pmap::edgeDiscFraction(0.5 * (lo + hi)), true};
}

}  // namespace rp::render
