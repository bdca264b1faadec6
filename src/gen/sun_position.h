// Solar position as RADIANCE's gensky and gendaylit compute it (src/gen/sun.c): the
// simple day-of-year formulas used without a year, and the Michalsky (1988) Astronomical
// Almanac algorithm used with -y year. Angles in radians; RADIANCE's conventions:
// longitude and standard meridian positive WEST of Greenwich, azimuth measured from
// south towards west, x = east, y = north, z = up. No sky models here (gensky.h, gendaylit.h).
#pragma once

#include "util/vec.h"

namespace rp::gen {

constexpr double kDegree = kPi / 180.0;

// Site on the earth. RADIANCE compat: the defaults are sun.c's radian constants
// (latitude 0.66 = 37.815 deg N, longitude 2.13 = 122.04 deg W, meridian 120 deg W),
// roughly San Francisco; "gensky -defaults" prints them in degrees.
struct Site {
    double latitude = 0.66;
    double longitude = 2.13;
    double meridian = 120.0 * kDegree;
};

// Date checks shared by gensky and gendaylit: month 1..12, day 1..days in that month
// (February 29 allowed). Throws InputError naming the bad field.
void checkDate(int month, int day);

// RADIANCE jdate(): day of the year 1..365, ignoring leap years.
int dayOfYear(int month, int day);

// Hours to add to standard clock time to get solar time (equation of time plus the
// meridian/longitude offset): 0.170 sin(4pi(J-80)/373) - 0.129 sin(2pi(J-8)/355)
// + 12 (meridian - longitude)/pi.
double solarTimeAdjustment(int jd, const Site& site);

// Solar declination 0.4093 sin(2pi(J-81)/365). RADIANCE compat: sun.c used 368 until
// Oct 2019 (v2.7) and 365 since; RADIANCE 5.4's gensky output for the daylight
// validation scene is reproduced only with 365, so 365 it is.
double solarDeclination(int jd);

// Altitude and azimuth (west of south) from declination and solar time in hours.
double solarAltitude(const Site& site, double declination, double solarTimeHours);
double solarAzimuth(const Site& site, double declination, double solarTimeHours);

// Michalsky's algorithm: days from noon UT on 1 Jan 2000 for a standard clock time at
// the site's meridian, and the declination (plus local solar time in hours, when asked)
// for that instant. Meant for 1950..2050.
double almanacDay(int year, int month, int day, double clockHours, const Site& site);
double almanacDeclination(double mjd, const Site& site, double* solarTimeHours);

struct SunPosition {
    double solarTime = 0;  // hours
    double declination = 0;
    double altitude = 0;
    double azimuth = 0;
};

// The whole chain: year 0 means the day-of-year formulas; hourIsSolar means the hour
// is already local solar time (RADIANCE's "+hour").
SunPosition sunPosition(const Site& site, int year, int month, int day, double hour,
                        bool hourIsSolar);

// Unit vector towards the sun: (-sin azi cos alt, -cos azi cos alt, sin alt).
Vec3 sunDirection(double altitude, double azimuth);

}  // namespace rp::gen
