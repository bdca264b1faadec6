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
// Inside an instance or mesh (at.object), world -> object space comes first, as RADIANCE
// composes ray.rox with the modifier's own transform (func.c setfunc).
calc::RayContext functionSpace(const PatternPoint& at, const Transform& toObject);

// world -> function space for `at`: toObject after the object's space, if any.
Transform functionTransform(const PatternPoint& at, const Transform& toObject);

// A vector computed in function space (a texture's perturbation) carried back to world
// space as RADIANCE's t_func.c does: the modifier's forward rotation, then the object's,
// each scale divided out.
Vec3 functionToWorld(const PatternPoint& at, const Transform* forward, Vec3 v);

}  // namespace rp::material
