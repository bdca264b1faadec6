// The sky subdivision of gendaymtx: Tregenza's 145 patches split m x m ways (Reinhart),
// with the ground as patch 0 and the zenith cap last, each patch's centre and solid angle
// kept in single precision as gendaymtx keeps them; and RADIANCE's table cosine, which
// gendaymtx uses for the patches' cosines. The .cal form of the same binning is
// lib/reinhartb.cal. The sky model is in gendaymtx_sky.h.
#pragma once

#include <vector>

#include "util/vec.h"

namespace rp::gen {

struct ReinhartSky {
    int subdivisions = 1;
    // Per patch: altitude and azimuth (radians; azimuth from north, increasing towards
    // +x) and solid angle (sr). Patch 0 is the ground (altitude -pi/2, solid angle 2 pi).
    std::vector<float> altitude, azimuth, solidAngle;

    int size() const { return static_cast<int>(altitude.size()); }
    // Unit vector to a patch centre: (cos alt sin azi, cos alt cos azi, sin alt).
    Vec3 direction(int patch) const;
};

// 145 m^2 + 2 patches (m = 0 leaves the ground and one zenith cap over the hemisphere).
// RADIANCE compat (gendaymtx.c rh_init): rows of equal altitude step pi/2 / (7m + 1/2),
// the last half step being the zenith cap; Tregenza's 30, 30, 24, 24, 18, 12, 6 patches
// per row, each times m.
ReinhartSky makeReinhartSky(int subdivisions);

// Unit vector for an altitude and azimuth as gendaymtx's vector() macro builds it.
Vec3 skyVector(double altitude, double azimuth);

// RADIANCE's tcos() (common/tcos.c, built without fast math): the cosine looked up in a
// 1025-entry table over a quarter turn, nearest entry, no interpolation; tableSin(x) is
// tableCos(x - pi/2) as RADIANCE's tsin().
double tableCos(double x);
double tableSin(double x);

}  // namespace rp::gen
