// Which mists enclose a point (a viewpoint or a lamp in the fog). RADIANCE's rays and
// photons learn their medium only from the boundaries they cross, so one that starts in
// a mist and ends on a surface inside it never knows; m_mist.c's "fix old" catches only
// those that leave it. A probe ray from the point out of the scene tells: a mist
// boundary it meets from the back, before meeting that mist from the front, encloses the
// point (closed boundaries, as ray.html asks of mists).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/scene_geometry.h"
#include "material/surface_chain.h"
#include "util/color.h"
#include "util/rng.h"

namespace rp::material {

struct EnclosingMist {
    int32_t material;  // the mist's record (SurfaceChains::materials())
    Color pattern;     // the pattern at the boundary the probe left it through
};

// The mists enclosing `p`, innermost first; empty when the scene has none. The chains
// are evaluated at the probe's hits (patterns, mixtures: `rng`).
std::vector<EnclosingMist> enclosingMists(const SceneGeometry& geometry,
                                          const SurfaceChains& chains, const Vec3& p, Rng& rng);

// The medium inside the mists `around` (enclosingMists' answer, entered outermost first)
// from the global one, with those mists added to `mists`.
Medium mediumWithin(const std::vector<EnclosingMist>& around, const Medium& global,
                    const MaterialTable& materials, MistSet& mists);

// Whether any surface's modifier chain can reach a mist (probing is needed at all).
bool sceneHasMist(const Scene& scene);

}  // namespace rp::material
