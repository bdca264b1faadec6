// gendaymtx's per-step sky (see gendaymtx_sky.h). Patch values are stored in single
// precision at the points where gendaymtx stores them, so the printed %.3g digits agree.
#include "gen/gendaymtx_sky.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gen/gen_text.h"
#include "gen/perez.h"
#include "gen/sun_position.h"

namespace rp::gen {

namespace {

constexpr double kWhiteEfficacy = 179.0;  // lm/W, RADIANCE WHTEFFICACY
constexpr double kSunDiameterDeg = 0.533;
constexpr double kDewPoint = 11.0;  // deg C: gendaymtx's default (gendaylit's is 10.97)
constexpr double kFtiny = 1e-6;     // RADIANCE FTINY

double toDegrees(double r) { return r * (180.0 / kPi); }

// Brightness and clearness from irradiances, with the clearness cap given.
void perezParameters(DaymtxPerez& p, double zenithDeg, int day, double clearnessCap) {
    p.brightness = perezBrightness(p.diffuseIrradiance, zenithDeg, day);
    p.clearness = perezClearness(p.diffuseIrradiance, p.directIrradiance, zenithDeg);
    if (p.clearness > clearnessCap) p.clearness = clearnessCap;
    if (p.brightness < 0.01) p.brightness = 0.01;
}

// Illuminance input: iterate irradiance <- illuminance / efficacy until both change by
// no more than 10 W/m2, at most 5 times.
void fromIlluminances(DaymtxPerez& p, double zenithDeg, int day, double water) {
    p.diffuseIrradiance = p.diffuseIlluminance * kSolarConstantW / kSolarConstantLux;
    p.directIrradiance = p.directIlluminance * kSolarConstantW / kSolarConstantLux;
    perezParameters(p, zenithDeg, day, 12.0);
    double last1 = 0.1, last2 = 0.1;
    int count = 0;
    while ((std::fabs(p.diffuseIrradiance - last1) > 10 ||
            std::fabs(p.directIrradiance - last2) > 10) &&
           count != 5) {
        last1 = p.diffuseIrradiance;
        last2 = p.directIrradiance;
        ++count;
        p.diffuseIrradiance =
            p.diffuseIlluminance / diffuseEfficacy(p.clearness, p.brightness, zenithDeg, water);
        // RADIANCE compat (gendaymtx.c CalcSkyParamFromIllum): an efficacy of 0.1 or less
        // is left in place of the irradiance (gendaylit uses 0).
        p.directIrradiance = directEfficacy(p.clearness, p.brightness, zenithDeg, water);
        if (p.directIrradiance > 0.1) p.directIrradiance = p.directIlluminance / p.directIrradiance;
        perezParameters(p, zenithDeg, day, 12.0);
    }
}

}  // namespace

double daymtxBrightness(const DaymtxColor& c) {
    return 0.265074126 * c[0] + 0.670114631 * c[1] + 0.064811243 * c[2];
}

DaymtxPerez daymtxPerez(const DaymtxStep& step, bool solarRadiance) {
    DaymtxPerez p;
    const double water = std::exp(0.07 * kDewPoint - 0.075);
    // Sun zenith within 90 (sun below the horizon) and 3 degrees (keeps the circumsolar
    // peak off the zenith patch).
    if (step.altitude <= 0)
        p.sunZenith = 90 * kDegree;
    else if (step.altitude >= 87 * kDegree)
        p.sunZenith = 3 * kDegree;
    else
        p.sunZenith = 90 * kDegree - step.altitude;
    const double zenithDeg = toDegrees(p.sunZenith);
    if (!step.photometric) {
        p.diffuseIrradiance = step.diffuse;
        p.directIrradiance = step.direct;
        perezParameters(p, zenithDeg, step.julianDate, 11.9);
        p.diffuseIlluminance =
            p.diffuseIrradiance * diffuseEfficacy(p.clearness, p.brightness, zenithDeg, water);
        p.directIlluminance =
            p.directIrradiance * directEfficacy(p.clearness, p.brightness, zenithDeg, water);
    } else {
        p.diffuseIlluminance = step.diffuse;
        p.directIlluminance = step.direct;
        fromIlluminances(p, zenithDeg, step.julianDate, water);
    }
    p.category = clearnessCategory(p.clearness);
    if (solarRadiance) {  // RADIANCE compat: -O1 scales irradiance by 179 to leave the rest
        p.diffuseIlluminance = p.diffuseIrradiance * kWhiteEfficacy;
        p.directIlluminance = p.directIrradiance * kWhiteEfficacy;
    }
    return p;
}

void computeSkyPatches(const ReinhartSky& sky, const DaymtxSkyOptions& opt, const DaymtxStep& step,
                       const DaymtxPerez& perez, float* patches) {
    const int n = sky.size();
    float ground = static_cast<float>(perez.diffuseIlluminance);
    if (step.altitude > 0)
        ground = static_cast<float>(ground + perez.directIlluminance * std::sin(step.altitude));
    ground = static_cast<float>(ground * (1.0 / kPi / kWhiteEfficacy));
    for (int c = 0; c < 3; ++c) patches[c] = ground * opt.groundReflectance[c];
    if (daymtxBrightness(opt.skyColor) <= 1e-4) {
        std::memset(patches + 3, 0, sizeof(float) * 3 * (n - 1));
        return;
    }
    const double Z = perez.sunZenith;
    const auto coeffs = perezCoefficients(Z, perez.clearness, perez.brightness, perez.category,
                                          PerezPrecision::Double);
    // Relative luminance at each patch centre; its horizontal integral over the patches
    // (RADIANCE's table sine for the cosine factor) normalises it.
    double horizontal = 0;
    for (int i = 1; i < n; ++i) {
        double azimuthDiff = std::fabs(double(sky.azimuth[i]) - step.azimuth);
        double zeta = kPi * 0.5 - sky.altitude[i];
        double gamma = std::acos(std::cos(Z) * std::cos(zeta) +
                                 std::sin(Z) * std::sin(zeta) * std::cos(azimuthDiff));
        float v = static_cast<float>(perezRelativeLuminance(coeffs, zeta, gamma));
        if (v < 0) v = 0;
        patches[3 * i] = patches[3 * i + 1] = patches[3 * i + 2] = v;
        horizontal += patches[3 * i + 1] * tableSin(sky.altitude[i]) * sky.solidAngle[i];
    }
    if (horizontal <= kFtiny) {  // no sky at all: make it uniform
        for (int i = 3; i < 3 * n; ++i) patches[i] = 1;
        horizontal = kPi;
    }
    const double scale = perez.diffuseIlluminance / horizontal * (1.0 / kWhiteEfficacy);
    for (int i = 1; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            float& v = patches[3 * i + c];
            v = static_cast<float>(v * scale);
            v *= opt.skyColor[c];
        }
}

void addDirectSun(const ReinhartSky& sky, const DaymtxSkyOptions& opt, const DaymtxStep& step,
                  double directIlluminance, float* patches) {
    if (directIlluminance <= 1e-4 || daymtxBrightness(opt.sunColor) <= 1e-4) return;
    constexpr int kMaxSunPatches = 4;
    const int count = std::clamp(opt.sunPatches, 1, kMaxSunPatches);
    double nearCos[kMaxSunPatches];
    int nearPatch[kMaxSunPatches] = {};
    for (double& c : nearCos) c = -1;
    const Vec3 sun = skyVector(step.altitude, step.azimuth);
    for (int p = 1; p < sky.size(); ++p) {
        double d = dot(sky.direction(p), sun);
        for (int i = 0; i < count; ++i)
            if (d > nearCos[i]) {  // keep the list sorted, nearest first
                for (int j = count - 1; j > i; --j) {
                    nearCos[j] = nearCos[j - 1];
                    nearPatch[j] = nearPatch[j - 1];
                }
                nearCos[i] = d;
                nearPatch[i] = p;
                break;
            }
    }
    // RADIANCE compat (gendaymtx.c AddDirect): weights summed from the farthest patch.
    double weight[kMaxSunPatches], total = 0;
    for (int i = count; i--;) total += weight[i] = 1.0 / (1.002 - nearCos[i]);
    for (int i = count; i--;) {
        const int p = nearPatch[i];
        float add = static_cast<float>(weight[i] * directIlluminance / (kWhiteEfficacy * total));
        add = static_cast<float>(add / (opt.fixedSunSolidAngle > 0 ? opt.fixedSunSolidAngle
                                                                   : double(sky.solidAngle[p])));
        for (int c = 0; c < 3; ++c) patches[3 * p + c] += add * opt.sunColor[c];
    }
}

std::string daymtxSunText(int minute, bool lit, double directIlluminance, const DaymtxStep& step,
                          const DaymtxColor& sunColor) {
    const double radius = kSunDiameterDeg / 2 * kDegree;
    const double radiance = lit ? directIlluminance / (kWhiteEfficacy * kPi * radius * radius) : 0;
    const Vec3 d = skyVector(step.altitude, step.azimuth);
    std::string s = cformat("\nvoid light solar%d\n0\n0\n", minute);
    s += cformat("3 %.3e %.3e %.3e\n", radiance * sunColor[0], radiance * sunColor[1],
                 radiance * sunColor[2]);
    s += cformat("\nsolar%d source sun%d\n0\n0\n", minute, minute);
    s += cformat("4 %.6f %.6f %.6f %.4f\n", d.x, d.y, d.z, kSunDiameterDeg);
    return s;
}

}  // namespace rp::gen
