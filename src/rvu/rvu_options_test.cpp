// rvu's command line: RADIANCE rvu's defaults (rvmain.c over raycalls.c's globals), rpict's
// view, picture and render options on top of them, rvu's own -o web[:PORT], -pe (a
// multiplier, or f-stops with a sign), -b, -devices, and a clear InputError naming each
// rpict-only option, unknown device or bad value.
#include "rvu/rvu_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "util/error.h"

namespace rp::rvu {
namespace {

// The message of the InputError that parsing `args` throws ("" if none).
std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseRvuCommand(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

TEST(RvuOptions, DefaultsAreRvmains) {
    const RvuOptions o = rvuDefaults();
    EXPECT_EQ(o.picture.sampleSpacing, 8);             // psample
    EXPECT_DOUBLE_EQ(o.picture.sampleThreshold, .15);  // maxdiff
    const render::RenderOptions& r = o.picture.render;
    EXPECT_DOUBLE_EQ(r.direct.threshold, .1);
    EXPECT_DOUBLE_EQ(r.direct.certainty, .25);
    EXPECT_EQ(r.direct.relays, 0);
    EXPECT_EQ(r.direct.pretest, 128);
    EXPECT_DOUBLE_EQ(r.direct.sampling, 0);
    EXPECT_DOUBLE_EQ(r.specular.threshold, .3);
    EXPECT_DOUBLE_EQ(r.specular.sampling, 1);
    EXPECT_EQ(r.limits.maxDepth, 6);
    EXPECT_DOUBLE_EQ(r.limits.minWeight, 1e-2);
    EXPECT_DOUBLE_EQ(r.ambient.accuracy, .3);
    EXPECT_EQ(r.ambient.resolution, 32);
    EXPECT_EQ(r.ambient.divisions, 256);
    EXPECT_EQ(r.ambient.supersamples, 64);
    // Not set by rvmain.c: the same in raycalls.c and rpict.c.
    EXPECT_EQ(r.ambient.bounces, 0);
    EXPECT_DOUBLE_EQ(r.direct.jitter, 0);
    EXPECT_TRUE(r.direct.visibility);
    EXPECT_TRUE(r.backVisible);
    EXPECT_EQ(r.threads, 1);
    // rvu's own (rvmain.c: exposure 1, greyscale 0) and STDVIEW.
    EXPECT_DOUBLE_EQ(o.exposure, 1);
    EXPECT_FALSE(o.greyscale);
    EXPECT_EQ(o.device, "web");
    EXPECT_EQ(o.port, 0);
    EXPECT_EQ(o.picture.view, View{});
    EXPECT_EQ(o.picture.xres, 512);
    EXPECT_EQ(o.picture.yres, 512);
}

TEST(RvuOptions, DefaultsSampleUncorrelatedAsRadianceRvu) {
    // rvu links raycalls.c, whose rand_samp = 1 (rtrace's too); rvmain.c keeps it, so
    // RADIANCE's `rvu -defaults` prints -u+. Only rpict.c has rand_samp = 0.
    EXPECT_TRUE(rvuDefaults().picture.render.uncorrelated);
    EXPECT_TRUE(parseRvuCommand({}).options.picture.render.uncorrelated);
}

TEST(RvuOptions, NoArgumentsGiveDefaults) {
    const RvuCommand c = parseRvuCommand({});
    EXPECT_TRUE(c.sceneFiles.empty());
    EXPECT_FALSE(c.printDefaults || c.printDevices || c.printVersion);
    EXPECT_EQ(c.options.picture.sampleSpacing, 8);
    EXPECT_EQ(c.options.picture.render.ambient.divisions, 256);
}

TEST(RvuOptions, ViewPictureAndRenderOptions) {
    const RvuCommand c = parseRvuCommand(
        {"-vtl", "-vp", "1",   "2",   "3",  "-vd", "0", "0",   "-1",  "-vu",      "0",  "1",
         "0",    "-vh", "20",  "-vv", "10", "-ps", "2", "-pt", ".2",  "-pj",      ".5", "-x",
         "640",  "-y",  "480", "-n",  "4",  "-ab", "2", "-aa", ".05", "scene.oct"});
    const RvuOptions& o = c.options;
    EXPECT_EQ(o.picture.view.type, ViewType::kParallel);
    EXPECT_EQ(o.picture.view.point, (Vec3{1, 2, 3}));
    EXPECT_EQ(o.picture.view.direction, (Vec3{0, 0, -1}));
    EXPECT_EQ(o.picture.view.up, (Vec3{0, 1, 0}));
    EXPECT_DOUBLE_EQ(o.picture.view.horizontal, 20);
    EXPECT_DOUBLE_EQ(o.picture.view.vertical, 10);
    EXPECT_EQ(o.picture.sampleSpacing, 2);
    EXPECT_DOUBLE_EQ(o.picture.sampleThreshold, .2);
    EXPECT_DOUBLE_EQ(o.picture.pixelJitter, .5);
    EXPECT_EQ(o.picture.xres, 640);
    EXPECT_EQ(o.picture.yres, 480);
    EXPECT_EQ(o.picture.render.threads, 4);
    EXPECT_EQ(o.picture.render.ambient.bounces, 2);
    EXPECT_DOUBLE_EQ(o.picture.render.ambient.accuracy, .05);
    EXPECT_EQ(o.picture.render.ambient.divisions, 256);  // untouched: still rvu's
    EXPECT_EQ(c.sceneFiles, std::vector<std::string>{"scene.oct"});
    EXPECT_NE(errorOf({"-n", "0"}), "");
    EXPECT_NE(errorOf({"-x", "0"}), "");
}

TEST(RvuOptions, ExposureMultiplierOrFStops) {
    auto pe = [](const std::string& v) { return parseRvuCommand({"-pe", v}).options.exposure; };
    EXPECT_DOUBLE_EQ(pe("2"), 2);
    EXPECT_DOUBLE_EQ(pe(".25"), .25);
    EXPECT_DOUBLE_EQ(pe("+1"), 2);  // f-stops
    EXPECT_DOUBLE_EQ(pe("-1"), .5);
    EXPECT_DOUBLE_EQ(pe("-3"), .125);
    EXPECT_DOUBLE_EQ(pe("+0"), 1);
    EXPECT_NEAR(pe("+.5"), std::sqrt(2.0), 1e-15);
    for (const char* bad : {"0", "-0x", "abc", "", "inf", "nan", "1e999"})
        EXPECT_TRUE(contains(errorOf({"-pe", bad}), "-pe")) << bad;
    EXPECT_TRUE(contains(errorOf({"-pe"}), "missing value for -pe"));
}

TEST(RvuOptions, WebDeviceWithOptionalPort) {
    EXPECT_EQ(parseRvuCommand({"-o", "web"}).options.device, "web");
    EXPECT_EQ(parseRvuCommand({"-o", "web"}).options.port, 0);
    const RvuOptions o = parseRvuCommand({"-o", "web:8123"}).options;
    EXPECT_EQ(o.device, "web");
    EXPECT_EQ(o.port, 8123);
    EXPECT_EQ(parseRvuCommand({"-o", "web:65535"}).options.port, 65535);
    EXPECT_EQ(parseRvuCommand({"-o", "web:0"}).options.port, 0);
    // RADIANCE's window devices (rad -o x11, objview) open the web display.
    EXPECT_EQ(parseRvuCommand({"-o", "x11"}).options.device, "web");
    EXPECT_EQ(parseRvuCommand({"-o", "qt:8124"}).options.port, 8124);
    const std::string bad = errorOf({"-o", "tty"});
    EXPECT_TRUE(contains(bad, "\"tty\"")) << bad;
    EXPECT_TRUE(contains(errorOf({"-o", "tty:1"}), "\"tty\""));
    EXPECT_EQ(parseRvuCommand({"-R", "x.rif", "-o", "x11"}).options.radFile, "x.rif");
    EXPECT_TRUE(contains(errorOf({"-o", "webgl"}), "\"webgl\""));
    for (const char* bad : {"web:99999", "web:65536", "web:", "web:-1", "web:8o", "web:1:2"})
        EXPECT_TRUE(contains(errorOf({"-o", bad}), "bad port")) << bad;
    EXPECT_TRUE(contains(errorOf({"-o"}), "missing value for -o"));
}

TEST(RvuOptions, GreyscaleTogglesOrSets) {
    auto grey = [](const std::vector<std::string>& a) {
        return parseRvuCommand(a).options.greyscale;
    };
    EXPECT_TRUE(grey({"-b"}));
    EXPECT_FALSE(grey({"-b", "-b"}));
    EXPECT_TRUE(grey({"-b+"}));
    EXPECT_TRUE(grey({"-b+", "-b+"}));
    EXPECT_FALSE(grey({"-b+", "-b-"}));
    EXPECT_TRUE(grey({"-b-", "-b"}));
    EXPECT_FALSE(parseRvuCommand({"-bv-"}).options.picture.render.backVisible);  // not -b
}

TEST(RvuOptions, PrintRequests) {
    EXPECT_TRUE(parseRvuCommand({"-devices"}).printDevices);
    EXPECT_TRUE(parseRvuCommand({"-defaults"}).printDefaults);
    EXPECT_TRUE(parseRvuCommand({"-help"}).printDefaults);
    EXPECT_TRUE(parseRvuCommand({"-version"}).printVersion);
    EXPECT_TRUE(contains(formatRvuDevices(), "web"));
}

TEST(RvuOptions, RefusesRpictOnlyOptionsByName) {
    for (const std::string opt : {"-z", "-r", "-ro", "-S", "-t", "-pd", "-pm", "-P", "-PP"}) {
        const std::string e = errorOf({opt, "1", "scene.oct"});
        EXPECT_TRUE(contains(e, "'" + opt + "'")) << opt << ": " << e;
        EXPECT_TRUE(contains(e, "rpict")) << opt << ": " << e;
    }
}

TEST(RvuOptions, UnknownOptionsAndScenes) {
    const std::string e = errorOf({"-q"});
    EXPECT_TRUE(contains(e, "unknown option '-q'")) << e;
    EXPECT_TRUE(contains(errorOf({"-pq", "1"}), "-pq"));
    const RvuCommand c = parseRvuCommand({"-ab", "1", "a.rad", "b.rad", "-"});
    EXPECT_EQ(c.sceneFiles, (std::vector<std::string>{"a.rad", "b.rad", "-"}));
    const std::string after = errorOf({"scene.oct", "-ab", "1"});
    EXPECT_TRUE(contains(after, "'-ab' after the scene")) << after;
    EXPECT_TRUE(contains(errorOf({"scene.oct", "-o", "web"}), "'-o'"));
}

TEST(RvuOptions, DefaultsTextStartsWithRvusOwn) {
    const std::string s = formatRvuDefaults(rvuDefaults());
    EXPECT_EQ(s.rfind("-n 1\t\t\t\t# number of rendering threads\n"
                      "-o web\t\t\t\t# output device\n"
                      "-pe 1.000000\t\t\t# exposure\n"
                      "-b-\t\t\t\t# greyscale off\n",
                      0),
              0u)
        << s;
    EXPECT_TRUE(contains(s, "\n-ps 8 ")) << s;
    // Not the lines of options rvu refuses, so that the text can be pasted back.
    EXPECT_FALSE(contains(s, "\n-pd ") || contains(s, "\n-pm ") || contains(s, "\n-t ")) << s;
    RvuOptions port = rvuDefaults();
    port.port = 8123;
    EXPECT_TRUE(contains(formatRvuDefaults(port), "-o web:8123\t")) << s;
    EXPECT_TRUE(contains(s, "\n-pt 0.150000\t")) << s;
    EXPECT_TRUE(contains(s, "\n-ad 256\t") || contains(s, "\n-ad 256 ")) << s;
    RvuOptions o = rvuDefaults();
    o.exposure = 2;
    o.greyscale = true;
    const std::string t = formatRvuDefaults(o);
    EXPECT_TRUE(contains(t, "-pe 2.000000\t")) << t;
    EXPECT_TRUE(contains(t, "\n-b+\t")) << t;
}

}  // namespace
}  // namespace rp::rvu
