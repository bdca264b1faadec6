// pcond: option switches and conflicts, the linear exposure of a picture that fits the
// display, the histogram map of one that does not, header lines and orientation, the
// human-vision functions at known points, glibc's drand48 sequence, colour matrices,
// macbethcal files and -I histograms.
#include "image/pcond.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "image/pcond_internal.h"
#include "image/picture.h"
#include "util/error.h"

namespace rp {
namespace {

using namespace pcond_detail;

PcondOptions parse(std::vector<std::string> args) { return parsePcondArgs(args); }

std::string parseError(std::vector<std::string> args) {
    try {
        parsePcondArgs(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// A grey picture whose left half is `left` and right half `right` (RGB values), or with
// `ramp` a gradient from `left` to `right` in equal ratios across the columns.
std::string greyPicture(int w, int h, float left, float right, bool ramp,
                        const std::string& extra = "") {
    Picture pic(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float v = ramp ? static_cast<float>(left * std::pow(right / left, x / (w - 1.)))
                                 : (x < w / 2 ? left : right);
            pic.at(x, y) = Pixel{v, v, v};
        }
    if (!extra.empty()) pic.header.lines.push_back(extra);
    std::ostringstream out;
    writePicture(out, pic);
    return out.str();
}

Picture condition(const std::string& bytes, std::vector<std::string> args,
                  const std::string& side = "") {
    args.push_back("in.hdr");
    const PcondOptions opt = parse(args);
    std::istringstream in(bytes), sideIn(side);
    std::ostringstream out;
    runPcond(in, "in.hdr", opt, "pcond test", out, &sideIn);
    std::istringstream back(out.str());
    return readPicture(back, "out");
}

TEST(Pcond, SwitchesToggleSetAndClearAndHumanIsFourOfThem) {
    PcondOptions o = parse({"-h", "in.hdr"});
    EXPECT_TRUE(o.acuity && o.veil && o.sensitivity && o.color);
    EXPECT_FALSE(o.centerWeight || o.linear);
    // -h toggles each flag: -a then -h leaves acuity off.
    o = parse({"-a", "-h", "in.hdr"});
    EXPECT_FALSE(o.acuity);
    EXPECT_TRUE(o.veil);
    o = parse({"-a", "-h+", "-v-", "in.hdr", "out.hdr"});
    EXPECT_TRUE(o.acuity && o.sensitivity && !o.veil);
    EXPECT_EQ(o.outputFile, "out.hdr");
    EXPECT_NE(parseError({"-hx", "in.hdr"}).find("unknown option '-hx'"), std::string::npos);
}

TEST(Pcond, ExposureIsAMultiplierOrStopsAndMeansLinear) {
    PcondOptions o = parse({"-e", "+2", "in.hdr"});
    EXPECT_DOUBLE_EQ(o.exposure, 4);
    EXPECT_TRUE(o.linear);
    EXPECT_DOUBLE_EQ(parse({"-e", "-1", "in.hdr"}).exposure, 0.5);
    EXPECT_DOUBLE_EQ(parse({"-e", "3", "in.hdr"}).exposure, 3);
    // A later -l- turns the linear response off again, as RADIANCE's flags do.
    EXPECT_FALSE(parse({"-e", "3", "-l-", "in.hdr"}).linear);
}

TEST(Pcond, ConflictingAndMissingArgumentsAreErrors) {
    EXPECT_NE(parseError({"-i", ".2", "-I", "in.hdr"}).find("only one of -i or -I"),
              std::string::npos);
    EXPECT_NE(parseError({"-p", "1", "2", "3", "4", "5", "6", "7", "8", "-f", "m.cal", "in.hdr"})
                  .find("only one of -p, -m or -f"),
              std::string::npos);
    EXPECT_NE(parseError({"-m", "w.cwp", "in.hdr"}).find("not supported"), std::string::npos);
    EXPECT_NE(parseError({"-h"}).find("expected an input picture"), std::string::npos);
    EXPECT_NE(parseError({"a.hdr", "b.hdr", "c.hdr"}).find("Usage: pcond"), std::string::npos);
    EXPECT_NE(parseError({"-u", "0", "in.hdr"}).find("'-u'"), std::string::npos);
    EXPECT_NE(parseError({"-q", "in.hdr"}).find("unknown option '-q'"), std::string::npos);
}

TEST(Pcond, PictureWithinTheDisplayRangeIsScaledLinearly) {
    // Uniform grey v: world luminance 179 v; the mean goes to the display's middle
    // brightness sqrt(100 * 1) = 10 cd/m^2, which is 0.1 of Ldmax = 100.
    const float v = toPixel(toColr(Pixel{.25f, .25f, .25f}))[0];  // as the file holds it
    const Picture out = condition(greyPicture(8, 6, v, v, false), {});
    EXPECT_NEAR(out.at(3, 2)[0], 0.1, 0.1 / 128);
    EXPECT_NEAR(out.exposure(), 0.1 / v, 1e-6);
    EXPECT_EQ(out.header.lines.end()[-2], "pcond test");  // then EXPOSURE=
}

TEST(Pcond, WideRangeIsCompressedIntoTheDisplay) {
    // Six decades evenly spread: the histogram map (no EXPOSURE=) keeps the order of the
    // columns and puts them all between the display's black and Ldmax.
    const Picture out = condition(greyPicture(128, 8, 1e-3f, 1e3f, true), {});
    EXPECT_EQ(out.header.value("EXPOSURE"), "");
    for (int x = 1; x < 128; ++x) EXPECT_LE(out.at(x - 1, 4)[1], out.at(x, 4)[1]) << x;
    EXPECT_LT(out.at(0, 4)[1], 0.02f);
    EXPECT_GT(out.at(127, 4)[1], 0.9f);
    EXPECT_LE(out.at(127, 4)[1], 1.01f);
    // Two values six decades apart need no compression (an empty histogram between
    // them): RADIANCE's pcond then scales linearly.
    EXPECT_NE(condition(greyPicture(16, 12, 1e-3f, 1e3f, false), {}).header.value("EXPOSURE"), "");
}

TEST(Pcond, HeaderDropsExposureAndPrimariesAndKeepsTheOrientation) {
    const std::string bytes = greyPicture(4, 3, 1, 1, false, "EXPOSURE=2");
    const Picture out = condition(bytes, {"-e", "1"});
    for (const std::string& l : out.header.lines) EXPECT_NE(l, "EXPOSURE=2");
    EXPECT_NEAR(out.exposure(), 2, 1e-6);  // the input's times -e's
    EXPECT_NEAR(out.at(0, 0)[0], 1, 1. / 128);

    // A picture stored in columns ("+X 3 +Y 2") comes back the same way.
    std::string cols = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+X 3 +Y 2\n";
    for (int i = 0; i < 6; ++i) cols += std::string("\x80\x80\x80\x81", 4);
    std::istringstream in(cols);
    std::ostringstream out2;
    runPcond(in, "cols", parse({"-l", "cols"}), "pcond -l cols", out2);
    std::istringstream back(out2.str());
    EXPECT_EQ(readPictureInfo(back, "out").resolution, *parseResolution("+X 3 +Y 2"));
}

TEST(Pcond, HumanVisionFunctionsAtKnownPoints) {
    // Ferwerda et al.'s threshold: constant below 1.148e-4 cd/m^2, Weber above ~80.
    EXPECT_DOUBLE_EQ(contrastThreshold(1e-5), 1.38e-3);
    EXPECT_NEAR(contrastThreshold(100), std::pow(10., 2 - 1.255), 1e-9);
    EXPECT_NEAR(contrastThreshold(0.1), std::pow(10., -1 - .395), 1e-9);
    // Acuity: 17.25 atan(0.35) + 25.72 cycles/degree at 1 cd/m^2.
    EXPECT_NEAR(acuity(1), 17.25 * std::atan(0.35) + 25.72, 1e-12);
}

TEST(Pcond, Drand48FollowsGlibcFromStateZero) {
    Drand48 r;
    EXPECT_EQ(r.next(), std::ldexp(11.0, -48));  // a * 0 + c
    const double second =
        std::ldexp(static_cast<double>((0x5DEECE66DULL * 11 + 11) & ((1ULL << 48) - 1)), -48);
    EXPECT_EQ(r.next(), second);
}

TEST(Pcond, ColourMatricesRoundTripAndBalanceWhite) {
    const ColorMatrix toXyz = rgbToXyzBalanced(std::nullopt);
    const ColorMatrix toRgb = xyzToRgbBalanced(std::nullopt);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) s += toRgb[i][k] * toXyz[k][j];
            EXPECT_NEAR(s, i == j, 1e-5);
        }
    // Equal-energy white (1,1,1) stays white for a device with a D65 white point.
    const Primaries d65{.64f, .33f, .29f, .6f, .15f, .06f, .3127f, .329f};
    Pixel white{1, 1, 1};
    matrixScan(rgbToRgbBalanced(std::nullopt, d65), &white, 1);
    for (float v : white) EXPECT_NEAR(v, 1, 2e-3);
}

TEST(Pcond, MacbethFilesNeedEveryLine) {
    std::string cal =
        "rxa(i) : select(i,0,.2,.4,.6,.8,1);\nrya(i) : select(i,0,.1,.3,.6,.8,1);\n"
        "gxa(i) : select(i,0,.2,.4,.6,.8,1);\ngya(i) : select(i,0,.2,.4,.6,.8,1);\n"
        "bxa(i) : select(i,0,.2,.4,.6,.8,1);\nbya(i) : select(i,0,.2,.4,.6,.8,1);\n"
        "ro = 1*rn + 0*gn + -0*bn ;\ngo = 0*rn + 1*gn + 0*bn ;\n";
    std::istringstream partial(cal);
    try {
        readMacbeth(partial, "m.cal");
        ADD_FAILURE() << "accepted a file without 'bo ='";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("inpflags==0377"), std::string::npos) << e.what();
    }
    std::istringstream full(cal + "bo = 0*rn + 0*gn + 1*bn ;\n");
    const Macbeth mb = readMacbeth(full, "m.cal");
    Pixel p{.5f, .5f, .5f};  // red's curve passes (.4,.3) and (.6,.6): .45 at .5
    macbethScan(mb, &p, 1);
    EXPECT_NEAR(p[0], .45, 1e-6);
    EXPECT_NEAR(p[1], .5, 1e-6);
}

TEST(Pcond, PrecomputedHistogramsAreCheckedAndUsed) {
    const std::string bytes = greyPicture(8, 6, 1e-3f, 1e3f, false);
    EXPECT_THROW(condition(bytes, {"-I"}, "0 1\n0.1 1\n0.5 1\n"), InputError);  // uneven
    EXPECT_THROW(condition(bytes, {"-I"}, "0 1\nx\n"), InputError);
    // An even histogram over the picture's six decades (log10 of 179e-3 .. 179e3): the
    // histogram map, although the picture alone would be scaled linearly.
    std::string hist;
    for (int i = 0; i <= 60; ++i) hist += std::to_string(-0.75 + 0.1 * i) + " 1\n";
    const Picture out = condition(bytes, {"-I"}, hist);
    EXPECT_EQ(out.header.value("EXPOSURE"), "");
    EXPECT_LT(out.at(0, 0)[1], out.at(7, 5)[1]);
}

}  // namespace
}  // namespace rp
