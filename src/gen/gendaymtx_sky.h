// One time step of gendaymtx's sky: the Perez parameters from the measured direct and
// diffuse values, the patch radiances (ground first, then the sky patches), the direct
// sun spread over the nearest patches, and the sun description of the -D file. The
// Perez formulas themselves are perez.h's; the time loop and the matrix are gendaymtx.h's.
#pragma once

#include <array>
#include <string>

#include "gen/gendaymtx_patches.h"

namespace rp::gen {

// RADIANCE COLOR values are floats; gendaymtx multiplies patch values by them in float.
using DaymtxColor = std::array<float, 3>;

struct DaymtxSkyOptions {
    DaymtxColor skyColor{0.96f, 1.004f, 1.118f};  // -c
    DaymtxColor sunColor{1, 1, 1};                // 0 with -s
    DaymtxColor groundReflectance{0.2f, 0.2f, 0.2f};
    bool solarRadiance = false;      // -O1: total solar rather than visible radiance
    int sunPatches = 4;              // patches the sun is spread over (-5: 1)
    double fixedSunSolidAngle = -1;  // sr, -5: the sun's own instead of the patch's
};

// One time step as the model sees it.
struct DaymtxStep {
    double altitude = 0;  // sun, radians
    double azimuth = 0;   // sun, radians, in the patches' convention (rotation applied)
    int julianDate = 1;   // day of the year, for the eccentricity
    bool photometric = false;
    double direct = 0, diffuse = 0;  // direct normal, diffuse horizontal (W/m2 or lux)
};

// What the Perez model derived from the measurements.
struct DaymtxPerez {
    double sunZenith = 0;  // radians, kept within 3..90 degrees
    double clearness = 0, brightness = 0;
    int category = 0;
    double diffuseIrradiance = 0, directIrradiance = 0;
    double diffuseIlluminance = 0, directIlluminance = 0;  // lux (or W/m2 x 179 with -O1)
};

// The Perez sky parameters and illuminances for a step. RADIANCE compat (gendaymtx.c
// ComputeSky, CalcSkyParamFromIllum): clearness capped at 11.9 (irradiance input) or 12
// (illuminance input, which iterates at most 5 times), brightness raised to 0.01.
DaymtxPerez daymtxPerez(const DaymtxStep& step, bool solarRadiance);

// Fills patches[3 * sky.size()]: the ground (patch 0) from the global horizontal value
// and the reflectance, the sky patches from the Perez distribution scaled to the diffuse
// horizontal illuminance, in W/sr/m2 (lumens / 179).
void computeSkyPatches(const ReinhartSky& sky, const DaymtxSkyOptions& opt, const DaymtxStep& step,
                       const DaymtxPerez& perez, float* patches);

// Adds the direct sun to the sunPatches patches nearest the sun, weighted by proximity
// 1 / (1.002 - cos angle), divided by each patch's solid angle (or the fixed one).
void addDirectSun(const ReinhartSky& sky, const DaymtxSkyOptions& opt, const DaymtxStep& step,
                  double directIlluminance, float* patches);

// The -D description of one sun: "solar<minute>" light and "sun<minute>" source, 0.533
// degrees wide, radiance 0 unless `lit`.
std::string daymtxSunText(int minute, bool lit, double directIlluminance, const DaymtxStep& step,
                          const DaymtxColor& sunColor);

// RADIANCE's bright() of a colour, for gendaymtx's "colour is black" tests.
double daymtxBrightness(const DaymtxColor& c);

}  // namespace rp::gen
