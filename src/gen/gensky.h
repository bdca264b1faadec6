// gensky(1): CIE clear, intermediate, overcast and uniform skies with an optional sun,
// as RADIANCE's gensky computes and prints them (zenith brightness from turbidity,
// normalisation by polynomial fits, ground brightness, skybright.cal arguments). Command
// parsing, the computation and the text; sun position is in sun_position.h, the sky
// luminance formulas themselves in cie_sky.h. Tool main: tools/gensky.cpp.
#pragma once

#include <string>
#include <vector>

#include "gen/sun_position.h"
#include "util/vec.h"

namespace rp::gen {

// The numbers are skybright.cal's sky types (first real argument).
enum class SkyType { Clear = 1, Overcast = 2, Uniform = 3, Intermediate = 4 };

// How a -b/-B or -r/-R value is meant: not given, radiance (lower case), or horizontal
// irradiance (upper case).
enum class GivenAs { Computed, Radiance, Irradiance };

struct GenskyOptions {
    bool printDefaults = false;  // gensky -defaults
    bool fromAngles = false;     // gensky -ang alt azi
    double altitude = 0;         // radians (from -ang or computed)
    double azimuth = 0;          // radians west of south
    int month = 0, day = 0;
    int year = 0;  // -y; 0 = day-of-year formulas
    double hour = 0;
    bool solarTime = false;  // "+hour": local solar time
    Site site;
    SkyType type = SkyType::Clear;
    bool sun = true;    // +s / +i
    double zenith = 0;  // -b / -B value
    GivenAs zenithGiven = GivenAs::Computed;
    double solar = 0;  // -r / -R value
    GivenAs solarGiven = GivenAs::Computed;
    double turbidity = 2.45;         // -t
    double groundReflectance = 0.2;  // -g
};

// What gensky computes; every printed number comes from here.
struct GenskySky {
    SkyType type = SkyType::Clear;
    bool fromDate = false;
    double solarTime = 0;              // hours, when fromDate
    double altitude = 0, azimuth = 0;  // radians, after the 87 degree limit
    bool altitudeLimited = false;      // sun moved down to 87 degrees
    double dateAltitude = 0;           // the altitude from the date, before that limit
    Vec3 sunDir;
    double zenithBrightness = 0;  // W/sr/m2 (skybright.cal A2)
    double f2 = 0;                // clear/intermediate normalisation (A4)
    double groundAmbient = 0;     // diffuse horizontal irradiance / pi ("Ground ambient level")
    double groundBrightness = 0;  // reflectance * (sky + sun) horizontal irradiance / pi (A3)
    double solarRadiance = 0;     // W/sr/m2 of the 0.5 degree sun disc
    bool sun = false;             // whether the sun source is printed
    std::vector<std::string> warnings;  // for stderr, without the "gensky: " prefix
};

// RADIANCE's cvthour(), the hour word of gensky, gendaylit and genssky: "[+]H[.frac]" or
// "[+]H:MM" ('+': local solar time), optionally followed (standard time only) by a time
// zone name, which sets site.meridian. Returns true when a zone was given. InputError for
// a malformed word, an hour past 24 or an unknown zone.
bool parseClockTime(const std::string& word, double& hour, bool& solarTime, Site& site);

// Parse gensky's command line (args[0] = program name). Throws InputError for bad dates
// (month 1..12, day within the month), hours outside 0..24, unknown time zones, unknown
// options, missing values and non-numeric words.
GenskyOptions parseGenskyArgs(const std::vector<std::string>& args);

GenskySky computeGensky(const GenskyOptions& opt);

// "# gensky ..." header, the comment lines, the sun and skyfunc, in RADIANCE's layout.
std::string formatGensky(const GenskySky& sky, const std::vector<std::string>& args);

// "gensky -defaults": the default options, one per line.
std::string genskyDefaults(const GenskyOptions& opt);

// parse + compute + format; warnings (if given) receive what gensky prints on stderr.
std::string gensky(const std::vector<std::string>& args, std::vector<std::string>* warnings);

}  // namespace rp::gen
