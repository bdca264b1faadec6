// gendaylit(1): a Perez all-weather sky (brightfunc over perezlum.cal) and sun from
// measured direct and diffuse irradiance or illuminance, as RADIANCE's gendaylit
// computes and prints it. Parsing, the computation and the text; the Perez model itself
// is in perez.h, sun position in sun_position.h. Tool main: tools/gendaylit.cpp.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "gen/sun_position.h"
#include "util/vec.h"

namespace rp::gen {

// Which measurements were given.
enum class DaylitInput {
    Perez,             // -P epsilon delta
    DirectNormal,      // -W direct-normal diffuse-horizontal irradiance (W/m2)
    Illuminance,       // -L direct-normal diffuse-horizontal illuminance (lux)
    DirectHorizontal,  // -G direct-horizontal diffuse-horizontal irradiance (W/m2)
    Global,            // -E global horizontal irradiance (W/m2), Erbs split
};

struct GendaylitOptions {
    bool fromAngles = false;           // -ang alt azi
    double altitude = 0, azimuth = 0;  // radians
    int month = 0, day = 0, year = 0;
    double hour = 0;
    bool solarTime = false;  // "+hour"
    Site site;
    bool haveInput = false;
    DaylitInput input = DaylitInput::DirectNormal;
    double value1 = 0, value2 = 0;   // the two numbers after -P/-W/-L/-G (one for -E)
    bool sun = true;                 // -s: no sun source (+s: with)
    bool cloudy = false;             // -c/+c: no sun, and no 87 degree altitude limit
    double groundReflectance = 0.2;  // -g
    int output = 0;                  // -O: 0 visible W, 1 solar W, 2 lumen
    double dewPoint = 10.97353115;   // -d (deg C): precipitable water exp(.07 Td - .075)
    bool quiet = false;              // -w: no warnings
};

struct GendaylitSky {
    bool errorSky = false;  // gendaylit's "error sky": all-zero Perez arguments
    double solarTime = 0;   // hours (0 with -ang, as gendaylit prints it)
    double altitude = 0, azimuth = 0;
    Vec3 sunDir;
    double epsilon = 0, delta = 0, water = 0;
    double diffuseIrradiance = 0, directIrradiance = 0;    // W/m2 (direct: normal)
    double diffuseIlluminance = 0, directIlluminance = 0;  // lux
    std::array<double, 5> coeffs{};                        // Perez a..e
    double diffuseNormalisation = 0;                       // perezlum.cal A1
    double groundBrightness = 0;                           // A2
    double solarRadiance = 0;
    double zenithBrightness = 0;
    bool sun = false;  // print the sun source at all
    std::vector<std::string> warnings;
    std::vector<std::string> comments;  // extra "# ..." lines (-E)
};

// Throws InputError for bad dates/hours, missing measurements, unknown options, -O
// outside 0..2 and non-numeric words.
GendaylitOptions parseGendaylitArgs(const std::vector<std::string>& args);

GendaylitSky computeGendaylit(const GendaylitOptions& opt);

std::string formatGendaylit(const GendaylitSky& sky, const std::vector<std::string>& args);

std::string gendaylit(const std::vector<std::string>& args, std::vector<std::string>* warnings);

}  // namespace rp::gen
