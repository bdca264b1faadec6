// The ray variables a modifier's function file sees at a point (ray.html, "Function
// Files"; RADIANCE func.c): world-space values carried into the modifier's own space by
// the inverse of its transform. Evaluating expressions is calc/; choosing the point is
// the caller's (a shaded hit, a shadow ray meeting a light, a photon leaving one).
#pragma once

#include "calc/ray_context.h"
#include "material/pattern.h"
#include "scene/xform.h"

namespace rp::material {

// Fills every ray variable except Lu, Lv and args. `toObject` is world -> function space
// (the inverse of the modifier's transform). What each value means, as RADIANCE's
// chanvalue gives it:
//  - D, N, I, J, K: directions through toObject, divided by its scale, so a scaled
//    modifier (rect_fixture's -s 0.0254) still sees unit vectors: src_theta's acos(Dz)
//    is the angle off the source's axis whatever the luminaire's units;
//  - P, Tx Ty Tz: points through toObject (Tx Ty Tz: the world origin);
//  - T, Ts: distances in function-space units (times toObject's scale);
//  - S: toObject's scale ("world scale": one world unit measured in function units);
//  - Rdot: as given, clamped to [-1, 1]; not transformed.
calc::RayContext functionSpace(const PatternPoint& at, const Transform& toObject);

}  // namespace rp::material
