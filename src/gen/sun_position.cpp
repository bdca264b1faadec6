// Solar position formulas of RADIANCE's sun.c (see sun_position.h for the sources).
#include "gen/sun_position.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace rp::gen {

namespace {
// Wrap r into [0, period).
double wrap(double r, double period) {
    r = std::fmod(r, period);
    return r < 0 ? r + period : r;
}
constexpr int kMonthStart[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
constexpr int kMonthDays[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
}  // namespace

void checkDate(int month, int day) {
    if (month < 1 || month > 12)
        throw InputError("bad month " + std::to_string(month) + ": expected 1..12");
    if (day < 1 || day > kMonthDays[month - 1])
        throw InputError("bad day " + std::to_string(day) + ": month " + std::to_string(month) +
                         " has days 1.." + std::to_string(kMonthDays[month - 1]));
}

int dayOfYear(int month, int day) { return kMonthStart[month - 1] + day; }

double solarTimeAdjustment(int jd, const Site& site) {
    return 0.170 * std::sin((4.0 * kPi / 373.0) * (jd - 80)) -
           0.129 * std::sin((2.0 * kPi / 355.0) * (jd - 8)) +
           (12.0 / kPi) * (site.meridian - site.longitude);
}

double solarDeclination(int jd) { return 0.4093 * std::sin((2.0 * kPi / 365.0) * (jd - 81)); }

double solarAltitude(const Site& site, double decl, double st) {
    return std::asin(std::sin(site.latitude) * std::sin(decl) -
                     std::cos(site.latitude) * std::cos(decl) * std::cos(st * (kPi / 12.0)));
}

double solarAzimuth(const Site& site, double decl, double st) {
    return -std::atan2(std::cos(decl) * std::sin(st * (kPi / 12.0)),
                       -std::cos(site.latitude) * std::sin(decl) -
                           std::sin(site.latitude) * std::cos(decl) * std::cos(st * (kPi / 12.0)));
}

// Michalsky 1988, Solar Energy 40(3):227-235: days since J2000.0 from the Julian date
// 2432916.5 of 1 Jan 1949 0h UT, counting leap days; clock time becomes UT through the
// standard meridian.
double almanacDay(int year, int month, int day, double clockHours, const Site& site) {
    int jd = dayOfYear(month, day);
    if (month > 2 && year % 4 == 0) jd += 1;  // RADIANCE compat: every 4th year is leap
    jd += (year - 1949) * 365 + (year - 1949) / 4;
    double utHours = clockHours + site.meridian * (12.0 / kPi);
    return jd + utHours / 24.0 + (2432916.5 - 2451545.0);
}

double almanacDeclination(double mjd, const Site& site, double* solarTimeHours) {
    // Mean longitude L, mean anomaly g, ecliptic longitude l, obliquity ep (Almanac C24).
    double L = wrap((280.460 + 0.9856474 * mjd) * kDegree, 2 * kPi);
    double g = wrap((357.528 + 0.9856003 * mjd) * kDegree, 2 * kPi);
    double l = L + 1.915 * kDegree * std::sin(g) + 0.020 * kDegree * std::sin(2 * g);
    double ep = (23.439 - 4e-7 * mjd) * kDegree;
    if (solarTimeHours) {
        double ra = std::atan2(std::sin(l) * std::cos(ep), std::cos(l));
        double ut = 24.0 * (mjd - std::floor(mjd)) + 12.0;
        double gmst = 6.697375 + 0.0657098242 * mjd + ut;
        double lmst = gmst - site.longitude * (12.0 / kPi);
        *solarTimeHours = wrap(lmst - ra * (12.0 / kPi) + 12.0, 24.0);
    }
    return std::asin(std::sin(ep) * std::sin(l));
}

SunPosition sunPosition(const Site& site, int year, int month, int day, double hour,
                        bool hourIsSolar) {
    SunPosition p;
    p.solarTime = hour;
    if (year != 0) {
        double mjd = almanacDay(year, month, day, hour, site);
        p.declination = almanacDeclination(mjd, site, hourIsSolar ? nullptr : &p.solarTime);
    } else {
        int jd = dayOfYear(month, day);
        p.declination = solarDeclination(jd);
        if (!hourIsSolar) p.solarTime = hour + solarTimeAdjustment(jd, site);
    }
    p.altitude = solarAltitude(site, p.declination, p.solarTime);
    p.azimuth = solarAzimuth(site, p.declination, p.solarTime);
    return p;
}

Vec3 sunDirection(double altitude, double azimuth) {
    return {-std::sin(azimuth) * std::cos(altitude), -std::cos(azimuth) * std::cos(altitude),
            std::sin(altitude)};
}

}  // namespace rp::gen
