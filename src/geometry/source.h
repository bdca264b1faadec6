// RADIANCE `source`: a distant light given as a direction and the angular diameter of
// its disk (ray.html, "Source"). Not a surface in space, so never traced by the
// accelerator; rays that escape the scene ask which sources their direction falls in.
// Emission (sampling, flux) belongs to light/.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/primitive.h"
#include "util/vec.h"

namespace rp {

struct DistantSource {
    Vec3 dir;             // unit, toward the centre of the source
    double cosHalfAngle;  // cos of half the angular diameter
    double solidAngle;    // 2 pi (1 - cosHalfAngle) rounded to float, RADIANCE's ss2
    int32_t prim;
    int32_t modifier;
};

// From "xdir ydir zdir angle" (angle in degrees). A zero direction or a non-positive
// angle warns and returns false; a bad argument count throws InputError.
bool makeSource(const Primitive& prim, int32_t primIndex, DistantSource& src);

// Indices into `sources` of every source whose disk contains unit direction `dir`, in
// input order. RADIANCE compat (source.c, srcvalue): the test is
// 2 pi (1 - dir.sdir) <= ss2, i.e. the angle to the centre is at most half the diameter;
// RADIANCE then shades with the first non-glow match, which is the caller's business.
void sourcesInDirection(const std::vector<DistantSource>& sources, const Vec3& dir,
                        std::vector<int32_t>& out);

}  // namespace rp
