// Tests for the Perez model and gendaylit: clearness/brightness definitions, coefficient
// bins, the diffuse normalisation against a fine numerical integration, sun radiance,
// ground brightness, output layout (perezlum.cal argument order), error skies, bad input.
#include "gen/gendaylit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gen/cie_sky.h"
#include "gen/perez.h"
#include "util/error.h"

namespace rp::gen {
namespace {

constexpr double kDeg = kPi / 180;

// Horizontal irradiance of the Perez sky (normalisation times relative luminance),
// midpoint rule on a fine grid.
double integratePerez(const GendaylitSky& s) {
    double sum = 0;
    int nT = 180, nP = 360;
    double dT = 0.5 * kPi / nT, dP = 2 * kPi / nP;
    for (int i = 0; i < nT; ++i) {
        double th = (i + 0.5) * dT;
        for (int j = 0; j < nP; ++j) {
            double ph = (j + 0.5) * dP;
            Vec3 d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
            double gamma = std::acos(std::clamp(dot(d, s.sunDir), -1.0, 1.0));
            sum += perezRelativeLuminance(s.coeffs, th, gamma) * std::cos(th) * std::sin(th);
        }
    }
    return s.diffuseNormalisation * sum * dT * dP;
}

TEST(Perez, ClearnessBrightnessAndBins) {
    // epsilon = ((Ed + Ei)/Ed + 1.041 Z^3) / (1 + 1.041 Z^3), Delta = Ed m / (E0 Esc).
    double z = 30, Z = 30 * kDeg;
    double k = 1.041 * Z * Z * Z;
    EXPECT_NEAR(perezClearness(100, 700, z), (8 + k) / (1 + k), 1e-12);
    double m = 1 / (std::cos(Z) + 0.15 * std::pow(93.885 - z, -1.253));
    EXPECT_NEAR(airMass(z), m, 1e-12);
    EXPECT_NEAR(perezBrightness(100, z, 1), 100 * m / (1367 * eccentricity(1)), 1e-12);
    EXPECT_NEAR(eccentricity(1), 1.00011 + 0.034221 + 0.000719, 1e-12);
    // Inverse relations.
    double delta = perezBrightness(100, z, 80), eps = perezClearness(100, 700, z);
    EXPECT_NEAR(diffuseFromBrightness(delta, z, 80), 100, 1e-9);
    EXPECT_NEAR(directFromClearness(eps, delta, z, 80), 700, 1e-9);
    EXPECT_EQ(perezBin(1.0), 0);
    EXPECT_EQ(perezBin(1.064), 0);
    EXPECT_EQ(perezBin(1.065), 1);
    EXPECT_EQ(perezBin(2.81), 5);
    EXPECT_EQ(perezBin(6.21), 7);
    // RADIANCE compat: gendaylit bins a float epsilon, so float(2.8) < 2.8 falls below.
    EXPECT_EQ(perezBin(2.8), 4);
    EXPECT_EQ(perezBin(12), 7);
    // Perez 1993 Table 1, bin 8: a = -1.0500 + 0.0289 Z + Delta (0.4260 + 0.3590 Z).
    auto c = perezCoefficients(0.5, 8, 0.2);
    EXPECT_NEAR(c[0], -1.05 + 0.0289 * 0.5 + 0.2 * (0.426 + 0.359 * 0.5), 1e-6);
    // Overcast bin: c = exp((Delta (2.8 + .6004 Z))^1.2375) - 1.
    c = perezCoefficients(0.5, 1.0, 0.3);
    EXPECT_NEAR(c[2], std::exp(std::pow(0.3 * (2.8 + 0.6004 * 0.5), 1.2375)) - 1.0, 1e-6);
    // Relative luminance at the zenith with the sun at the zenith: (1 + a e^b)(1 + c + e).
    EXPECT_NEAR(perezRelativeLuminance(c, 0, 0), (1 + c[0] * std::exp(c[1])) * (1 + c[2] + c[4]),
                1e-12);
}

TEST(Gendaylit, DiffuseNormalisationReproducesDiffuseIrradiance) {
    // -O 1 (solar watts): the sky integrates to the diffuse horizontal irradiance given.
    // gendaylit normalises with 145 equal-weight Tregenza patches, so allow 5 %.
    for (const char* alt : {"15", "40", "65"})
        for (auto [dir, dif] : {std::pair{"800", "100"}, {"300", "250"}, {"0", "200"}}) {
            GendaylitSky s = computeGendaylit(
                parseGendaylitArgs({"gendaylit", "-ang", alt, "20", "-W", dir, dif, "-O", "1"}));
            ASSERT_FALSE(s.errorSky) << alt << " " << dir;
            EXPECT_NEAR(integratePerez(s) / std::stod(dif), 1.0, 0.05) << alt << " " << dir;
            // Sun: direct normal irradiance spread over the 0.533 degree disc.
            double omega = 2 * kPi * (1 - std::cos(0.2665 * kDeg));
            EXPECT_NEAR(s.solarRadiance * omega, std::stod(dir), 1e-9);
        }
}

TEST(Gendaylit, VisibleOutputUsesEfficacies) {
    GendaylitSky s = computeGendaylit(parseGendaylitArgs(
        {"gendaylit", "6", "21", "12", "-a", "47", "-o", "-8", "-m", "-15", "-W", "800", "120"}));
    ASSERT_FALSE(s.errorSky);
    EXPECT_NEAR(s.water, 2.0, 1e-6);  // default dew point gives 2 cm precipitable water
    double eDif = diffuseEfficacy(s.epsilon, s.delta, 90 - s.altitude / kDeg, s.water);
    EXPECT_NEAR(s.diffuseIlluminance, 120 * eDif, 1e-9);
    EXPECT_NEAR(integratePerez(s) * 179, s.diffuseIlluminance, 0.05 * s.diffuseIlluminance);
    // Ground: reflectance * (zenith * clear-sky normalisation + sun) for epsilon >= 6.
    ASSERT_GE(s.epsilon, 6);
    double norm = skyNormalisationFit(s.altitude, false) / clearSkyF2(s.altitude) / kPi;
    double ground = s.zenithBrightness * norm + 6.8e-5 / kPi * s.solarRadiance * s.sunDir.z;
    EXPECT_NEAR(s.groundBrightness, 0.2 * ground, 1e-9 * ground);
}

TEST(Gendaylit, OutputLayout) {
    std::vector<std::string> warnings;
    std::string out = gendaylit({"gendaylit", "-ang", "40", "10", "-W", "600", "150"}, &warnings);
    EXPECT_TRUE(warnings.empty());
    std::istringstream in(out);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    ASSERT_EQ(lines.size(), 19u);
    EXPECT_EQ(lines[0], "# gendaylit -ang 40 10 -W 600 150");
    EXPECT_EQ(lines[1], "# Local solar time: 0.00");
    EXPECT_EQ(lines[2], "# Solar altitude and azimuth: 40.0 10.0");
    EXPECT_EQ(lines[3].substr(0, 58), "# epsilon, delta, atmospheric precipitable water content :");
    EXPECT_EQ(lines[5], "void light solar");
    EXPECT_EQ(lines[10], "solar source sun");
    EXPECT_EQ(lines[13].substr(lines[13].size() - 9), " 0.533000");
    EXPECT_EQ(lines[15], "void brightfunc skyfunc");
    EXPECT_EQ(lines[16], "2 skybright perezlum.cal");
    EXPECT_EQ(lines[17], "0");
    std::istringstream reals(out.substr(out.rfind("\n10 ") + 1));
    std::vector<double> v;
    for (double x; reals >> x;) v.push_back(x);
    ASSERT_EQ(v.size(), 11u);  // count + 10 reals
    EXPECT_EQ(v[0], 10);
    EXPECT_NEAR(v[8], -std::sin(10 * kDeg) * std::cos(40 * kDeg), 1e-6);
    EXPECT_NEAR(v[10], std::sin(40 * kDeg), 1e-6);
    // -s: no sun source.
    out = gendaylit({"gendaylit", "-ang", "40", "10", "-W", "600", "150", "-s"}, nullptr);
    EXPECT_EQ(out.find("solar source sun"), std::string::npos);
}

TEST(Gendaylit, ErrorSkies) {
    std::vector<std::string> warnings;
    std::string out = gendaylit({"gendaylit", "1", "1", "2", "-W", "0", "0"}, &warnings);
    EXPECT_NE(out.find("\n10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  "), std::string::npos);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("sun altitude below zero"), std::string::npos);
    // Daytime but no light at all, and a direct beam brighter than the sun.
    EXPECT_TRUE(
        computeGendaylit(parseGendaylitArgs({"gendaylit", "-ang", "40", "0", "-W", "0", "0"}))
            .errorSky);
    EXPECT_TRUE(
        computeGendaylit(parseGendaylitArgs({"gendaylit", "-ang", "40", "0", "-W", "1400", "50"}))
            .errorSky);
    // -w silences warnings.
    warnings.clear();
    gendaylit({"gendaylit", "1", "1", "2", "-W", "0", "0", "-w"}, &warnings);
    EXPECT_TRUE(warnings.empty());
}

TEST(Gendaylit, InputVariantsAgree) {
    // -G direct horizontal = -W direct normal * sin(alt).
    GendaylitSky w =
        computeGendaylit(parseGendaylitArgs({"gendaylit", "-ang", "30", "0", "-W", "500", "100"}));
    GendaylitSky g =
        computeGendaylit(parseGendaylitArgs({"gendaylit", "-ang", "30", "0", "-G", "250", "100"}));
    EXPECT_NEAR(g.epsilon, w.epsilon, 1e-9);
    EXPECT_NEAR(g.diffuseNormalisation, w.diffuseNormalisation, 1e-9);
    // -P with W's epsilon and delta gives W's irradiances back.
    GendaylitSky p =
        computeGendaylit(parseGendaylitArgs({"gendaylit", "-ang", "30", "0", "-P",
                                             std::to_string(w.epsilon), std::to_string(w.delta)}));
    EXPECT_NEAR(p.diffuseIrradiance, 100, 0.01);
    EXPECT_NEAR(p.directIrradiance, 500, 0.1);
    // -L with W's illuminances iterates back to (nearly) W's irradiances.
    GendaylitSky l = computeGendaylit(parseGendaylitArgs(
        {"gendaylit", "-ang", "30", "0", "-L", std::to_string(w.directIlluminance),
         std::to_string(w.diffuseIlluminance), "-O", "1"}));
    EXPECT_NEAR(l.diffuseIrradiance, 100, 1.0);
    EXPECT_NEAR(l.directIrradiance, 500, 5.0);
}

TEST(Gendaylit, BadInput) {
    using A = std::vector<std::string>;
    auto message = [](const A& a) {
        try {
            parseGendaylitArgs(a);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(A{"gendaylit", "13", "1", "12", "-W", "1", "1"}),
              "bad month 13: expected 1..12");
    EXPECT_EQ(message(A{"gendaylit", "4", "31", "12", "-W", "1", "1"}),
              "bad day 31: month 4 has days 1..30");
    EXPECT_EQ(message(A{"gendaylit", "4", "3", "24", "-W", "1", "1"}),
              "bad hour '24': expected 0 <= hour < 24");
    EXPECT_EQ(message(A{"gendaylit", "4", "3", "12"}),
              "no sky measurements: give -W, -G, -L, -P or -E");
    EXPECT_EQ(message(A{"gendaylit", "4", "3", "12", "-W", "1"}), "option -W needs two values");
    EXPECT_EQ(message(A{"gendaylit", "4", "3", "12", "-W", "1", "1", "-O", "3"}).substr(0, 6),
              "-O mus");
    EXPECT_EQ(message(A{"gendaylit", "4", "3", "12", "-W", "1", "1", "-k"}), "unknown option '-k'");
}

}  // namespace
}  // namespace rp::gen
