// Tests for gendaymtx: the Reinhart patches (counts, solid angles, order), the table
// cosine, the step's Perez parameters, the sky normalisation and the sun spreading
// (energy kept), option order quirks and errors, and RADIANCE's own test case end to end.
#include "gen/gendaymtx.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "gen/perez.h"
#include "gen/sun_position.h"
#include "util/error.h"

namespace rp::gen {
namespace {

TEST(ReinhartSky, CountsSolidAnglesAndOrder) {
    for (int m : {1, 2, 4}) {
        ReinhartSky sky = makeReinhartSky(m);
        ASSERT_EQ(sky.size(), 144 * m * m + 2);
        // The sky patches tile the hemisphere (single-precision solid angles).
        double sum = 0;
        for (int p = 1; p < sky.size(); ++p) sum += sky.solidAngle[p];
        EXPECT_NEAR(sum, 2 * kPi, 1e-5) << "m = " << m;
        EXPECT_FLOAT_EQ(sky.altitude[0], -kPi / 2);  // ground first
        EXPECT_FLOAT_EQ(sky.altitude[sky.size() - 1], kPi / 2);
    }
    // Tregenza: the first row has 30 patches from north (azimuth 0) at 6 degrees altitude
    // (half a row of 12 degrees less the zenith's half row: 90 / 7.5 / 2).
    ReinhartSky t = makeReinhartSky(1);
    EXPECT_NEAR(t.altitude[1], 6 * kDegree, 1e-6);
    EXPECT_EQ(t.azimuth[1], 0.0f);
    EXPECT_NEAR(t.azimuth[2], 12 * kDegree, 1e-6);
    EXPECT_NEAR(t.altitude[31], 18 * kDegree, 1e-6);
    Vec3 north = t.direction(1);
    EXPECT_NEAR(north.x, 0, 1e-7);
    EXPECT_GT(north.y, 0.99);
    EXPECT_GT(t.direction(2).x, 0);  // the second patch lies towards +x
}

TEST(ReinhartSky, TableCosine) {
    // Nearest of 1024 entries per quarter turn: off by at most half a step's slope.
    for (double x = -7; x < 7; x += 0.01237)
        EXPECT_NEAR(tableCos(x), std::cos(x), std::sin(kPi / 4096) + 1e-12) << x;
    EXPECT_EQ(tableCos(0), 1.0);
    EXPECT_EQ(tableSin(kPi / 2), 1.0);
    EXPECT_EQ(tableCos(kPi), -1.0);
}

DaymtxStep noonStep(double direct, double diffuse) {
    DaymtxStep s;
    s.altitude = 50 * kDegree;
    s.azimuth = kPi;  // south
    s.julianDate = 172;
    s.direct = direct;
    s.diffuse = diffuse;
    return s;
}

TEST(GendaymtxSky, PerezParameters) {
    DaymtxPerez p = daymtxPerez(noonStep(700, 100), false);
    EXPECT_NEAR(p.sunZenith, 40 * kDegree, 1e-12);
    EXPECT_NEAR(p.clearness, perezClearness(100, 700, 40), 1e-9);
    EXPECT_NEAR(p.brightness, perezBrightness(100, 40, 172), 1e-12);
    EXPECT_EQ(p.category, clearnessCategory(p.clearness));
    const double water = std::exp(0.07 * 11 - 0.075);  // gendaymtx's dew point: 11 C
    EXPECT_NEAR(p.diffuseIlluminance, 100 * diffuseEfficacy(p.clearness, p.brightness, 40, water),
                1e-6);
    // No diffuse light: clearness capped at 11.9, brightness raised to 0.01.
    DaymtxPerez bare = daymtxPerez(noonStep(500, 0), false);
    EXPECT_EQ(bare.clearness, 11.9);
    EXPECT_EQ(bare.brightness, 0.01);
    // -O1: the illuminances become irradiance x 179.
    DaymtxPerez solar = daymtxPerez(noonStep(700, 100), true);
    EXPECT_DOUBLE_EQ(solar.directIlluminance, 700 * 179.0);
    // Illuminance input recovers irradiances near the ones that make those illuminances.
    DaymtxStep lux = noonStep(p.directIlluminance, p.diffuseIlluminance);
    lux.photometric = true;
    DaymtxPerez back = daymtxPerez(lux, false);
    EXPECT_NEAR(back.diffuseIrradiance, 100, 10);
    EXPECT_NEAR(back.directIrradiance, 700, 10);
}

TEST(GendaymtxSky, PatchesKeepTheDiffuseAndGroundLight) {
    ReinhartSky sky = makeReinhartSky(2);
    DaymtxSkyOptions opt;
    opt.skyColor = {1, 1, 1};
    DaymtxStep step = noonStep(700, 100);
    DaymtxPerez p = daymtxPerez(step, false);
    std::vector<float> v(3 * sky.size());
    computeSkyPatches(sky, opt, step, p, v.data());
    // The normalisation: horizontal illuminance over the patches is the diffuse one.
    double horizontal = 0;
    for (int i = 1; i < sky.size(); ++i)
        horizontal += v[3 * i + 1] * tableSin(sky.altitude[i]) * sky.solidAngle[i];
    EXPECT_NEAR(horizontal * 179, p.diffuseIlluminance, 1e-5 * p.diffuseIlluminance);
    // Ground: global horizontal / (pi 179), times the 20 % reflectance.
    double global = p.diffuseIlluminance + p.directIlluminance * std::sin(step.altitude);
    EXPECT_NEAR(v[0], 0.2 * global / kPi / 179, 1e-5 * v[0]);
    // The sun adds dir / 179 of irradiance (x solid angle) to the patches near it.
    std::vector<float> withSun = v;
    addDirectSun(sky, opt, step, p.directIlluminance, withSun.data());
    double added = 0;
    int touched = 0;
    for (int i = 1; i < sky.size(); ++i) {
        double d = withSun[3 * i] - v[3 * i];
        if (d != 0) ++touched;
        added += d * sky.solidAngle[i];
    }
    EXPECT_EQ(touched, 4);
    EXPECT_NEAR(added * 179, p.directIlluminance, 1e-5 * p.directIlluminance);
    // -s: no sun at all.
    DaymtxSkyOptions noSun = opt;
    noSun.sunColor = {0, 0, 0};
    std::vector<float> dark = v;
    addDirectSun(sky, noSun, step, p.directIlluminance, dark.data());
    EXPECT_EQ(dark, v);
}

TEST(GendaymtxSky, FivePhaseSunGoesToOnePatch) {
    ReinhartSky sky = makeReinhartSky(1);
    DaymtxSkyOptions opt;
    opt.sunPatches = 1;
    double r = kPi / 360 * 0.533;
    opt.fixedSunSolidAngle = r * r * kPi;
    std::vector<float> v(3 * sky.size(), 0.0f);
    DaymtxStep step = noonStep(700, 100);
    addDirectSun(sky, opt, step, 1000, v.data());
    int touched = 0;
    for (int i = 0; i < 3 * sky.size(); i += 3)
        if (v[i] != 0) {
            ++touched;
            const double want = 1000 / 179.0 / opt.fixedSunSolidAngle;
            EXPECT_NEAR(v[i], want, 1e-6 * want);  // two single-precision roundings
        }
    EXPECT_EQ(touched, 1);
}

TEST(GendaymtxSky, SunText) {
    DaymtxStep step = noonStep(700, 100);
    std::string s = daymtxSunText(1234, false, 5e4, step, {1, 1, 1});
    EXPECT_EQ(s.substr(0, 48), "\nvoid light solar1234\n0\n0\n3 0.000e+00 0.000e+00 ");
    EXPECT_NE(s.find("\nsolar1234 source sun1234\n0\n0\n4 0.000000 -0.642788 0.766044 0.5330\n"),
              std::string::npos)
        << s;
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string s; in >> s;) w.push_back(s);
    return w;
}

TEST(GendaymtxOptions, OrderMatters) {
    GendaymtxOptions a = parseGendaymtxArgs(words("gendaymtx -d -c 1 1 1 t.wea"));
    EXPECT_EQ(a.sky.skyColor, (DaymtxColor{1, 1, 1}));  // the sky is back
    EXPECT_EQ(a.sky.groundReflectance, (DaymtxColor{0, 0, 0}));
    EXPECT_EQ(a.input, "t.wea");
    GendaymtxOptions b = parseGendaymtxArgs(words("gendaymtx -m 4 -D -"));
    EXPECT_EQ(b.matrix, DaymtxMatrix::None);
    EXPECT_EQ(b.subdivisions, 1);
    EXPECT_TRUE(b.input.empty());
    GendaymtxOptions c = parseGendaymtxArgs(words("gendaymtx -n -A -m 2 -of -O1 -rz 30 -5 .5"));
    EXPECT_EQ(c.matrix, DaymtxMatrix::Average);
    EXPECT_EQ(c.subdivisions, 2);
    EXPECT_EQ(c.format, 'f');
    EXPECT_TRUE(c.sky.solarRadiance);
    EXPECT_EQ(c.rotationDeg, 30);
    EXPECT_EQ(c.sky.sunPatches, 1);
}

TEST(GendaymtxOptions, Errors) {
    auto message = [](const std::string& line) {
        try {
            parseGendaymtxArgs(words(line));
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("gendaymtx -q t.wea").find("unknown option '-q'"), std::string::npos);
    EXPECT_NE(message("gendaymtx -O2 t.wea").find("unknown option '-O2'"), std::string::npos);
    EXPECT_NE(message("gendaymtx -m 0 t.wea").find("-m must be 1 or more"), std::string::npos);
    EXPECT_NE(message("gendaymtx -5 0 t.wea").find("solar disk size"), std::string::npos);
    EXPECT_NE(message("gendaymtx -g .2 .2").find("needs a value"), std::string::npos);
    EXPECT_NE(message("gendaymtx -c 1 x 1 t.wea").find("sky color"), std::string::npos);
    EXPECT_NE(message("gendaymtx a.wea b.wea").find("too many arguments"), std::string::npos);
}

std::string runText(const std::string& commandLine, const std::string& tapeText) {
    std::vector<std::string> args = words(commandLine);
    GendaymtxOptions opt = parseGendaymtxArgs(args);
    std::istringstream in(tapeText);
    WeaTape tape = readWea(in, "t.wea");
    std::ostringstream out;
    GendaymtxOutputs outputs;
    outputs.matrix = &out;
    runGendaymtx(opt, tape, "t.wea", args, outputs);
    return out.str();
}

std::string readData(const std::string& file) {
    std::ifstream in(std::string(RP_SOURCE_DIR) + "/tests/data/gendaymtx/" + file,
                     std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Gendaymtx, RadianceTestCase) {
    // RADIANCE's test/gen case; expected/radtest.out is its ref/test.smx.
    std::string want = readData("expected/radtest.out");
    ASSERT_FALSE(want.empty());
    EXPECT_EQ(
        runText("gendaymtx -r 90 -m 1 -g .3 .2 .1 -c .9 .9 1.2 test.wea", readData("test.wea")),
        want);
}

TEST(Gendaymtx, LayoutAndErrors) {
    const std::string head =
        "place Here\nlatitude 40\nlongitude 100\ntime_zone 105\nsite_elevation 0\n"
        "weather_data_file_units 1\n";
    // Night only, averaged, no header: one "0 0 0" line per patch, no blank lines.
    std::string zeros;
    for (int i = 0; i < 146; ++i) zeros += "0 0 0\n";
    EXPECT_EQ(runText("gendaymtx -h -A t.wea", head + "6 21 12 0 0\n6 21 13 0 0\n"), zeros);
    std::string cols = runText("gendaymtx t.wea", head + "6 21 12 500 100\n6 21 13 500 100\n");
    EXPECT_NE(cols.find("\nNROWS=146\nNCOLS=2\nNCOMP=3\nFORMAT=ascii\n\n"), std::string::npos);
    try {
        runText("gendaymtx t.wea", head + "6 21 12 500 100\n6 21 13 -5 100\n");
        FAIL() << "negative value accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "t.wea:8: negative direct or diffuse value");
    }
    EXPECT_THROW(runText("gendaymtx -u t.wea", head + "1 1 0.5 0 0\n"), InputError);
}

}  // namespace
}  // namespace rp::gen
