#include "util/header.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace rp {

TEST(Header, RoundTripAndValues) {
    Header h;
    h.lines = {"mkpmap -apg x.pm 50k scene.oct", "NumPhotons\t= 3",
               "FORMAT=Radiance_Global_kdT_Photon_Map", "VERSION=3.1k"};
    std::stringstream ss;
    writeHeader(ss, h);
    ss << "BINARY";
    Header back = readHeader(ss, "x.pm");
    EXPECT_EQ(back.lines, h.lines);
    EXPECT_EQ(back.format(), "Radiance_Global_kdT_Photon_Map");
    EXPECT_EQ(back.value("VERSION"), "3.1k");
    std::string rest;
    ss >> rest;
    EXPECT_EQ(rest, "BINARY");
}

TEST(Header, MissingMagicIsInputError) {
    std::stringstream ss("void plastic red\n0\n0\n5 1 0 0 0 0\n");
    try {
        readHeader(ss, "red.rad");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "red.rad: not a RADIANCE file (no #?RADIANCE header)");
    }
    std::stringstream ss2("void plastic red\n");
    Header h;
    EXPECT_FALSE(tryReadHeader(ss2, h));
}

TEST(Header, TruncatedHeaderIsInputError) {
    std::stringstream ss("#?RADIANCE\nFORMAT=x\n");
    EXPECT_THROW(readHeader(ss, "t.pm"), InputError);
}

TEST(Header, CommandLineQuotesAsRadiancePrintargs) {
    // RADIANCE compat (fputword): examples checked against RADIANCE 5.4's rcontrib header.
    const char* argv[] = {"rtrace", "-ap",       "my map.pm", "50",
                          "it's",   "say\"hi\"", "a'",        "tab\there"};
    EXPECT_EQ(commandLine(8, argv),
              "rtrace -ap \"my map.pm\" 50 \"it's\" 'say\"hi\"' a' \"tab\there\"");
}

}  // namespace rp
