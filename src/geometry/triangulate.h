// Triangulation of one planar polygon exactly as RADIANCE's point-in-polygon test
// (face.c inface: even-odd crossings in the dominant-axis projection) defines it: any
// vertex count, convex or concave, holes joined to the outline by a seam (with or
// without the repeated return vertex), several holes, overlapping and collinear seam
// edges, self-intersections. Planes and shapes live in polygon.h; this file only turns
// a vertex loop into triangles.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "util/vec.h"

namespace rp {

using TriIndices = std::array<uint32_t, 3>;

struct Triangulation {
    // The triangles' corners: the input loop for convex polygons; otherwise the loop's
    // vertices plus points on its edges where the decomposition cut them.
    std::vector<Vec3> vertices;
    std::vector<TriIndices> triangles;  // indices into vertices, CCW about the normal
};

// Triangulates the loop verts[0..n) whose front side faces `normal` (counter-clockwise
// seen from the front, RADIANCE's convention). The triangles cover exactly the points
// with an odd crossing count, each once, and share every edge point they touch (no
// T-junctions). Zero-area triangles are dropped. A fan in O(n) for convex loops; else
// each slab costs O(e log e) for the e edges crossing it: walls with thousands of windows
// take milliseconds (99k vertices: 0.05 s), but an outline that a horizontal line crosses
// O(n) times is quadratic (a random 10,000-spike star: 1 s).
Triangulation triangulatePolygon(std::span<const Vec3> verts, const Vec3& normal);

}  // namespace rp
