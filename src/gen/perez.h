// The Perez all-weather sky model as RADIANCE's gendaylit uses it: sky clearness and
// brightness from irradiances (Perez et al. 1990), luminous efficacy models (Perez et
// al. 1990, Solar Energy 44(5):271-289), the five luminance coefficients a..e and the
// relative luminance (Perez, Seals & Michalsky 1993, Solar Energy 50(3):235-245), and the
// 145-patch normalisation integral. Parsing and output are in gendaylit.h.
#pragma once

#include <array>

namespace rp::gen {

constexpr double kSolarConstantW = 1367;      // W/m2
constexpr double kSolarConstantLux = 127500;  // lux

// Perez clearness bins: epsilon in [1, 1.065), [1.065, 1.23), ... [6.2, inf): 0..7.
int perezBin(double epsilon);

// Eccentricity correction (R0/R)^2 for a day of the year (Spencer 1971).
double eccentricity(double dayNumber);

// Kasten's relative air mass for a solar zenith angle in degrees (limited to 90).
double airMass(double sunZenithDeg);

// Perez sky brightness Delta and clearness epsilon from diffuse horizontal and direct
// normal irradiance (W/m2), and the inverse relations.
double perezBrightness(double diffuseHor, double sunZenithDeg, double dayNumber);
double perezClearness(double diffuseHor, double directNormal, double sunZenithDeg);
double diffuseFromBrightness(double delta, double sunZenithDeg, double dayNumber);
double directFromClearness(double epsilon, double delta, double sunZenithDeg, double dayNumber);

// Luminous efficacies (lm/W) for precipitable water w (cm): diffuse horizontal and
// direct normal (clamped at 0), and global horizontal. Return -1 when epsilon lies past
// the last bin's bound (gendaylit then prints its "error sky").
double diffuseEfficacy(double epsilon, double delta, double sunZenithDeg, double water);
double directEfficacy(double epsilon, double delta, double sunZenithDeg, double water);
double globalEfficacy(double epsilon, double delta, double sunZenithDeg, double water);

// The clearness category of the efficacy models and of gendaymtx: 0..7 for epsilon in
// [1, 12.01), -1 outside (compared in double precision, unlike perezBin).
int clearnessCategory(double epsilon);

// How the coefficient table is read: gendaylit keeps it in single precision, gendaymtx
// in double precision.
enum class PerezPrecision { Single, Double };

// Coefficients a..e for sun zenith Z (radians). RADIANCE compat: in bins 2..4 (1.065 <
// epsilon < 2.8) Delta below 0.2 is raised to 0.2 ("correction du modele de Perez").
// This form is gendaylit's: the bin from perezBin, the table in single precision.
std::array<double, 5> perezCoefficients(double sunZenith, double epsilon, double delta);
// The same with the bin (0..7) and the table's precision given (gendaymtx passes
// clearnessCategory and Double).
std::array<double, 5> perezCoefficients(double sunZenith, double epsilon, double delta, int bin,
                                        PerezPrecision precision);

// Relative luminance (1 + a exp(b / cos zeta)) (1 + c exp(d gamma) + e cos^2 gamma) for a
// sky point at zenith angle zeta and angle gamma from the sun.
double perezRelativeLuminance(const std::array<double, 5>& c, double zeta, double gamma);

// gendaylit's integ_lv(): sum over the 145 Tregenza patch centres of the relative
// luminance times cos(theta), times 2 pi / 145 (equal patch weights).
double perezHorizontalIntegral(const std::array<double, 5>& c, double sunZenith);

}  // namespace rp::gen
