// -ape's measure of a photon search disc (pmap::DiscCoverage): which part of it lies on
// surfaces that can hold the lookup's photons.
#pragma once

#include "geometry/ray.h"
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
// A disc that lies inside the query's own polygon (its distance to the nearest edge, for
// a polygon of the scene itself) needs no probe. Else 16 probes on the rim and the
// centre come first: all on the surface means the whole disc (RADIANCE's estimate
// stays). Otherwise 64 probes spread evenly over the disc (a sunflower pattern, fixed in
// the tangent frame) give the fraction. The part is taken for one straight edge when a
// line in one of 64 directions (the 7 nearest the uncovered probes' centroid), placed to
// leave that fraction, puts at most 2 probes on its wrong side; the edge's distance is
// then found by bisection along the line's normal, and the fraction follows from it to
// about 1e-3 (64 probes leave it uncertain by 1/64, which the gradient fit,
// pmap/edge_estimate.h, magnifies).
class SurfaceCoverage final : public pmap::DiscCoverage {
public:
    // `normal`: the hit surface's unit geometric normal on the side the light comes from.
    SurfaceCoverage(const material::MaterialTable& materials, const SceneGeometry& geometry,
                    const Hit& hit, const Vec3& normal);
    Part part(double radius2, double slab) const override;
    const Vec3& planeNormal() const override { return normal_; }

private:
    // Whether the probe at `at` (in the tangent plane) finds the surface.
    bool covered(const Vec3& at, double slab) const;
    // The query's distance to the nearest edge of the polygon it lies on; 0 where the
    // surface is no polygon of the scene itself (instances and meshes, other shapes).
    double polygonClearance() const;
    // The straight edge that best explains which disc probes found the surface (`in`),
    // as the fraction it leaves, if one does.
    Part straightEdge(const bool* in, double fraction, double radius, double slab) const;

    const material::MaterialTable& materials_;
    const SceneGeometry& geometry_;
    const Hit& hit_;
    Vec3 point_, normal_;
    // The tangent frame, made at the first probe: shading builds one of these at every
    // ambient lookup, and only -ape's ask it anything.
    mutable Vec3 e1_, e2_;
    mutable bool framed_ = false;
};

}  // namespace rp::render
