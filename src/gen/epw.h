// epw2wea(1): an EnergyPlus weather file (.epw) to a DAYSIM weather tape (.wea), text
// for text as RADIANCE 5.4's epw2wea writes it. The tape reader is in wea.h.
#pragma once

#include <istream>
#include <string>

namespace rp::gen {

struct EpwConversion {
    std::string wea;      // the .wea file
    std::string console;  // what epw2wea prints on the standard output (the header)
};

// Converts a whole file. From the LOCATION line: city, country (the state when the
// country is empty), latitude, longitude, time zone and elevation; the records per
// hour from DATA PERIODS (the 8th header line); then month, day, hour (mid-interval),
// direct normal and diffuse horizontal irradiance from each record. Throws InputError
// "name:line: ..." where epw2wea would read garbage: no LOCATION line, a short
// LOCATION or DATA PERIODS line, fewer than 8 header lines, a record with fewer than
// 16 fields or with non-numbers where numbers are read.
EpwConversion epwToWea(std::istream& in, const std::string& name);

}  // namespace rp::gen
