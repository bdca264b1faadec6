// Flat polygon sources seen from a point: RADIANCE's binary subdivision of the source's
// bounding rectangle (srcsamp.c flt_partit) with each cell clipped exactly against the
// polygon, so that concave polygons and holes get the right area. Used by
// source_sampling.cpp; separate because clipping is most of it.
#pragma once

#include <array>
#include <vector>

#include "render/source_list.h"
#include "render/source_sampling.h"
#include "util/rng.h"

namespace rp::render {

// A cell of the source's bounding rectangle, in its (u, v) coordinates.
struct PolygonCell {
    double u0, u1, v0, v1;
};

// A convex piece of a cell: a triangle clipped by a rectangle has at most 7 corners.
struct PolygonPiece {
    std::array<double, 2 * 8> uv;
    int n = 0;
    double area = 0;
    double cu = 0, cv = 0;  // centroid
};

// Working memory of samplePolygon, kept by the caller (it runs at every shaded point).
// The cells of one source fit a fixed array: subdivision stops at kMaxSourceParts.
struct PolygonScratch {
    std::array<PolygonCell, kMaxSourceParts> cells;
    int cellCount = 0;
    std::vector<PolygonPiece> pieces;
};

// Appends one sample per non-empty cell. `ds` <= 0 means one cell for the whole polygon
// (RADIANCE nopart). The caller checks that `from` is in front of the polygon.
void samplePolygon(const PlanarRegion& region, const Vec3& from, double ds, double weight,
                   double jitter, Rng& rng, PolygonScratch& scratch,
                   std::vector<SourceSample>& out);

}  // namespace rp::render
