// Sky luminance distributions of skybright.cal (the skies gensky describes) and the
// polynomial normalisation gensky uses in place of integrating them. Evaluating these
// here lets tests integrate the sky numerically and check gensky's ground brightness.
// gensky's own computation is in gensky.h.
#pragma once

#include "gen/gensky.h"
#include "util/vec.h"

namespace rp::gen {

// Clear-sky normalisation F2 = 0.274 (0.91 + 10 exp(-3 Zs) + 0.45 cos^2 Zs): the CIE
// indicatrix at the sun's zenith angle Zs times the gradation at the zenith (0.274 ~
// 1 - exp(-0.32)).
double clearSkyF2(double sunAltitude);
// Intermediate-sky normalisation (gensky): (2.739 + .9891 sin(.3119 + 2.6 alt))
// exp(-(pi/2 - alt)(.4441 + 1.48 alt)).
double intermediateSkyF2(double sunAltitude);

// gensky's normsc(): fourth-order polynomial fit of (horizontal diffuse irradiance * F2 /
// zenith radiance) in x = (alt - pi/4)/(pi/4); `intermediate` picks the second fit.
double skyNormalisationFit(double sunAltitude, bool intermediate);

// Sky radiance in direction dir (unit, dir.z > 0) for skybright.cal's arguments: type,
// zenith brightness, normalisation f2 and the sun direction. Above-horizon part only
// (skybright.cal blends towards the ground brightness below the horizon).
double skyRadiance(SkyType type, double zenith, double f2, const Vec3& sunDir, const Vec3& dir);

// Horizontal irradiance from the sky hemisphere, integral of L cos(theta) d omega, by
// the midpoint rule over nTheta x nPhi cells.
double skyHorizontalIrradiance(SkyType type, double zenith, double f2, const Vec3& sunDir,
                               int nTheta = 360, int nPhi = 720);

}  // namespace rp::gen
