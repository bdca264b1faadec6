// Perez sky model tables and formulas (see perez.h for the papers). The coefficient
// table is Perez et al. 1993, Table 1: per clearness bin, for each of a b c d e the four
// numbers x1..x4 of  x1 + x2 Z + Delta (x3 + x4 Z)  (bin 1 uses special forms for c, d).
#include "gen/perez.h"

#include <cmath>

#include "util/error.h"

namespace rp::gen {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Kept as the paper prints them; gendaylit reads them rounded to single precision (so its
// printed coefficients agree to the last digit), gendaymtx as they are.
constexpr double kLuminanceCoeffs[8][5][4] = {
    {{1.3525, -0.2576, -0.2690, -1.4366},
     {-0.7670, 0.0007, 1.2734, -0.1233},
     {2.8000, 0.6004, 1.2375, 1.000},
     {1.8734, 0.6297, 0.9738, 0.2809},
     {0.0356, -0.1246, -0.5718, 0.9938}},
    {{-1.2219, -0.7730, 1.4148, 1.1016},
     {-0.2054, 0.0367, -3.9128, 0.9156},
     {6.9750, 0.1774, 6.4477, -0.1239},
     {-1.5798, -0.5081, -1.7812, 0.1080},
     {0.2624, 0.0672, -0.2190, -0.4285}},
    {{-1.1000, -0.2515, 0.8952, 0.0156},
     {0.2782, -0.1812, -4.5000, 1.1766},
     {24.7219, -13.0812, -37.7000, 34.8438},
     {-5.0000, 1.5218, 3.9229, -2.6204},
     {-0.0156, 0.1597, 0.4199, -0.5562}},
    {{-0.5484, -0.6654, -0.2672, 0.7117},
     {0.7234, -0.6219, -5.6812, 2.6297},
     {33.3389, -18.3000, -62.2500, 52.0781},
     {-3.5000, 0.0016, 1.1477, 0.1062},
     {0.4659, -0.3296, -0.0876, -0.0329}},
    {{-0.6000, -0.3566, -2.5000, 2.3250},
     {0.2937, 0.0496, -5.6812, 1.8415},
     {21.0000, -4.7656, -21.5906, 7.2492},
     {-3.5000, -0.1554, 1.4062, 0.3988},
     {0.0032, 0.0766, -0.0656, -0.1294}},
    {{-1.0156, -0.3670, 1.0078, 1.4051},
     {0.2875, -0.5328, -3.8500, 3.3750},
     {14.0000, -0.9999, -7.1406, 7.5469},
     {-3.4000, -0.1078, -1.0750, 1.5702},
     {-0.0672, 0.4016, 0.3017, -0.4844}},
    {{-1.0000, 0.0211, 0.5025, -0.5119},
     {-0.3000, 0.1922, 0.7023, -1.6317},
     {19.0000, -5.0000, 1.2438, -1.9094},
     {-4.0000, 0.0250, 0.3844, 0.2656},
     {1.0468, -0.3788, -2.4517, 1.4656}},
    {{-1.0500, 0.0289, 0.4260, 0.3590},
     {-0.3250, 0.1156, 0.7781, 0.0025},
     {31.0625, -14.5000, -46.1148, 55.3750},
     {-7.2312, 0.4050, 13.3500, 0.6234},
     {1.5000, -0.6426, 1.8564, 0.5636}},
};

// Perez 1990 efficacy models: a + b w + c cos Z + d ln Delta (global, diffuse) and
// a + b w + c exp(5.73 Z - 5) + d Delta (direct), per clearness bin.
struct EfficacyModel {
    double a[8], b[8], c[8], d[8];
};
constexpr EfficacyModel kGlobal = {{96.63, 107.54, 98.73, 92.72, 86.73, 88.34, 78.63, 99.65},
                                   {-0.47, 0.79, 0.70, 0.56, 0.98, 1.39, 1.47, 1.86},
                                   {11.50, 1.79, 4.40, 8.36, 7.10, 6.06, 4.93, -4.46},
                                   {-9.16, -1.19, -6.95, -8.31, -10.94, -7.60, -11.37, -3.15}};
constexpr EfficacyModel kDiffuse = {{97.24, 107.22, 104.97, 102.39, 100.71, 106.42, 141.88, 152.23},
                                    {-0.46, 1.15, 2.96, 5.59, 5.94, 3.83, 1.90, 0.35},
                                    {12.00, 0.59, -5.53, -13.95, -22.75, -36.15, -53.24, -45.27},
                                    {-8.91, -3.95, -8.77, -13.90, -23.74, -28.83, -14.03, -7.98}};
constexpr EfficacyModel kDirect = {{57.20, 98.99, 109.83, 110.34, 106.36, 107.19, 105.75, 101.18},
                                   {-4.55, -3.46, -4.90, -5.84, -3.97, -1.25, 0.77, 1.58},
                                   {-2.98, -1.21, -1.71, -1.99, -1.75, -1.51, -1.26, -1.10},
                                   {117.12, 12.38, -8.81, -4.56, -6.16, -26.73, -34.44, -8.29}};

constexpr double kBinBounds[9] = {1, 1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200, 12.01};

// The efficacy models' bin: -1 outside [1, upper) (gendaylit uses 12.01 for global and
// diffuse, 12.1 for direct).
int efficacyBin(double epsilon, double upper) {
    int bin = -1;
    for (int i = 0; i < 8; ++i) {
        double hi = i == 7 ? upper : kBinBounds[i + 1];
        if (epsilon >= kBinBounds[i] && epsilon < hi) bin = i;
    }
    return bin;
}

double cubedZenith(double sunZenithDeg) {
    double z = sunZenithDeg * kDeg;
    return 1.041 * z * z * z;
}

}  // namespace

int perezBin(double epsilon) {
    float e = static_cast<float>(epsilon);  // RADIANCE compat: get_numlin takes a float
    int bin = 0;
    while (bin < 7 && e >= kBinBounds[bin + 1]) ++bin;
    return bin;
}

double eccentricity(double dayNumber) {
    double g = 2 * 3.14159265358979323846 * (dayNumber - 1) / 365;
    return 1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2 * g) +
           0.000077 * std::sin(2 * g);
}

double airMass(double z) {
    if (z > 90) z = 90;
    return 1 / (std::cos(z * kDeg) + 0.15 * std::exp(std::log(93.885 - z) * -1.253));
}

double perezBrightness(double diffuseHor, double z, double day) {
    return diffuseHor * airMass(z) / (kSolarConstantW * eccentricity(day));
}

double perezClearness(double diffuseHor, double directNormal, double z) {
    double k = cubedZenith(z);
    return ((diffuseHor + directNormal) / diffuseHor + k) / (1 + k);
}

double diffuseFromBrightness(double delta, double z, double day) {
    return delta / airMass(z) * (kSolarConstantW * eccentricity(day));
}

double directFromClearness(double epsilon, double delta, double z, double day) {
    return diffuseFromBrightness(delta, z, day) * ((epsilon - 1) * (1 + cubedZenith(z)));
}

double diffuseEfficacy(double epsilon, double delta, double z, double w) {
    int i = efficacyBin(epsilon, 12.01);
    if (i < 0) return -1;
    return kDiffuse.a[i] + kDiffuse.b[i] * w + kDiffuse.c[i] * std::cos(z * kDeg) +
           kDiffuse.d[i] * std::log(delta);
}

double directEfficacy(double epsilon, double delta, double z, double w) {
    int i = efficacyBin(epsilon, 12.1);
    if (i < 0) return -1;
    double v = kDirect.a[i] + kDirect.b[i] * w + kDirect.c[i] * std::exp(5.73 * z * kDeg - 5) +
               kDirect.d[i] * delta;
    return v < 0 ? 0 : v;
}

double globalEfficacy(double epsilon, double delta, double z, double w) {
    int i = efficacyBin(epsilon, 12.01);
    if (i < 0) return -1;
    return kGlobal.a[i] + kGlobal.b[i] * w + kGlobal.c[i] * std::cos(z * kDeg) +
           kGlobal.d[i] * std::log(delta);
}

int clearnessCategory(double epsilon) { return efficacyBin(epsilon, 12.01); }

std::array<double, 5> perezCoefficients(double Z, double epsilon, double delta) {
    return perezCoefficients(Z, epsilon, delta, perezBin(epsilon), PerezPrecision::Single);
}

std::array<double, 5> perezCoefficients(double Z, double epsilon, double delta, int bin,
                                        PerezPrecision precision) {
    RP_CHECK(bin >= 0 && bin < 8);
    if (epsilon > 1.065 && epsilon < 2.8 && delta < 0.2) delta = 0.2;
    double x[5][4];
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j) {
            double v = kLuminanceCoeffs[bin][i][j];
            x[i][j] = precision == PerezPrecision::Single ? double(static_cast<float>(v)) : v;
        }
    std::array<double, 5> c;
    for (int i = 0; i < 5; ++i) c[i] = x[i][0] + x[i][1] * Z + delta * (x[i][2] + x[i][3] * Z);
    if (bin == 0) {  // Perez 1993: c and d take exponential forms in the overcast bin
        c[2] = std::exp(std::pow(delta * (x[2][0] + x[2][1] * Z), x[2][2])) - x[2][3];
        c[3] = -std::exp(delta * (x[3][0] + x[3][1] * Z)) + x[3][2] + delta * x[3][3];
    }
    return c;
}

double perezRelativeLuminance(const std::array<double, 5>& c, double zeta, double gamma) {
    double cg = std::cos(gamma);
    return (1 + c[0] * std::exp(c[1] / std::cos(zeta))) *
           (1 + c[2] * std::exp(c[3] * gamma) + c[4] * cg * cg);
}

double perezHorizontalIntegral(const std::array<double, 5>& c, double Z) {
    // Tregenza's 145 patches: rows of patch centres at altitude 6, 18, ... 78 degrees
    // (zenith angle 84 .. 12) with 30, 30, 24, 24, 18, 12, 6 patches, plus the zenith.
    static constexpr int kRowCount[8] = {30, 30, 24, 24, 18, 12, 6, 1};
    double sum = 0;
    for (int row = 0; row < 8; ++row) {
        double theta = (84 - 12 * row) * kDeg;
        for (int k = 0; k < kRowCount[row]; ++k) {
            double phi = (360.0 / kRowCount[row]) * k * kDeg;
            double cg =
                std::cos(Z) * std::cos(theta) + std::sin(Z) * std::sin(theta) * std::cos(phi);
            double gamma = cg > 1 ? 0 : std::acos(cg);
            // RADIANCE compat: patch luminances are stored in single precision
            float lv = static_cast<float>(perezRelativeLuminance(c, theta, gamma));
            sum += lv * std::cos(theta);
        }
    }
    return sum * (2. * 3.14159265358979323846 / 145.);
}

}  // namespace rp::gen
