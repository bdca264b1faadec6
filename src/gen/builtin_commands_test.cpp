// Scene files' generator commands run in-process (no RADIANCE on PATH needed), pipelines
// included; what needs a shell still goes to the shell.
#include "gen/builtin_commands.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "calc/search_path.h"
#include "gen/genblinds.h"
#include "gen/genrev.h"
#include "gen/gensurf.h"
#include "gen/genworm.h"
#include "scene/reader.h"
#include "scene/scene_load.h"
#include "util/shared_for_tests.h"
#include "util/warnings.h"

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
    Scene s = parseScene(
        "void plastic m\n0\n0\n5 .5 .5 .5 0 0\n"
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

// Exported scenes nest commands (issue 43): room.rad runs !xform ./objects/walls.rad,
// whose own !xform and !genbox lines run in-process too, and as RADIANCE's xform runs
// them, in that file's folder (./inner.rad is objects/inner.rad). PATH is emptied: a
// command handed to /bin/sh would fail ("sh: 1: xform: not found").
TEST(BuiltinCommands, CommandsInFilesThatXformReadsRunInProcess) {
    unsetenv(kShellCommandsEnv);
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(testing::TempDir()) / "builtin_nested";
    fs::create_directories(dir / "objects");
    std::ofstream(dir / "objects" / "walls.rad") << "wall polygon w 0 0 9 0 0 0 1 0 0 0 1 0\n"
                                                    "!xform -t 0 0 2 ./inner.rad\n"
                                                    "!genbox wall box 1 1 1 | xform -t 5 0 0\n";
    std::ofstream(dir / "objects" / "inner.rad") << "wall sphere ball 0 0 4 0 0 0 .5\n";
    const std::string room = (dir / "room.rad").string();
    std::ofstream(room) << "void plastic wall 0 0 5 .5 .5 .5 0 0\n!xform " +
                               (dir / "objects" / "walls.rad").string() + "\n";
    const char* oldPath = std::getenv("PATH");
    const std::string savedPath = oldPath ? oldPath : "";
    setenv("PATH", "", 1);
    Scene s;
    try {
        s = loadScene({room}, builtinLoadOptions());
    } catch (...) {
        setenv("PATH", savedPath.c_str(), 1);
        throw;
    }
    setenv("PATH", savedPath.c_str(), 1);
    std::map<PrimType, int> count;
    for (const Primitive& p : s.prims) ++count[p.type];
    EXPECT_EQ(count[PrimType::Polygon], 1 + 6);
    ASSERT_EQ(count[PrimType::Sphere], 1);
    for (const Primitive& p : s.prims) {
        if (p.type == PrimType::Sphere) {
            EXPECT_DOUBLE_EQ(p.rargs[2], 2);  // moved by the inner -t
        }
    }
}

// A file that includes itself through !xform, directly or through another, stops with
// an error at the command that closes the loop (RADIANCE recurses until it runs out).
TEST(BuiltinCommands, SceneFileIncludingItselfIsAnError) {
    unsetenv(kShellCommandsEnv);
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(testing::TempDir()) / "builtin_loop";
    fs::create_directories(dir);
    const std::string a = (dir / "a.rad").string(), b = (dir / "b.rad").string();
    std::ofstream(a) << "void plastic m 0 0 5 .5 .5 .5 0 0\n!xform " << a << "\n";
    std::ofstream(b) << "\n\n!xform -t 1 0 0 " << a << "\n";
    for (const std::string& top : {a, b}) {
        try {
            loadScene({top}, builtinLoadOptions());
            ADD_FAILURE() << "no error for " << top;
        } catch (const InputError& e) {
            EXPECT_EQ(e.loc().file, a) << e.what();
            EXPECT_EQ(e.loc().line, 2) << e.what();
            EXPECT_NE(e.message().find("scene file includes itself"), std::string::npos)
                << e.what();
        }
    }
}

// genblinds, genrev, gensurf and genworm run in-process with exactly the text their
// tools print (the tools are thin mains around the same functions).
TEST(BuiltinCommands, BlindsRevSurfWormRunInProcess) {
    unsetenv(kShellCommandsEnv);
    auto path = calc::defaultSearchPath("");
    std::vector<std::string> warnings;
    auto blinds = runBuiltinCommand("genblinds m slat 0.05 1 0.5 2 -30 +r 0.15", SourceLoc{});
    ASSERT_TRUE(blinds);
    EXPECT_EQ(*blinds,
              genblinds({"genblinds", "m", "slat", "0.05", "1", "0.5", "2", "-30", "+r", "0.15"}));
    auto rev = runBuiltinCommand("genrev steel torus 'sin(2*PI*t)' '1+cos(2*PI*t)' 4", SourceLoc{});
    ASSERT_TRUE(rev);
    EXPECT_EQ(*rev, genrev({"genrev", "steel", "torus", "sin(2*PI*t)", "1+cos(2*PI*t)", "4"}, path,
                           warnings));
    auto worm =
        runBuiltinCommand("genworm m w 0 0 t 'if(t-.6,small,.5)' 2 -e 'small = .25'", SourceLoc{});
    ASSERT_TRUE(worm);
    EXPECT_EQ(*worm, genworm({"genworm", "m", "w", "0", "0", "t", "if(t-.6,small,.5)", "2", "-e",
                              "small = .25"},
                             path, warnings));
    auto surf = runBuiltinCommand("gensurf m p 'sx*s' t 0 2 2 -e 'sx = 2'", SourceLoc{});
    ASSERT_TRUE(surf);
    std::istringstream none;
    EXPECT_EQ(*surf, gensurf({"gensurf", "m", "p", "sx*s", "t", "0", "2", "2", "-e", "sx = 2"},
                             path, none, warnings));
    EXPECT_NE(surf->find("# gensurf m p sx*s t 0 2 2 -e \"sx = 2\"\n"), std::string::npos);
    EXPECT_TRUE(warnings.empty());
}

// A scene with each of them loads without any generator on PATH.
TEST(BuiltinCommands, BlindsRevSurfWormInAScene) {
    unsetenv(kShellCommandsEnv);
    Scene s = parseScene(
        "void plastic m 0 0 5 .5 .5 .5 0 0\n"
        "!genblinds m slat 0.05 1 0.5 2 20 -r 0.2 | xform -rz 90\n"
        "!genrev m can 't' '1' 2\n"
        "!genworm m w 0 0 t .1 2\n"
        "!gensurf m p s t 0 2 2\n",
        "gens.rad", builtinLoadOptions());
    std::map<PrimType, int> count;
    for (const Primitive& p : s.prims) ++count[p.type];
    EXPECT_EQ(count[PrimType::Polygon], 2 * 5 + 4);  // 5 facets per curved slat; 2 x 2 cells
    EXPECT_EQ(count[PrimType::Cylinder], 2 + 2);     // genrev's 2 segments, genworm's 2 links
    EXPECT_EQ(count[PrimType::Sphere], 3);
    EXPECT_EQ(s.prims.size(), 1u + 14u + 4u + 3u);
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

// Every scene of ../shared/validation loads as the tools load it (generators such as
// !genblinds | xform in-process, no PATH needed), without a warning.
TEST(Validation, EverySharedSceneLoads) {
    RP_REQUIRE_SHARED("validation");
    setWarningSink([](const std::string& m) { ADD_FAILURE() << "warning: " << m; });
    std::filesystem::path root = std::filesystem::path(RP_SHARED_DIR) / "validation";
    int scenes = 0;
    for (const auto& dir : std::filesystem::directory_iterator(root)) {
        if (!dir.is_directory()) continue;
        for (const auto& f : std::filesystem::directory_iterator(dir.path())) {
            if (f.path().extension() != ".rad") continue;
            SCOPED_TRACE(f.path().string());
            Scene s = loadScene({f.path().string()}, builtinLoadOptions());
            EXPECT_GT(s.prims.size(), 0u);
            ++scenes;
        }
    }
    setWarningSink(nullptr);
    EXPECT_GE(scenes, 6);
    Scene cornell = loadScene({RP_SHARED_DIR "/validation/cornell/scene.rad"});
    EXPECT_EQ(cornell.prims[0].name, "white");
    EXPECT_EQ(cornell.prims[0].loc.line, 5);
}

}  // namespace rp::gen

namespace rp::gen {

// mgf2rad runs in-process (here on genBSDF's blinds MGF, through xform); its MGF errors
// keep the MGF file and line inside the scene line's message.
TEST(BuiltinCommands, Mgf2radAndPkgBsdfRunInProcess) {
    unsetenv(kShellCommandsEnv);
    std::string mgf = std::string(RP_SOURCE_DIR) + "/tests/data/mgf/genbsdf_blinds.mgf";
    Scene s =
        parseScene("!mgf2rad " + mgf + " | xform -t 0 0 1\n", "win.rad", builtinLoadOptions());
    size_t polygons = 0;
    for (const Primitive& p : s.prims) polygons += p.type == PrimType::Polygon;
    EXPECT_EQ(polygons, 45u);
    std::string bad = testing::TempDir() + "builtin_bad.mgf";
    {
        std::ofstream f(bad);
        f << "# two\nf a b c\n";
    }
    try {
        parseScene("!mgf2rad " + bad + "\n", "win.rad", builtinLoadOptions());
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "win.rad:1: mgf2rad: " + bad + ":2: Undefined reference: f a b c");
    }
    try {
        parseScene("!pkgBSDF -s nowhere_at_all.xml\n", "win.rad", builtinLoadOptions());
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "win.rad:1: pkgBSDF: nowhere_at_all.xml: cannot find BSDF file");
    }
}

}  // namespace rp::gen
