// rtrace's command line and -defaults text (rtrace_options.h).
#include "render/rtrace_options.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::render {
namespace {

std::string errorOf(std::vector<std::string> args) {
    try {
        parseRtraceArgs(std::move(args));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(RtraceOptions, ToolOptions) {
    RtraceOptions o = parseRtraceArgs({"rtrace", "-ab", "1", "-x", "4", "-y", "3", "-h-", "-ffd",
                                       "-ovodLsmM", "-I", "-ld", "-n", "2", "s.oct"});
    EXPECT_EQ(o.render.ambient.bounces, 1);
    EXPECT_EQ(o.xres, 4);
    EXPECT_EQ(o.yres, 3);
    EXPECT_FALSE(o.header);
    EXPECT_EQ(o.inputFormat, 'f');
    EXPECT_EQ(o.outputFormat, 'd');
    EXPECT_EQ(o.outputSpec, "vodLsmM");
    EXPECT_TRUE(o.immediateIrradiance);
    EXPECT_TRUE(o.limitDistance);
    EXPECT_EQ(o.render.threads, 2);
    EXPECT_EQ(o.sceneFile, "s.oct");
    EXPECT_EQ(o.optionCount, 14u);
    o = parseRtraceArgs({"rtrace", "-fd", "-h", "-I+", "-I-", "s.oct"});
    EXPECT_EQ(o.inputFormat, 'd');
    EXPECT_EQ(o.outputFormat, 'd');
    EXPECT_FALSE(o.header);
    EXPECT_FALSE(o.immediateIrradiance);
    o = parseRtraceArgs({"rtrace", "-fac", "s.oct"});
    EXPECT_EQ(o.outputFormat, 'c');
}

TEST(RtraceOptions, RtraceDefaults) {
    RtraceOptions o = parseRtraceArgs({"rtrace", "s.oct"});
    EXPECT_TRUE(o.render.uncorrelated);  // RADIANCE rtmain.c: -u+ for rtrace
    EXPECT_EQ(o.outputSpec, "v");
    EXPECT_EQ(o.inputFormat, 'a');
    EXPECT_TRUE(o.header);
}

TEST(RtraceOptions, Errors) {
    EXPECT_EQ(errorOf({"rtrace", "-xx", "s.oct"}), "unknown option '-xx'");
    EXPECT_EQ(errorOf({"rtrace", "-fz", "s.oct"}), "unknown option '-fz'");
    EXPECT_EQ(errorOf({"rtrace", "-fca", "s.oct"}), "unknown option '-fca'");
    EXPECT_EQ(errorOf({"rtrace", "-hx", "s.oct"}), "unknown option '-hx'");
    EXPECT_EQ(errorOf({"rtrace", "-ab", "2"}), "missing octree argument");
    EXPECT_EQ(errorOf({"rtrace", "-x", "a", "s.oct"}), "bad value 'a' for option '-x'");
    EXPECT_NE(errorOf({"rtrace", "a.oct", "b.oct"}), "");
}

TEST(RtraceOptions, TraceIncludeAndExcludeLists) {
    TempDir dir;
    const std::string file = dir.file("mods.txt");
    std::ofstream(file) << "glass\n  metal frame\n";
    RtraceOptions o = parseRtraceArgs({"rtrace", "-ti", "a", "-tI", file, "-ti", "b", "s.oct"});
    EXPECT_EQ(o.trace.mode, TraceFilter::Mode::kInclude);
    EXPECT_EQ(o.trace.modifiers, (std::vector<std::string>{"a", "glass", "metal", "frame", "b"}));
    // RADIANCE compat: switching kinds starts a new list.
    o = parseRtraceArgs({"rtrace", "-ti", "a", "-te", "b", "-tE", file, "s.oct"});
    EXPECT_EQ(o.trace.mode, TraceFilter::Mode::kExclude);
    EXPECT_EQ(o.trace.modifiers, (std::vector<std::string>{"b", "glass", "metal", "frame"}));
    EXPECT_EQ(parseRtraceArgs({"rtrace", "s.oct"}).trace.mode, TraceFilter::Mode::kAll);
    EXPECT_EQ(errorOf({"rtrace", "-tI", dir.file("none"), "s.oct"}),
              "cannot open trace include file \"" + dir.file("none") + "\"");
    EXPECT_EQ(errorOf({"rtrace", "-te"}), "missing value for option '-te'");
    EXPECT_EQ(errorOf({"rtrace", "-tx", "a", "s.oct"}), "unknown option '-tx'");
}

// RADIANCE compat (rtmain.c and renderopts.c: wordfile on getpath): a modifier list file
// named without a folder is found along RAYPATH, as the .cal files are.
TEST(RtraceOptions, ModifierListFilesAreFoundAlongRaypath) {
    TempDir dir;
    std::ofstream(dir.file("lib_mods.txt")) << "glass frame\n";
    const char* old = std::getenv("RAYPATH");
    const std::string saved = old ? old : "";
    ::setenv("RAYPATH", (".:" + dir.path().string()).c_str(), 1);
    RtraceOptions o = parseRtraceArgs({"rtrace", "-tI", "lib_mods.txt", "s.oct"});
    EXPECT_EQ(o.trace.modifiers, (std::vector<std::string>{"glass", "frame"}));
    o = parseRtraceArgs({"rtrace", "-aE", "lib_mods.txt", "s.oct"});
    EXPECT_EQ(o.render.ambient.modifiers, (std::vector<std::string>{"glass", "frame"}));
    EXPECT_FALSE(o.render.ambient.includeList);
    if (old)
        ::setenv("RAYPATH", saved.c_str(), 1);
    else
        ::unsetenv("RAYPATH");
}

TEST(RtraceOptions, DefaultsStopsParsing) {
    RtraceOptions o = parseRtraceArgs({"rtrace", "-ab", "3", "-defaults", "-bogus"});
    EXPECT_TRUE(o.printDefaults);
    const std::string text = formatRtraceDefaults(o);
    EXPECT_EQ(text.substr(0, text.find("-w+")),
              "-n 1 \t\t\t\t# number of rendering processes\n"
              "-x 0        \t\t\t# flush interval\n"
              "-y 0        \t\t\t# y resolution\n"
              "-ld-\t\t\t\t# limit distance off\n"
              "-h+\t\t\t\t# output header\n"
              "-faa\t\t\t\t# format input/output = ascii/ascii\n"
              "-ov        \t\t\t# output value\n");
    EXPECT_NE(text.find("-w+\t\t\t\t# warning messages on\n-i-"), std::string::npos);
    EXPECT_NE(text.find("-u+\t\t\t\t# uncorrelated Monte Carlo sampling\n"), std::string::npos);
    EXPECT_NE(text.find("-ab 3        \t\t\t# ambient bounces\n"), std::string::npos);
    o = parseRtraceArgs({"rtrace", "-I+", "-x", "2", "-y", "2", "-ffc", "-ovw", "-defaults"});
    const std::string t2 = formatRtraceDefaults(o);
    EXPECT_EQ(t2.substr(0, t2.find('\n') + 1), "-I+\t\t\t\t# immediate irradiance on\n");
    EXPECT_NE(t2.find("# x resolution"), std::string::npos);
    EXPECT_NE(t2.find("-ffc\t\t\t\t# format input/output = float/32-bit_rle_rgbe\n"),
              std::string::npos);
    EXPECT_NE(t2.find("# output value weight\n"), std::string::npos);
}

TEST(RtraceOptions, ExpandsAtOptionPositions) {
    TempDir dir;
    std::ofstream(dir.file("opts")) << "-ab 2 -h-\n";
    RtraceOptions o = parseRtraceArgs({"rtrace", "@" + dir.file("opts"), "-ov", "s.oct"});
    EXPECT_EQ(o.render.ambient.bounces, 2);
    EXPECT_FALSE(o.header);
    EXPECT_EQ(o.args.size(), 6u);
    EXPECT_EQ(o.optionCount, 5u);
}

}  // namespace
}  // namespace rp::render
