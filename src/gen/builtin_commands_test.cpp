// Scene files' generator commands run in-process (no RADIANCE on PATH needed), pipelines
// included; what needs a shell still goes to the shell.
#include "gen/builtin_commands.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "scene/reader.h"

namespace rp::gen {

TEST(SplitPipeline, WordsQuotesAndPipes) {
    auto p = splitPipeline("genbox mat 'my box' 1 2 3 | xform -t \"1\" 0\\ 0 0");
    ASSERT_TRUE(p);
    ASSERT_EQ(p->size(), 2u);
    EXPECT_EQ((*p)[0], (std::vector<std::string>{"genbox", "mat", "my box", "1", "2", "3"}));
    EXPECT_EQ((*p)[1], (std::vector<std::string>{"xform", "-t", "1", "0 0", "0"}));
}

TEST(SplitPipeline, ShellFeaturesAreLeftToTheShell) {
    for (const char* c : {"genbox m b 1 1 1 > x", "genbox m b $X 1 1", "a; b", "a && b", "a || b",
                          "cat *.rad", "xform `ls`", "genbox m b 1 1 1 |", "echo 'open"})
        EXPECT_FALSE(splitPipeline(c)) << c;
}

TEST(BuiltinCommands, GenboxThroughXformInAScene) {
    unsetenv(kShellCommandsEnv);
    Scene s = parseScene("void plastic m\n0\n0\n5 .5 .5 .5 0 0\n"
                         "!genbox m box 1 2 3 | xform -t 10 0 0\n",
                         "room.rad", builtinLoadOptions());
    ASSERT_EQ(s.prims.size(), 7u);  // the material and six polygons
    double minX = 1e9, maxX = -1e9, maxY = -1e9;
    for (size_t i = 1; i < s.prims.size(); ++i) {
        const Primitive& p = s.prims[i];
        EXPECT_EQ(p.type, PrimType::Polygon);
        EXPECT_EQ(p.modifier, 0);
        EXPECT_EQ(p.loc.line, 5);  // the ! line
        for (size_t k = 0; k + 2 < p.rargs.size(); k += 3) {
            minX = std::min(minX, p.rargs[k]);
            maxX = std::max(maxX, p.rargs[k]);
            maxY = std::max(maxY, p.rargs[k + 1]);
        }
    }
    EXPECT_EQ(minX, 10);
    EXPECT_EQ(maxX, 11);
    EXPECT_EQ(maxY, 2);
}

TEST(BuiltinCommands, XformOfAFileRunsInProcess) {
    unsetenv(kShellCommandsEnv);
    std::string path = testing::TempDir() + "builtin_xform.rad";
    {
        std::ofstream f(path);
        f << "m sphere s 0 0 4 0 0 0 1\n";
    }
    Scene s = parseScene("void plastic m 0 0 5 .5 .5 .5 0 0\n!xform -n k -t 0 0 3 " + path + "\n",
                         "top.rad", builtinLoadOptions());
    ASSERT_EQ(s.prims.size(), 2u);
    EXPECT_EQ(s.prims[1].name, "k.s");
    EXPECT_DOUBLE_EQ(s.prims[1].rargs[2], 3);
}

TEST(BuiltinCommands, GeneratorErrorsNameTheCommandLine) {
    try {
        parseScene("\n!genbox m box -1 2 3\n", "bad.rad", builtinLoadOptions());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().file, "bad.rad");
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_EQ(e.message().rfind("genbox: ", 0), 0u) << e.what();
    }
}

TEST(BuiltinCommands, OtherProgramsAndTheEnvironmentSwitchGoToTheShell) {
    unsetenv(kShellCommandsEnv);
    EXPECT_FALSE(runBuiltinCommand("echo void plastic x 0 0 5 1 1 1 0 0", SourceLoc{}));
    EXPECT_FALSE(runBuiltinCommand("genbox m b 1 1 1 | sort", SourceLoc{}));
    EXPECT_TRUE(runBuiltinCommand("genbox m b 1 1 1", SourceLoc{}));
    setenv(kShellCommandsEnv, "1", 1);
    EXPECT_FALSE(runBuiltinCommand("genbox m b 1 1 1", SourceLoc{}));
    setenv(kShellCommandsEnv, "0", 1);
    EXPECT_TRUE(runBuiltinCommand("genbox m b 1 1 1", SourceLoc{}));
    unsetenv(kShellCommandsEnv);
}

}  // namespace rp::gen
