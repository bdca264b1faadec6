// Ear-clipping triangulation of one planar polygon as RADIANCE allows it: any vertex
// count, convex or concave, and holes joined to the outline by a seam (an edge walked
// once in each direction, so seam vertices appear twice). Planes and shapes live in
// polygon.h; this file only turns a vertex loop into triangles.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "util/vec.h"

namespace rp {

using TriIndices = std::array<uint32_t, 3>;

struct Triangulation {
    std::vector<TriIndices> triangles;  // indices into the input loop, CCW about normal
    bool clean = true;  // false if no valid ear was left and a fallback clip was used
                        // (self-intersecting input); the result still covers the loop
};

// Triangulates the loop verts[0..n) whose front side faces `normal` (counter-clockwise
// seen from the front, RADIANCE's convention). Zero-area triangles (collinear runs, the
// two sides of a seam) are dropped. Runs in O(n) for convex loops, O(n * reflex) else.
Triangulation triangulatePolygon(std::span<const Vec3> verts, const Vec3& normal);

}  // namespace rp
