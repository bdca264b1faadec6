// Flat polygon sources seen from a point: RADIANCE's binary subdivision of the source's
// bounding rectangle (srcsamp.c flt_partit) with each cell clipped exactly against the
// polygon, so that concave polygons and holes get the right area. Used by
// source_sampling.cpp; separate because clipping is most of it.
#pragma once

#include <vector>

#include "render/source_list.h"
#include "render/source_sampling.h"
#include "util/rng.h"

namespace rp::render {

// Appends one sample per non-empty cell. `ds` <= 0 means one cell for the whole polygon
// (RADIANCE nopart). The caller checks that `from` is in front of the polygon.
void samplePolygon(const PlanarRegion& region, const Vec3& from, double ds, double weight,
                   double jitter, Rng& rng, std::vector<SourceSample>& out);

}  // namespace rp::render
