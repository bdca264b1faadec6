// rpict's option parsing, defaults text and picture size rule (rpict_options.h).
#include "render/rpict_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::render {
namespace {

TEST(RpictOptions, DefaultsAreRpictsNotRtraces) {
    RpictOptions o;
    EXPECT_EQ(o.xres, 512);
    EXPECT_EQ(o.yres, 512);
    EXPECT_DOUBLE_EQ(o.pixelAspect, 1);
    EXPECT_DOUBLE_EQ(o.pixelJitter, 0.67);
    EXPECT_EQ(o.sampleSpacing, 4);
    EXPECT_DOUBLE_EQ(o.sampleThreshold, 0.05);
    EXPECT_EQ(o.reportInterval, 0);
    // RADIANCE 5.4 rpict.c globals.
    EXPECT_EQ(o.render.limits.maxDepth, 7);
    EXPECT_DOUBLE_EQ(o.render.limits.minWeight, 1e-3);
    EXPECT_DOUBLE_EQ(o.render.direct.threshold, 0.05);
    EXPECT_DOUBLE_EQ(o.render.direct.sampling, 0.25);
    EXPECT_EQ(o.render.direct.relays, 1);
    EXPECT_DOUBLE_EQ(o.render.ambient.accuracy, 0.2);
    EXPECT_EQ(o.render.ambient.resolution, 64);
    EXPECT_EQ(o.render.ambient.divisions, 512);
    EXPECT_EQ(o.render.ambient.supersamples, 128);
    EXPECT_EQ(o.render.ambient.bounces, 0);
    EXPECT_EQ(o.view, View{});
}

TEST(RpictOptions, ParsesEveryFamily) {
    RpictCommand c = parseRpictCommand(
        {"-x",  "100", "-y", "50",  "-pa",     "0",  "-ps",   "2",    "-pt", ".1",       "-pj",
         "0",   "-t",  "5",  "-o",  "out.hdr", "-z", "z.raw", "-vth", "-vh", "180",      "-vv",
         "180", "-ab", "2",  "-lr", "-3",      "-n", "4",     "-pm",  "0.5", "scene.rad"});
    const RpictOptions& o = c.options;
    EXPECT_EQ(o.xres, 100);
    EXPECT_EQ(o.yres, 50);
    EXPECT_DOUBLE_EQ(o.pixelAspect, 0);
    EXPECT_EQ(o.sampleSpacing, 2);
    EXPECT_DOUBLE_EQ(o.sampleThreshold, 0.1);
    EXPECT_DOUBLE_EQ(o.pixelJitter, 0);
    EXPECT_EQ(o.reportInterval, 5);
    EXPECT_EQ(o.outputFile, "out.hdr");
    EXPECT_EQ(o.zFile, "z.raw");
    EXPECT_EQ(o.view.type, ViewType::kHemispherical);
    EXPECT_DOUBLE_EQ(o.view.horizontal, 180);
    EXPECT_EQ(o.render.ambient.bounces, 2);
    EXPECT_EQ(o.render.limits.maxDepth, -3);
    EXPECT_EQ(o.render.threads, 4);
    EXPECT_DOUBLE_EQ(o.motionBlur, 0.5);
    ASSERT_EQ(c.sceneFiles.size(), 1u);
    EXPECT_EQ(c.sceneFiles[0], "scene.rad");
    EXPECT_FALSE(c.printDefaults);
}

TEST(RpictOptions, NoSceneIsLeftToTheTool) {
    RpictCommand c = parseRpictCommand({"-x", "10"});
    EXPECT_TRUE(c.sceneFiles.empty());
    EXPECT_TRUE(parseRpictCommand({"-defaults"}).printDefaults);
}

std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseRpictCommand(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(RpictOptions, BadInputIsAnInputError) {
    EXPECT_EQ(errorOf({"-q", "s.rad"}), "unknown option '-q'");
    EXPECT_NE(errorOf({"-x", "abc", "s.rad"}).find("bad value for -x"), std::string::npos);
    EXPECT_NE(errorOf({"-x", "0", "s.rad"}).find("-x"), std::string::npos);
    EXPECT_NE(errorOf({"-pt", "1x", "s.rad"}).find("bad value for -pt"), std::string::npos);
    EXPECT_NE(errorOf({"-x"}).find("missing value for -x"), std::string::npos);
    EXPECT_NE(errorOf({"s.rad", "-x", "10"}).find("after the scene file"), std::string::npos);
    EXPECT_NE(errorOf({"-vh"}).size(), 0u);
    for (const char* unsupported : {"-P", "-PP"})
        EXPECT_NE(errorOf({unsupported, "1", "s.rad"}).find("not supported"), std::string::npos)
            << unsupported;
    EXPECT_NE(errorOf({"-S", "x", "s.rad"}).find("bad value for -S"), std::string::npos);
    EXPECT_NE(errorOf({"-r"}).find("missing value for -r"), std::string::npos);
}

TEST(RpictOptions, SequenceRecoverAndApertureOptions) {
    RpictOptions o = parseRpictCommand({"-S", "3", "-r", "old.hdr", "-pd", "0.1", "s.rad"}).options;
    EXPECT_EQ(o.sequenceStart, 3);
    EXPECT_EQ(o.recoverFile, "old.hdr");
    EXPECT_TRUE(o.outputFile.empty());
    EXPECT_DOUBLE_EQ(o.apertureBlur, 0.1);
    // RADIANCE compat: -ro is -r and -o with the same file.
    o = parseRpictCommand({"-o", "a.hdr", "-ro", "b.hdr", "s.rad"}).options;
    EXPECT_EQ(o.recoverFile, "b.hdr");
    EXPECT_EQ(o.outputFile, "b.hdr");
}

TEST(RpictOptions, ExpandsAtFilesAtOptionPositions) {
    TempDir dir;
    std::string file = dir.file("opts");
    std::ofstream(file) << "-x 64 -y 32\n-ps 1\n";
    RpictCommand c = parseRpictCommand({"@" + file, "-pj", "0", "s.rad"});
    EXPECT_EQ(c.options.xres, 64);
    EXPECT_EQ(c.options.yres, 32);
    EXPECT_EQ(c.options.sampleSpacing, 1);
    EXPECT_DOUBLE_EQ(c.options.pixelJitter, 0);
    EXPECT_EQ(c.sceneFiles, std::vector<std::string>{"s.rad"});
}

TEST(RpictOptions, DefaultsTextFollowsRadiance) {
    RpictOptions o;
    std::string s = formatRpictDefaults(o);
    EXPECT_EQ(s.rfind("-vtv\t\t\t\t# view type perspective\n", 0), 0u) << s;
    EXPECT_NE(s.find("-x  512      \t\t\t# x resolution\n"), std::string::npos) << s;
    EXPECT_NE(s.find("-pj 0.670000\t\t\t# pixel jitter\n"), std::string::npos);
    EXPECT_NE(s.find("-ps 4        \t\t\t# pixel sample\n"), std::string::npos);
    EXPECT_NE(s.find("-pt 0.050000\t\t\t# pixel threshold\n"), std::string::npos);
    EXPECT_NE(s.find("-w+\t\t\t\t# warning messages on\n"), std::string::npos);
    EXPECT_NE(s.find("-lr 7"), std::string::npos);  // from formatRenderDefaults
    EXPECT_NE(s.find("-dt 0.050000"), std::string::npos);
}

TEST(RpictOptions, ViewAspectPerType) {
    View v;
    EXPECT_NEAR(viewAspect(v), 1.0, 1e-12);
    v.horizontal = 60;
    EXPECT_NEAR(viewAspect(v), std::tan(22.5 * kPi / 180) / std::tan(30 * kPi / 180), 1e-12);
    v.type = ViewType::kParallel;
    v.horizontal = 4;
    v.vertical = 2;
    EXPECT_NEAR(viewAspect(v), 0.5, 1e-12);
    v.type = ViewType::kAngular;
    v.horizontal = 360;
    v.vertical = 180;
    EXPECT_NEAR(viewAspect(v), 0.5, 1e-12);
    v.type = ViewType::kHemispherical;
    v.horizontal = v.vertical = 180;
    EXPECT_NEAR(viewAspect(v), 1.0, 1e-12);
}

TEST(RpictOptions, PictureSizeKeepsTheViewAspect) {
    RpictOptions o;
    o.view.horizontal = 60;  // wider than high
    PictureSize p = pictureSize(o);
    EXPECT_EQ(p.xres, 512);
    // 512 * tan(22.5 deg) / tan(30 deg) = 367.33..., RADIANCE rounds (+.5, truncate).
    EXPECT_EQ(p.yres, 367);
    EXPECT_DOUBLE_EQ(p.pixelAspect, 1);

    o.view.horizontal = 45;
    o.view.vertical = 60;  // higher than wide: x is reduced
    p = pictureSize(o);
    EXPECT_EQ(p.yres, 512);
    EXPECT_EQ(p.xres, 367);

    // -pa 0: the resolution is kept and the pixel aspect follows.
    o.pixelAspect = 0;
    p = pictureSize(o);
    EXPECT_EQ(p.xres, 512);
    EXPECT_EQ(p.yres, 512);
    EXPECT_NEAR(p.pixelAspect, std::tan(30 * kPi / 180) / std::tan(22.5 * kPi / 180), 1e-12);

    // -pa 2 on a square view: pixels twice as high as wide, so half the scanlines.
    o.view.vertical = 45;
    o.pixelAspect = 2;
    p = pictureSize(o);
    EXPECT_EQ(p.xres, 512);
    EXPECT_EQ(p.yres, 256);
    EXPECT_DOUBLE_EQ(p.pixelAspect, 2);

    // Never below one pixel.
    o.pixelAspect = 1;
    o.xres = 1;
    o.yres = 1;
    o.view.horizontal = 1;
    o.view.vertical = 170;
    p = pictureSize(o);
    EXPECT_EQ(p.xres, 1);
    EXPECT_EQ(p.yres, 1);
}

}  // namespace
}  // namespace rp::render
