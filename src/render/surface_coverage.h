// -ape's measure of a photon search disc (pmap::DiscCoverage): which part of it lies on
// surfaces that can hold the lookup's photons.
#pragma once

#include "geometry/scene_geometry.h"
#include "material/material_table.h"
#include "pmap/density.h"
#include "util/vec.h"

namespace rp::render {

// Measured with probes, each a short ray down onto the tangent plane that must meet,
// within the slab, a surface whose material stores photons (antimatter and transparent
// surfaces passed; an opaque one that keeps no photons, such as a mirror, ends it).
// Nothing else is asked of a probe: the photon search finds photons wherever the slab
// meets such a surface (beyond a thin partition on the same floor too), so the part
// measured is the part the photons counted come from.
// 16 probes on the rim and the centre first: all on the surface means the whole disc
// (RADIANCE's estimate stays); otherwise 64 spread evenly over the disc (a sunflower
// pattern, fixed in the tangent frame). The part is taken for one straight edge when a
// line in one of 64 directions, placed to leave that fraction, puts at most 2 of them on
// its wrong side; the edge's distance is then found by bisection along the line's normal,
// and the fraction follows from it to about 1e-3 (64 probes leave it uncertain by 1/64,
// which the gradient fit, pmap/edge_estimate.h, magnifies).
class SurfaceCoverage final : public pmap::DiscCoverage {
public:
    // `normal`: the surface's unit geometric normal on the side the light comes from.
    SurfaceCoverage(const material::MaterialTable& materials, const SceneGeometry& geometry,
                    const Vec3& point, const Vec3& normal);
    Part part(double radius2, double slab) const override;
    const Vec3& planeNormal() const override { return normal_; }

private:
    // Whether the probe at `at` (in the tangent plane) finds the surface.
    bool covered(const Vec3& at, double slab) const;
    // The straight edge that best explains the probes at (x, y) (disc radii in the
    // tangent frame), as the fraction it leaves, if one does.
    Part straightEdge(const double* x, const double* y, const bool* in, double fraction,
                      double radius, double slab) const;

    const material::MaterialTable& materials_;
    const SceneGeometry& geometry_;
    Vec3 point_, normal_, e1_, e2_;
};

}  // namespace rp::render
