// The DAYSIM weather tape (.wea) that gendaymtx reads: six header lines (place, latitude,
// longitude, time_zone, site_elevation, weather_data_file_units) and one line per time
// step, "month day hour direct diffuse". Reading only; the EPW conversion is in epw.h and
// the sky matrix in gendaymtx.h.
#pragma once

#include <istream>
#include <string>
#include <vector>

namespace rp::gen {

// What the two values of a time step are (weather_data_file_units).
enum class WeaUnits {
    DirectNormalIrradiance = 1,      // direct normal, diffuse horizontal (W/m2)
    DirectHorizontalIrradiance = 2,  // direct horizontal, diffuse horizontal (W/m2)
    DirectNormalIlluminance = 3,     // direct normal, diffuse horizontal (lux)
};

struct WeaHeader {
    std::string place;
    double latitude = 0;   // degrees north
    double longitude = 0;  // degrees west
    double timeZone = 0;   // standard meridian, degrees west
    double elevation = 0;  // metres
    WeaUnits units = WeaUnits::DirectNormalIrradiance;
};

struct WeaRecord {
    int month = 0, day = 0;
    double hour = 0;  // local standard time
    double direct = 0, diffuse = 0;
    int line = 0;  // 1-based, for messages
};

struct WeaTape {
    WeaHeader header;
    std::vector<WeaRecord> records;
};

// Reads a whole tape. RADIANCE compat (gendaymtx.c main): the header keywords come in
// this order, white space between words (new lines included) is free, and units 1..3 are
// accepted. Where RADIANCE stops at the first unreadable record (and warns about data
// past the end of the tape) we throw: an InputError "name:line: ..." for a record that
// is not five numbers, a bad month or day, and a header keyword missing or out of order.
WeaTape readWea(std::istream& in, const std::string& name);

}  // namespace rp::gen
