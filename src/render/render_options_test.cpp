// Common render options: every family, booleans, errors, -defaults text, and the @file /
// $EVAR expansion (command_args.h).
#include "render/render_options.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "util/command_args.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::render {
namespace {

// Parses every argument as common options (the shared entries of a tool's option table);
// a word that is none of them is an unknown option.
RenderOptions parse(std::vector<std::string> args, RenderOptions o = {}) {
    OptionTable t;
    addRenderOptions(t, o);
    EXPECT_EQ(t.parse(args, 0).next, args.size());
    return o;
}

std::string errorOf(std::vector<std::string> args) {
    RenderOptions o;
    OptionTable t;
    addRenderOptions(t, o);
    try {
        t.parse(args, 0);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// -cs -cw (RADIANCE 6): the sampling checked as RADIANCE's setspectrsamp, then one set of
// options per pass of three bands, with the colours given as options in its bands and
// its own ambient file.
TEST(RenderOptions, SpectralPasses) {
    RenderOptions o = parse({"-cs", "7", "-cw", "700", "400", "-av", "1", "2", "3", "-af", "x.amb",
                             "-ap", "g.pm", "50"});
    const spectral::Sampling s = spectralSampling(o);
    EXPECT_EQ(s.n, 7);
    EXPECT_EQ(s.wl, (std::array<double, 4>{700, 588, 480, 400}));
    const std::vector<RenderOptions> passes = passOptions(o, s);
    ASSERT_EQ(passes.size(), 3u);
    // 7 bands of 300/7 nm from 700 nm: centres 678.6 635.7 592.9 | 550 507.1 | 464.3 421.4.
    EXPECT_EQ(passes[0].ambient.value, (Color{1, 1, 1}));
    EXPECT_EQ(passes[1].ambient.value, (Color{2, 2, 3}));
    EXPECT_EQ(passes[2].ambient.value, (Color{3, 3, 3}));
    EXPECT_EQ(passes[1].ambient.file, "x.amb.3-5");
    EXPECT_EQ(passes[1].ambient.bands, "-cs 7 -cw 400 700 bands 3-5");
    EXPECT_EQ(passes[2].photonMaps[0].pass.first, 6);
    EXPECT_EQ(passes[2].direct.pass, passes[2].pass);
    // RGB is one pass that changes nothing.
    const RenderOptions rgb = parse({"-av", "1", "2", "3", "-af", "x.amb"});
    const std::vector<RenderOptions> one = passOptions(rgb, spectralSampling(rgb));
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].ambient.value, (Color{1, 2, 3}));
    EXPECT_EQ(one[0].ambient.file, "x.amb");
    EXPECT_EQ(one[0].ambient.bands, "");
    EXPECT_THROW(spectralSampling(parse({"-cs", "2"})), InputError);
    EXPECT_THROW(spectralSampling(parse({"-cs", "9", "-cw", "500", "540"})), InputError);
}

TEST(RenderOptions, DirectSpecularLimits) {
    RenderOptions o = parse({"-dt", "0.1", "-dc", "0.9", "-dj", "0.5", "-ds", "0", "-dr", "3",
                             "-dp", "64",  "-ss", "2",   "-st", "0.5", "-lr", "8", "-lw", "1e-3"});
    EXPECT_DOUBLE_EQ(o.direct.threshold, 0.1);
    EXPECT_DOUBLE_EQ(o.direct.certainty, 0.9);
    EXPECT_DOUBLE_EQ(o.direct.jitter, 0.5);
    EXPECT_DOUBLE_EQ(o.direct.sampling, 0);
    EXPECT_EQ(o.direct.relays, 3);
    EXPECT_EQ(o.direct.pretest, 64);
    EXPECT_DOUBLE_EQ(o.specular.sampling, 2);
    EXPECT_DOUBLE_EQ(o.specular.threshold, 0.5);
    EXPECT_EQ(o.limits.maxDepth, 8);
    EXPECT_DOUBLE_EQ(o.limits.minWeight, 1e-3);
}

TEST(RenderOptions, Ambient) {
    RenderOptions o = parse({"-av", "0.1", "0.2", "0.3", "-aw", "5", "-ab", "2", "-aa", "0.2",
                             "-ar", "64", "-ad", "512", "-as", "128", "-af", "x.amb"});
    EXPECT_EQ(o.ambient.value, Color(0.1, 0.2, 0.3));
    EXPECT_EQ(o.ambient.valueWeight, 5);
    EXPECT_EQ(o.ambient.bounces, 2);
    EXPECT_DOUBLE_EQ(o.ambient.accuracy, 0.2);
    EXPECT_EQ(o.ambient.resolution, 64);
    EXPECT_EQ(o.ambient.divisions, 512);
    EXPECT_EQ(o.ambient.supersamples, 128);
    EXPECT_EQ(o.ambient.file, "x.amb");
}

TEST(RenderOptions, IncludeExcludeLists) {
    TempDir dir;
    std::ofstream(dir.file("mods")) << "a b\n c\n";
    RenderOptions o = parse({"-ae", "x", "-aE", dir.file("mods")});
    EXPECT_FALSE(o.ambient.includeList);
    EXPECT_EQ(o.ambient.modifiers, (std::vector<std::string>{"x", "a", "b", "c"}));
    // Switching to include starts a new list (RADIANCE renderopts.c).
    o = parse({"-ai", "y", "-aI", dir.file("mods")}, o);
    EXPECT_TRUE(o.ambient.includeList);
    EXPECT_EQ(o.ambient.modifiers, (std::vector<std::string>{"y", "a", "b", "c"}));
    EXPECT_NE(errorOf({"-aI", dir.file("missing")}).find("missing"), std::string::npos);
}

TEST(RenderOptions, Booleans) {
    RenderOptions o;
    EXPECT_TRUE(o.backVisible);
    o = parse({"-bv"}, o);
    EXPECT_FALSE(o.backVisible);  // toggles
    o = parse({"-bv"}, o);
    EXPECT_TRUE(o.backVisible);
    o = parse({"-bv-", "-dv-", "-i+", "-u+", "-w-"}, o);
    EXPECT_FALSE(o.backVisible);
    EXPECT_FALSE(o.direct.visibility);
    EXPECT_TRUE(o.irradiance);
    EXPECT_TRUE(o.uncorrelated);
    EXPECT_FALSE(o.warnings);
    o = parse({"-bv+", "-dv+", "-i-", "-u-", "-w+", "-i"}, o);
    EXPECT_TRUE(o.backVisible);
    EXPECT_TRUE(o.direct.visibility);
    EXPECT_TRUE(o.irradiance);
    EXPECT_FALSE(o.uncorrelated);
    EXPECT_TRUE(o.warnings);
    o = parse({"-bvy", "-dvf", "-i0", "-u1"}, o);
    EXPECT_TRUE(o.backVisible);
    EXPECT_FALSE(o.direct.visibility);
    EXPECT_FALSE(o.irradiance);
    EXPECT_TRUE(o.uncorrelated);
    EXPECT_EQ(errorOf({"-bvx"}), "unknown option '-bvx'");
}

TEST(RenderOptions, PhotonMaps) {
    RenderOptions o =
        parse({"-ap", "g.pm", "-ap", "c.pm", "50", "-ap", "b.pm", "50", "200", "-am", "0.5"});
    ASSERT_EQ(o.photonMaps.size(), 3u);
    EXPECT_EQ(o.photonMaps[0].file, "g.pm");
    EXPECT_EQ(o.photonMaps[0].bandwidth, 0);
    EXPECT_EQ(o.photonMaps[1].bandwidth, 50);
    EXPECT_EQ(o.photonMaps[1].bandwidth2, 0);
    EXPECT_EQ(o.photonMaps[2].bandwidth, 50);
    EXPECT_EQ(o.photonMaps[2].bandwidth2, 200);
    EXPECT_DOUBLE_EQ(o.photonMaxRadius, 0.5);
    EXPECT_EQ(o.ambient.bounces, 1);  // RADIANCE pmapopt.c: a photon map implies -ab 1
    // A following word that is not an integer is the next option (or the octree).
    std::vector<std::string> args{"-ap", "g.pm", "scene.oct"};
    RenderOptions p;
    OptionTable t;
    addRenderOptions(t, p);
    EXPECT_EQ(t.parse(args, 0).next, 2u);
    EXPECT_NE(errorOf({"-ap", "g.pm", "0"}), "");
    EXPECT_NE(errorOf({"-ap", "g.pm", "50", "20"}), "");
    EXPECT_NE(errorOf({"-am", "0"}), "");
    EXPECT_EQ(errorOf({"-ap"}), "missing value for option '-ap'");
}

// RADIANCE's out-of-core options: -ac page size (x bandwidth), -aC photons with k/M/G.
TEST(RenderOptions, PhotonCache) {
    RenderOptions d = parse({});
    EXPECT_EQ(d.photonCache, 0u);  // unset: the store is chosen by memory
    EXPECT_DOUBLE_EQ(d.photonPageSize, 4);
    RenderOptions o = parse({"-aC", "2.5M", "-ac", "8"});
    EXPECT_EQ(o.photonCache, 2500000u);
    EXPECT_DOUBLE_EQ(o.photonPageSize, 8);
    EXPECT_EQ(parse({"-aC", "10k"}).photonCache, 10000u);
    EXPECT_EQ(errorOf({"-aC", "0"}), "option '-aC': invalid photon cache size");
    EXPECT_NE(errorOf({"-aC", "lots"}), "");
    EXPECT_NE(errorOf({"-ac", "0"}), "");
}

// -n bounds all of TBB's parallelism while the limit lives (map loading included), and
// -n 0 or less counts as 1.
TEST(RenderOptions, ThreadLimitBoundsParallelism) {
    using tbb::global_control;
    const size_t before = global_control::active_value(global_control::max_allowed_parallelism);
    RenderOptions o;
    o.threads = 1;
    {
        const auto limit = threadLimit(o);
        EXPECT_EQ(global_control::active_value(global_control::max_allowed_parallelism), 1u);
    }
    EXPECT_EQ(global_control::active_value(global_control::max_allowed_parallelism), before);
    o.threads = 0;
    {
        const auto limit = threadLimit(o);
        EXPECT_EQ(global_control::active_value(global_control::max_allowed_parallelism), 1u);
    }
}

TEST(RenderOptions, ThreadsErrorFileMist) {
    RenderOptions o = parse({"-n", "4", "-e", "err.txt", "-me", "0.1", "0.1", "0.1", "-ma", "0.5",
                             "0.5", "0.5", "-mg", "0.3", "-ms", "0.2"});
    EXPECT_EQ(o.threads, 4);
    EXPECT_EQ(o.errorFile, "err.txt");
    EXPECT_TRUE(o.mist.any());
    EXPECT_DOUBLE_EQ(o.mist.eccentricity, 0.3);
}

TEST(RenderOptions, Errors) {
    EXPECT_EQ(errorOf({"-dt"}), "missing value for option '-dt'");
    EXPECT_EQ(errorOf({"-dt", "abc"}), "bad value 'abc' for option '-dt'");
    EXPECT_EQ(errorOf({"-ab", "1.5"}), "bad value '1.5' for option '-ab'");
    EXPECT_EQ(errorOf({"-av", "1", "2"}), "missing value for option '-av'");
    EXPECT_NE(errorOf({"-ad", "-1"}), "");
    EXPECT_EQ(errorOf({"-ad", "2000000000"}), "option '-ad': must be in [0, 100000000]");
    EXPECT_NE(errorOf({"-n", "0"}), "");
    EXPECT_NE(errorOf({"-dc", "2"}), "");
    // Not common options: left for the tool (which reports them as unknown).
    RenderOptions o;
    OptionTable t;
    addRenderOptions(t, o);
    EXPECT_EQ(t.find("-xx"), nullptr);
    EXPECT_EQ(t.find("-I"), nullptr);
    EXPECT_EQ(errorOf({"-xx"}), "unknown option '-xx'");
}

TEST(RenderOptions, DefaultsText) {
    RenderOptions o;
    const std::string text = formatRenderDefaults(o);
    EXPECT_EQ(text.substr(0, text.find('\n', text.find('\n') + 1) + 1),
              "-i-\t\t\t\t# irradiance calculation off\n"
              "-u-\t\t\t\t# correlated quasi-Monte Carlo sampling\n");
    EXPECT_NE(text.find("-dt 0.030000\t\t\t# direct threshold\n"), std::string::npos);
    EXPECT_NE(text.find("-dc 0.750000\t\t\t# direct certainty\n"), std::string::npos);
    EXPECT_NE(text.find("-dr 2        \t\t\t# direct relays\n"), std::string::npos);
    EXPECT_NE(text.find("-av 0.000000 0.000000 0.000000\t# ambient value\n"), std::string::npos);
    EXPECT_NE(text.find("-ad 1024     \t\t\t# ambient divisions\n"), std::string::npos);
    EXPECT_NE(text.find("-me 0.00e+00 0.00e+00 0.00e+00\t# mist extinction coefficient\n"),
              std::string::npos);
    EXPECT_NE(text.find("-lr -10      \t\t\t# limit reflection (Russian roulette)\n"),
              std::string::npos);
    EXPECT_NE(text.find("-lw 2.00e-03\t\t\t# limit weight\n"), std::string::npos);
    EXPECT_EQ(text.substr(text.rfind('-')), "-am 0.0\t\t\t\t# max photon search radius\n");
    o.limits.maxDepth = 6;
    EXPECT_NE(formatRenderDefaults(o).find("-lr 6        \t\t\t# limit reflection\n"),
              std::string::npos);
}

TEST(RenderOptionsExpand, SplitWords) {
    EXPECT_EQ(splitWords("  -ab 2\n-av 'a b' \"c d\"e\t"),
              (std::vector<std::string>{"-ab", "2", "-av", "a b", "c de"}));
    EXPECT_TRUE(splitWords(" \n ").empty());
}

TEST(RenderOptionsExpand, FileAndEnvironment) {
    TempDir dir;
    std::ofstream(dir.file("opts")) << "-ab 2 -aa 0.2\n";
    std::ofstream(dir.file("outer")) << "@" << dir.file("opts") << " -ad 64\n";
    ::setenv("RP_TEST_RTRACE_OPTS", "-lr 4 -lw 0.01", 1);
    std::vector<std::string> args{"rtrace", "@" + dir.file("outer"), "$RP_TEST_RTRACE_OPTS", "x"};
    expandArgAt(args, 1);
    EXPECT_EQ(args, (std::vector<std::string>{"rtrace", "-ab", "2", "-aa", "0.2", "-ad", "64",
                                              "$RP_TEST_RTRACE_OPTS", "x"}));
    expandArgAt(args, 7);
    EXPECT_EQ(args[7], "-lr");
    EXPECT_EQ(args.size(), 12u);
    // An empty expansion removes the argument.
    ::setenv("RP_TEST_RTRACE_EMPTY", "", 1);
    std::vector<std::string> e{"rtrace", "$RP_TEST_RTRACE_EMPTY", "scene"};
    expandArgAt(e, 1);
    EXPECT_EQ(e, (std::vector<std::string>{"rtrace", "scene"}));
}

TEST(RenderOptionsExpand, Errors) {
    TempDir dir;
    std::vector<std::string> args{"rtrace", "@" + dir.file("none")};
    try {
        expandArgAt(args, 1);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot expand '@" + dir.file("none") + "'");
    }
    ::unsetenv("RP_TEST_RTRACE_UNSET");
    args = {"rtrace", "$RP_TEST_RTRACE_UNSET"};
    EXPECT_THROW(expandArgAt(args, 1), InputError);
    std::ofstream(dir.file("self")) << "@" << dir.file("self");
    args = {"rtrace", "@" + dir.file("self")};
    EXPECT_THROW(expandArgAt(args, 1), InputError);
}

}  // namespace
}  // namespace rp::render
