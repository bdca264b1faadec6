// genssky's options and bad input; its output is checked end to end (against RADIANCE
// 6.1a's layout, its sun and overcast sky, and the renderer's illuminances) by
// tests/golden/genssky.sh, and the atmosphere itself by atmosphere_test.cpp.
#include "gen/genssky.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace rp::gen {
namespace {

constexpr double kDeg = kPi / 180;

std::vector<std::string> words(std::initializer_list<const char*> w) {
    return {w.begin(), w.end()};
}

TEST(Genssky, ParsesRadiance6sOptions) {
    const GensskyOptions o = parseGensskyArgs(words(
        {"genssky", "3",    "2",   "15.25", "-a",   "42", "-o",   "108", "-m", "110", "-n",
         "8",       "-c",   "0.3", "-d",    "0.2",  "-g", "0.3",  "-r",  "32", "-f",  "sky",
         "-p",      "dir/", "-L",  "80000", "8000", "-y", "2024", "-i",  "5",  "-l",  "my.dat"}));
    EXPECT_EQ(o.month, 3);
    EXPECT_EQ(o.day, 2);
    EXPECT_DOUBLE_EQ(o.hour, 15.25);
    EXPECT_NEAR(o.site.latitude, 42 * kDeg, 1e-12);
    EXPECT_NEAR(o.site.longitude, 108 * kDeg, 1e-12);
    EXPECT_NEAR(o.site.meridian, 110 * kDeg, 1e-12);
    EXPECT_EQ(o.threads, 8);
    EXPECT_DOUBLE_EQ(o.cloudCover, 0.3);
    EXPECT_DOUBLE_EQ(o.aerosolDepth, 0.2);
    EXPECT_DOUBLE_EQ(o.groundReflectance, 0.3);
    EXPECT_EQ(o.resolution, 32);
    EXPECT_EQ(o.prefix, "sky");
    EXPECT_EQ(o.dataDir, "dir");  // a trailing separator dropped, as RADIANCE
    EXPECT_DOUBLE_EQ(o.directNormal, 80000);
    EXPECT_DOUBLE_EQ(o.diffuseHorizontal, 8000);
    EXPECT_EQ(o.year, 2024);
    EXPECT_EQ(o.orders, 5);
    EXPECT_EQ(o.mieFile, "my.dat");
}

TEST(Genssky, TimeZoneOnTheHourWinsOverMeridian) {
    const GensskyOptions o =
        parseGensskyArgs(words({"genssky", "6", "21", "12:30CET", "-m", "110"}));
    EXPECT_DOUBLE_EQ(o.hour, 12.5);
    EXPECT_NEAR(o.site.meridian, -15 * kDeg, 1e-12);
}

TEST(Genssky, DefaultsAsRadiance6) {
    const GensskyOptions o = parseGensskyArgs(words({"genssky", "-defaults"}));
    EXPECT_TRUE(o.printDefaults);
    EXPECT_EQ(gensskyDefaults(o),
              "-i 4\t\t\t\t#scattering order\n"
              "-g 0.200000\t\t\t#ground reflectance\n"
              "-c 0.000000\t\t\t#cloud cover\n"
              "-r 64\t\t\t\t#image resolution\n"
              "-d 0.115000\t\t\t#broadband aerosol optical depth\n"
              "-f out\t\t\t\t#output name (-f)\n"
              "-p .\t\t\t\t#atmos data directory\n");
}

TEST(Genssky, BadInput) {
    auto bad = [](std::initializer_list<const char*> w) {
        EXPECT_THROW(parseGensskyArgs(words(w)), InputError);
    };
    bad({"genssky", "3", "21"});                       // no hour
    bad({"genssky", "13", "21", "12"});                // month
    bad({"genssky", "2", "30", "12"});                 // day
    bad({"genssky", "3", "21", "25"});                 // hour
    bad({"genssky", "3", "21", "12XYZ"});              // time zone
    bad({"genssky", "3", "21", "12", "-q"});           // unknown option
    bad({"genssky", "3", "21", "12", "-c", "1.5"});    // cloud cover
    bad({"genssky", "3", "21", "12", "-g", "-0.1"});   // reflectance
    bad({"genssky", "3", "21", "12", "-i", "1"});      // one scattering order
    bad({"genssky", "3", "21", "12", "-r", "1"});      // resolution
    bad({"genssky", "3", "21", "12", "-L", "80000"});  // -L needs two values
    bad({"genssky", "3", "21", "12", "-a", "north"});  // not a number
    // An aerosol file that is nowhere on the search path.
    EXPECT_THROW(genssky(words({"genssky", "3", "21", "12", "-l", "no_such_mie.dat"}),
                         {"/nonexistent"}, nullptr),
                 InputError);
}

}  // namespace
}  // namespace rp::gen
