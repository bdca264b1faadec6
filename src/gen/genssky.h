// genssky(1), RADIANCE 6's spectral sky: a clear sky from the precomputed atmosphere
// (atmosphere.h) for a date, time and place, blended with a CIE overcast sky by cloud
// cover, optionally scaled to measured illuminances; written as a hyperspectral picture
// of the whole sphere of directions (<prefix>_sky.hsr, 20 bands from 380 to 780 nm)
// and a scene text with the sun (a `light` under a `spectrum`) and `specpict skyfunc`
// that maps directions onto that picture, as RADIANCE 6.1a's genssky prints them.
// The atmosphere's tables are kept in <dir>/atmos_data for later runs. Tool main:
// tools/genssky.cpp.
#pragma once

#include <string>
#include <vector>

#include "gen/sun_position.h"

namespace rp::gen {

struct GensskyOptions {
    bool printDefaults = false;  // genssky -defaults
    int month = 0, day = 0, year = 0;
    double hour = 0;
    bool solarTime = false;  // "+hour"
    Site site;
    double aerosolDepth = 0.115;         // -d: broadband aerosol optical depth
    double cloudCover = 0;               // -c: 0 clear .. 1 overcast
    std::string mieFile = "mie_ca.dat";  // -l: aerosol scattering by altitude and band
    std::string dataDir = ".";           // -p: where the picture and atmos_data go
    double groundReflectance = 0.2;      // -g
    double directNormal = 0;             // -L: direct normal illuminance (lux), 0: computed
    double diffuseHorizontal = 0;        // -L: diffuse horizontal illuminance (lux)
    int threads = 1;                     // -n
    int resolution = 64;                 // -r: picture width; the height is half
    std::string prefix = "out";          // -f
    int orders = 4;                      // -i: scattering orders
};

// Parses genssky's command line (args[0] = program name). InputError for bad dates and
// times, unknown options, missing values and values out of range.
GensskyOptions parseGensskyArgs(const std::vector<std::string>& args);

// "genssky -defaults".
std::string gensskyDefaults(const GensskyOptions& opt);

// Runs genssky: computes (or reads from atmos_data) the atmosphere, writes the picture,
// returns the scene text. `searchPath` finds the aerosol file (RAYPATH); `warnings`
// receives what genssky prints on stderr.
std::string genssky(const std::vector<std::string>& args,
                    const std::vector<std::string>& searchPath, std::vector<std::string>* warnings);

}  // namespace rp::gen
