// Subdividing one light source into samples as seen from a point (RADIANCE srcsamp.c):
// cells no larger than -ds times their distance (at most MAXSPART = 64 per source), one
// sample per cell, moved within it by -dj. Which sources exist is source_list.h; shadow
// testing and the -dt/-dc ordering are direct.cpp.
#pragma once

#include <vector>

#include "geometry/ray.h"
#include "render/render_options.h"
#include "render/source_list.h"
#include "util/rng.h"
#include "util/vec.h"

namespace rp::render {

struct PolygonScratch;  // source_polygon.h

constexpr int kMaxSourceParts = 64;  // RADIANCE MAXSPART: cells per source at most

struct SourceSample {
    Vec3 dir;          // unit direction from the (apparent) origin toward the sample
    Vec3 target;       // the sample point on the source surface (local sources)
    double dist = 0;   // distance from the origin to target (HUGE_VAL: distant source)
    double omega = 0;  // solid angle of the sample's cell seen from the origin
};

// Appends the samples of `src`'s real surface seen from `from` (for a virtual source,
// the shaded point reflected through its mirrors). `weight` is the ray weight: RADIANCE
// subdivides less for low-weight rays (flatpart: cell size/distance <= ds/weight).
// Per shape:
//  - polygon: RADIANCE's binary subdivision of the bounding rectangle (flt_partit); each
//    cell is clipped exactly against the polygon's triangles (concave polygons and holes
//    work), omega is the covered area times cos over d^2 at the sample (RADIANCE's
//    nextssamp; -ds 0: one sample at the centre for the whole source), the sample the
//    covered part's centroid
//    (jittered toward a uniform point of the covered part; a jittered point that leaves
//    a non-convex covered part falls back to that uniform point);
//  - sphere: equal-solid-angle cells of the cone of directions it subtends (exact total
//    solid angle); nothing from inside;
//  - distant: the same for its direction cone;
//  - ring: equal-area polar cells; cone family and bubbles: cells in (angle, axis)
//    parameters; omega = area cos / distance^2 at the sample point.
// Samples behind a flat source, outside a spotlight's cone or beyond a glow's radius
// are not produced.
void sampleSource(const SourceList& list, const DirectSource& src, const ShapeSet& shapes,
                  const Vec3& from, const DirectOptions& options, double weight, Rng& rng,
                  PolygonScratch& scratch, std::vector<SourceSample>& out);

// The hit record a ray travelling in `dir` would get on `src`'s surface at point `p`
// (distance `t` from its origin), as SceneGeometry::closestHit completes it: used to ask
// the oracle for the source's radiance without tracing, and when a shadow ray reaches
// its target without the accelerator reporting the (grazed) source surface.
Hit sourceSurfaceHit(const DirectSource& src, const ShapeSet& shapes,
                     const std::vector<PlanarRegion>& regions, const Vec3& p, const Vec3& dir,
                     double t);

// Same for a point on a relay (planar mirror or prism).
Hit relaySurfaceHit(const RelayPlane& m, const Vec3& p, const Vec3& dir, double t);

// Exact solid angle of triangle (a, b, c) seen from `o` (Van Oosterom & Strackee 1983).
double triangleSolidAngle(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace rp::render
