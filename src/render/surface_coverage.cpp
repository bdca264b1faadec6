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
constexpr int kEdgeBisections = 10;
// Surfaces passed on the way down (antimatter, glass) before a probe gives up.
constexpr int kMaxProbePasses = 8;
}  // namespace

SurfaceCoverage::SurfaceCoverage(const material::MaterialTable& materials,
                                 const SceneGeometry& geometry, const Vec3& point,
                                 const Vec3& normal)
    : materials_(materials), geometry_(geometry), point_(point), normal_(normal) {
    orthonormalFrame(normal_, e1_, e2_);
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
    if (!covered(point_, slab)) return {0, false};  // off every surface (rtrace -I in air)
    bool whole = true;
    for (int i = 0; i < kRimProbes && whole; ++i) {
        const double a = 2 * std::numbers::pi * i / kRimProbes;
        whole = covered(point_ + (e1_ * std::cos(a) + e2_ * std::sin(a)) * radius, slab);
    }
    if (whole) return {};
    // Equal areas per probe: radius sqrt((i + 1/2) / n), turned by the golden angle.
    const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
    double x[kDiscProbes], y[kDiscProbes];
    bool in[kDiscProbes];
    int n = 0;
    for (int i = 0; i < kDiscProbes; ++i) {
        const double rho = std::sqrt((i + 0.5) / kDiscProbes), a = golden * i;
        x[i] = rho * std::cos(a);
        y[i] = rho * std::sin(a);
        in[i] = covered(point_ + (e1_ * x[i] + e2_ * y[i]) * radius, slab);
        n += in[i] ? 1 : 0;
    }
    return straightEdge(x, y, in, double(n) / kDiscProbes, radius, slab);
}

pmap::DiscCoverage::Part SurfaceCoverage::straightEdge(const double* x, const double* y,
                                                       const bool* in, double fraction,
                                                       double radius, double slab) const {
    const double delta = pmap::edgeOffsetOfFraction(fraction);
    int best = kDiscProbes;
    double bestAngle = 0;
    for (int j = 0; j < kEdgeDirections; ++j) {
        const double a = 2 * std::numbers::pi * j / kEdgeDirections;
        const double c = std::cos(a), s = std::sin(a);
        int misfits = 0;
        for (int i = 0; i < kDiscProbes; ++i) misfits += (x[i] * c + y[i] * s < delta) != in[i];
        if (misfits < best) {
            best = misfits;
            bestAngle = a;
        }
    }
    if (best > kEdgeMisfits) return {fraction, false};
    // The query is on the surface; the rim beyond the edge must not be.
    const Vec3 out = (e1_ * std::cos(bestAngle) + e2_ * std::sin(bestAngle)) * radius;
    if (covered(point_ + out, slab)) return {fraction, false};
    double lo = 0, hi = 1;
    for (int i = 0; i < kEdgeBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        (covered(point_ + out * mid, slab) ? lo : hi) = mid;
    }
    return {pmap::edgeDiscFraction(0.5 * (lo + hi)), true};
}

}  // namespace rp::render
