// Distant sources (see source.h).
#include "geometry/source.h"

#include <cmath>
#include <string>

#include "util/warnings.h"

namespace rp {

bool makeSource(const Primitive& prim, int32_t primIndex, DistantSource& src) {
    const std::string what = "source '" + prim.name + "'";
    const std::vector<double>& a = prim.rargs;
    if (a.size() != 4)
        throw InputError(prim.loc,
                         what + ": expected 4 real arguments, got " + std::to_string(a.size()));
    Vec3 d{a[0], a[1], a[2]};
    if (!(length(d) > 0)) {
        warn(prim.loc, what + ": zero direction, ignored");
        return false;
    }
    if (!(a[3] > 0)) {
        warn(prim.loc, what + ": zero or negative angle, ignored");
        return false;
    }
    double half = std::fmin(a[3], 360.0) * (kPi / 180.0) * 0.5;
    src.dir = normalize(d);
    src.cosHalfAngle = std::cos(half);
    // RADIANCE compat (srcsupp.c, source.h): ss2 is a float. Its rounding decides rays at
    // the very edge: for a 180 degree glow it rounds 2 pi (1 - 6e-17) up past 2 pi, so
    // rays exactly along the horizon are inside it (sourcesInDirection).
    src.solidAngle = double(float(2 * kPi * (1 - src.cosHalfAngle)));
    src.prim = primIndex;
    src.modifier = prim.modifier;
    return true;
}

void sourcesInDirection(const std::vector<DistantSource>& sources, const Vec3& dir,
                        std::vector<int32_t>& out) {
    out.clear();
    for (size_t i = 0; i < sources.size(); ++i)
        // RADIANCE's own form (source.c sourcehit), not dot >= cosHalfAngle: for a 180
        // degree glow, cos(90 degrees) is 6e-17 and a ray along the horizon (dot exactly
        // 0) would miss it.
        if (2 * kPi * (1 - dot(sources[i].dir, dir)) <= sources[i].solidAngle)
            out.push_back(int32_t(i));
}

}  // namespace rp
