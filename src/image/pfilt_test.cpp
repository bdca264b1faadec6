// pfilt: box filter of a known picture, the two-pass exposure and its header line, -e
// stops, output sizes with -x /f and -p, the Gaussian's flat top, star-point randomness
// and option errors.
#include "image/pfilt.h"

#include <gtest/gtest.h>

#include <sstream>

#include "image/pfilt_filter.h"
#include "util/error.h"

namespace rp {
namespace {

PfiltOptions parse(std::vector<std::string> args) {
    size_t words = 0;
    return parsePfiltArgs(args, words);
}

// 4 x 2 grey picture, pixel value x + 4 y + 1.
Picture ramp() {
    Picture pic(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            const float v = static_cast<float>(x + 4 * y + 1);
            pic.at(x, y) = Pixel{v, v, v};
        }
    pic.header.lines.push_back("test");
    return pic;
}

std::string headerValue(const Picture& p, const std::string& name) { return p.header.value(name); }

TEST(Pfilt, BoxFilterAveragesTheInputPixelsOfEachOutputPixel) {
    const Picture out = runPfilt(ramp(), parse({"-1", "-x", "/2", "-y", "/2"}), "pfilt -1", "t");
    ASSERT_EQ(out.width, 2);
    ASSERT_EQ(out.height, 1);
    EXPECT_FLOAT_EQ(out.at(0, 0)[0], (1 + 2 + 5 + 6) / 4.0f);
    EXPECT_FLOAT_EQ(out.at(1, 0)[1], (3 + 4 + 7 + 8) / 4.0f);
    // One pass, exposure 1: no EXPOSURE= line, the history line after the input's.
    EXPECT_EQ(out.header.lines.back(), "pfilt -1");
    EXPECT_EQ(headerValue(out, "EXPOSURE"), "");
}

TEST(Pfilt, SamplingUpRepeatsPixels) {
    const Picture out = runPfilt(ramp(), parse({"-1", "-x", "8", "-y", "4"}), "pfilt", "t");
    ASSERT_EQ(out.width, 8);
    ASSERT_EQ(out.height, 4);
    EXPECT_FLOAT_EQ(out.at(0, 0)[0], 1);
    EXPECT_FLOAT_EQ(out.at(1, 1)[0], 1);
    EXPECT_FLOAT_EQ(out.at(7, 3)[0], 8);
}

TEST(Pfilt, TwoPassesPutTheAverageAtOneHalf) {
    // Grey values 1..8 average 4.5 (brightness of grey is its value): exposure 0.5 / 4.5,
    // times -e 2 (and +1 stop is the same 2).
    for (const char* e : {"2", "+1"}) {
        const Picture out = runPfilt(ramp(), parse({"-e", e}), "pfilt", "t");
        EXPECT_NEAR(out.at(0, 0)[0], 1 * 2 * 0.5 / 4.5, 1e-6);
        EXPECT_NEAR(out.at(3, 1)[2], 8 * 2 * 0.5 / 4.5, 1e-6);
        EXPECT_EQ(headerValue(out, "EXPOSURE"), "2.222222e-01");
    }
    // Hot pixels (>= -h) stay out of the average unless -a.
    const Picture hot = runPfilt(ramp(), parse({"-h", "5"}), "pfilt", "t");
    EXPECT_NEAR(hot.at(0, 0)[0], 0.5 / 2.5, 1e-6);
    const Picture avg = runPfilt(ramp(), parse({"-h", "5", "-a"}), "pfilt", "t");
    EXPECT_NEAR(avg.at(0, 0)[0], 0.5 / 4.5, 1e-6);
}

TEST(Pfilt, ChannelExposureWritesColorCorrection) {
    const Picture out = runPfilt(ramp(), parse({"-1", "-er", "2"}), "pfilt", "t");
    EXPECT_FLOAT_EQ(out.at(0, 0)[0], 2);
    EXPECT_FLOAT_EQ(out.at(0, 0)[1], 1);
    EXPECT_NE(headerValue(out, "COLORCORR"), "");
}

TEST(Pfilt, ExposureStopsAndRange) {
    EXPECT_DOUBLE_EQ(parse({"-e", "-2"}).exposure[1], 0.25);
    EXPECT_DOUBLE_EQ(parse({"-e", "+1", "-e", "3"}).exposure[0], 6);
    EXPECT_DOUBLE_EQ(parse({"-eb", ".5"}).exposure[2], 0.5);
    EXPECT_THROW(parse({"-e", "1e30"}), InputError);
    EXPECT_THROW(parse({"-e", "0"}), InputError);
}

TEST(Pfilt, OutputSizes) {
    PfiltSize s = pfiltOutputSize(64, 48, 1, parse({"-x", "/2", "-y", "/3"}));
    EXPECT_EQ(s.ncols, 32);
    EXPECT_EQ(s.nrows, 16);
    // -p 1 on 64 x 48 asked for 32 x 32: the x size shrinks to keep square pixels.
    s = pfiltOutputSize(64, 48, 1, parse({"-x", "32", "-y", "32", "-p", "1"}));
    EXPECT_EQ(s.ncols, 32);
    EXPECT_EQ(s.nrows, 24);
    s = pfiltOutputSize(64, 64, 1, parse({"-x", "32", "-y", "32", "-p", "2"}));
    EXPECT_EQ(s.ncols, 32);
    EXPECT_EQ(s.nrows, 16);
}

TEST(Pfilt, NonSquareOutputPixelsAreRecordedUnlessCorrected) {
    const Picture out = runPfilt(ramp(), parse({"-1", "-x", "2", "-y", "2"}), "pfilt", "t");
    EXPECT_EQ(headerValue(out, "PIXASPECT"), "0.500000");
    const Picture c = runPfilt(ramp(), parse({"-1", "-c", "-x", "2", "-y", "2"}), "pfilt", "t");
    EXPECT_EQ(headerValue(c, "PIXASPECT"), "");
}

TEST(Pfilt, GaussianOfAFlatPictureIsFlat) {
    Picture flat(16, 16);
    for (Pixel& p : flat.pixels) p = Pixel{0.3f, 0.2f, 0.1f};
    for (const char* r : {".6", "1", "2"}) {
        const Picture out =
            runPfilt(flat, parse({"-1", "-r", r, "-x", "/2", "-y", "/2"}), "p", "t");
        for (const Pixel& p : out.pixels) EXPECT_NEAR(p[0], 0.3, 1e-5);
        const Picture m =
            runPfilt(flat, parse({"-1", "-m", ".2", "-x", "/2", "-y", "/2"}), "p", "t");
        EXPECT_NEAR(m.at(4, 4)[1], 0.2, 0.02);  // away from the borders
    }
}

TEST(Pfilt, StarPointRandomnessIsGlibcLrand48) {
    Rand48 r;
    EXPECT_EQ(r.next(), 0);
    EXPECT_EQ(r.next(), 2116118);
    EXPECT_EQ(r.next(), 89401895);
}

TEST(Pfilt, StarsSpreadAlongALine) {
    Picture pic(9, 9);
    for (Pixel& p : pic.pixels) p = Pixel{0.1f, 0.1f, 0.1f};
    pic.at(4, 4) = Pixel{1000, 1000, 1000};
    // -n 2: one line, slope tan(0): horizontal through the hot pixel.
    const Picture out = runPfilt(pic, parse({"-n", "2", "-s", "0.01"}), "pfilt", "t");
    EXPECT_GT(out.at(0, 4)[0], out.at(0, 3)[0]);
    EXPECT_FLOAT_EQ(out.at(0, 3)[0], out.at(0, 5)[0]);
}

TEST(Pfilt, ScanlineOrderIsKept) {
    // A 2 x 3 picture stored as Y-scanlines (+X 2 +Y 3 order: scanlines along Y).
    std::ostringstream file;
    file << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+X 2 +Y 3\n";
    for (int i = 0; i < 6; ++i) file << char(128) << char(128) << char(128) << char(129);
    std::istringstream in(file.str());
    std::ostringstream out;
    runPfilt(in, "t", parse({"-1", "-x", "/3"}), "pfilt -1 -x /3", out);
    EXPECT_NE(out.str().find("\n+X 2 +Y 1\n"), std::string::npos);
}

TEST(Pfilt, Errors) {
    EXPECT_THROW(parse({"-q"}), InputError);
    EXPECT_THROW(parse({"-x", "0"}), InputError);
    EXPECT_THROW(parse({"-x", "/0"}), InputError);
    EXPECT_THROW(parse({"a.hdr", "b.hdr"}), InputError);
    EXPECT_EQ(parse({"-x", "3", "a.hdr"}).inputFile, "a.hdr");
    Picture black(2, 2);
    EXPECT_THROW(runPfilt(black, parse({}), "pfilt", "t"), InputError);  // too dark
    std::istringstream junk("junk");
    std::ostringstream out;
    EXPECT_THROW(runPfilt(junk, "t", parse({}), "pfilt", out), InputError);
}

}  // namespace
}  // namespace rp

namespace rp {
namespace {

// RADIANCE's pfilt knows an option by its second character: RADIANCE's own test Makefile
// reduces pictures with "pfilt -1 -r 1 -x 128 -y 128 -pa 1".
TEST(Pfilt, OptionsAreKnownByTheirSecondCharacter) {
    const PfiltOptions o = parse({"-1", "-r", "1", "-x", "128", "-y", "128", "-pa", "1"});
    EXPECT_EQ(o.pixelAspect, 1);
    EXPECT_TRUE(o.singlePass);
    EXPECT_EQ(o.radius, 1);
    EXPECT_EQ(parse({"-rad", ".6", "-m", ".2"}).radius, .6);
    EXPECT_EQ(parse({"-er", "2"}).exposure[0], 2);  // -e keeps its colour forms
    EXPECT_THROW(parse({"-q"}), InputError);
}

}  // namespace
}  // namespace rp
