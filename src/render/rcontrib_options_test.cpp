#include "render/rcontrib_options.h"

#include <gtest/gtest.h>

#include <fstream>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::render {
namespace {

RcontribOptions parse(std::vector<std::string> args, BinCountEval eval = nullptr) {
    args.insert(args.begin(), "rcontrib");
    return parseRcontribArgs(args, eval);
}

std::string errorOf(std::vector<std::string> args) {
    try {
        parse(std::move(args));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(RcontribOptions, DefaultsAreRadiancesAndOverridesApply) {
    // RADIANCE compat (rcontrib -defaults): -ab 1 -ad 350 -dj .9 -dr 3 -st .02 -dc .75,
    // and -dt, -aa and -as forced to 0 whatever is given.
    RcontribOptions o = parse({"-dt", "0.1", "-aa", "0.2", "-as", "64", "-m", "lamp", "s.oct"});
    EXPECT_EQ(o.render.ambient.bounces, 1);
    EXPECT_EQ(o.render.ambient.divisions, 350);
    EXPECT_DOUBLE_EQ(o.render.direct.jitter, 0.9);
    EXPECT_EQ(o.render.direct.relays, 3);
    EXPECT_DOUBLE_EQ(o.render.specular.threshold, 0.02);
    EXPECT_DOUBLE_EQ(o.render.direct.threshold, 0);
    EXPECT_DOUBLE_EQ(o.render.ambient.accuracy, 0);
    EXPECT_EQ(o.render.ambient.supersamples, 0);
    EXPECT_TRUE(o.render.contributions);
    EXPECT_TRUE(o.render.uncorrelated);
    EXPECT_EQ(o.sceneFile, "s.oct");
    EXPECT_FALSE(o.contributions);
}

TEST(RcontribOptions, EachModifierTakesTheSettingsToItsLeft) {
    RcontribOptions o = parse({"-o",  "a_%s.txt", "-m",  "sun",     "-p", "MF=2", "-b",   "rbin",
                               "-bn", "578",      "-o",  "sky.dat", "-m", "sky",  "-b",   "0",
                               "-m",  "ground",   "-V+", "-c",      "3",  "-faf", "s.oct"});
    ASSERT_EQ(o.modifiers.size(), 3u);
    EXPECT_EQ(o.modifiers[0].outSpec, "a_%s.txt");
    EXPECT_EQ(o.modifiers[0].binExpr, "0");
    EXPECT_EQ(o.modifiers[0].bins, 1);
    EXPECT_EQ(o.modifiers[1].outSpec, "sky.dat");
    EXPECT_EQ(o.modifiers[1].params, "MF=2");
    EXPECT_EQ(o.modifiers[1].binExpr, "rbin");
    EXPECT_EQ(o.modifiers[1].bins, 578);
    EXPECT_EQ(o.modifiers[2].binExpr, "0");
    EXPECT_EQ(o.modifiers[2].bins, 1);  // a constant bin is one bin, whatever -bn says
    EXPECT_TRUE(o.contributions);
    EXPECT_EQ(o.accumulate, 3);
    EXPECT_EQ(o.inputFormat, 'a');
    EXPECT_EQ(o.outputFormat, 'f');
    // The header's command line: as given, without the octree.
    EXPECT_EQ(o.commandWords.back(), "-faf");
}

TEST(RcontribOptions, BinCountMayNameADefinition) {
    auto eval = [](const std::vector<CalcDefinition>& defs, const std::string& e) {
        EXPECT_EQ(defs.size(), 1u);
        EXPECT_EQ(defs[0].text, "N=146");
        EXPECT_EQ(e, "N");
        return 146.0;
    };
    RcontribOptions o =
        parse({"-e", "N=146", "-bn", "N", "-b", "tbin", "-m", "sky", "s.oct"}, eval);
    EXPECT_EQ(o.modifiers[0].bins, 146);
}

TEST(RcontribOptions, ModifierFileWords) {
    rp::TempDir dir;
    const std::string f = dir.file("mods.txt");
    std::ofstream(f) << "lamp_red\nlamp_green lamp_blue\n";
    RcontribOptions o = parse({"-o", "c_%s.txt", "-M", f, "s.oct"});
    ASSERT_EQ(o.modifiers.size(), 3u);
    EXPECT_EQ(o.modifiers[2].name, "lamp_blue");
    EXPECT_EQ(o.modifiers[2].outSpec, "c_%s.txt");
}

TEST(RcontribOptions, RadiancesMessages) {
    EXPECT_EQ(errorOf({"s.oct"}), "missing required modifier argument");
    EXPECT_EQ(errorOf({"-m", "a", "-m", "a", "s.oct"}), "duplicate modifier 'a'");
    EXPECT_EQ(errorOf({"-m", "void", "s.oct"}), "cannot track 'void' modifier");
    EXPECT_EQ(errorOf({"-b", "Dx", "-m", "a", "s.oct"}),
              "unspecified or illegal bin count for modifier 'a'");
    EXPECT_EQ(errorOf({"-bn", "0", "-b", "Dx", "-m", "a", "s.oct"}),
              "unspecified or illegal bin count for modifier 'a'");
    EXPECT_EQ(errorOf({"-b", "2", "-m", "a", "s.oct"}), "illegal non-zero constant for bin (2)");
    EXPECT_EQ(errorOf({"-b", "-1", "-m", "a", "s.oct"}), "illegal non-zero constant for bin (-1)");
    EXPECT_EQ(errorOf({"-b", "0.4", "-m", "a", "s.oct"}), "");  // rounds to bin 0
    EXPECT_EQ(errorOf({"-M", "./no/such/file", "s.oct"}),
              "cannot find modifier file './no/such/file'");
    EXPECT_EQ(errorOf({"-m", "a"}), "missing octree argument");
    EXPECT_EQ(errorOf({"-fx", "-m", "a", "s.oct"}), "Illegal i/o format: -fx");
    EXPECT_EQ(errorOf({"-q", "-m", "a", "s.oct"}), "command line error at '-q'");
}

TEST(RcontribOptions, SumAllRaysHasNoResolution) {
    // rcmain.c override_options: -c 0 writes one record, so -x and -y do not apply.
    RcontribOptions o = parse({"-c", "0", "-x", "4", "-y", "3", "-m", "a", "s.oct"});
    EXPECT_EQ(o.xres, 0);
    EXPECT_EQ(o.yres, 0);
}

TEST(RcontribOptions, DefaultsTextMatchesRadiance) {
    RcontribOptions o = parse({"-defaults"});
    const std::string text = formatRcontribDefaults(o);
    // The first lines of RADIANCE 5.4's `rcontrib -defaults`, and its render values.
    EXPECT_EQ(text.substr(0, text.find("-n ")),
              "-c 1    \t\t\t# accumulated rays per record\n-V-\t\t\t\t# output coefficients\n");
    for (const char* line :
         {"-dt 0.000000\t\t\t# direct threshold\n", "-dj 0.900000\t\t\t# direct jitter\n",
          "-ab 1        \t\t\t# ambient bounces\n", "-ad 350      \t\t\t# ambient divisions\n",
          "-as 0        \t\t\t# ambient super-samples\n",
          "-st 0.020000\t\t\t# specular threshold\n"})
        EXPECT_NE(text.find(line), std::string::npos) << line;
}

}  // namespace
}  // namespace rp::render
