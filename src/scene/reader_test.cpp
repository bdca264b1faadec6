// Scene reader tests: records, arguments, SourceLocs, numbers, modifier resolution,
// aliases, !commands, and one test per kind of bad input.
#include "scene/reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/warning_capture_for_tests.h"

namespace rp {
namespace {

std::string errorOf(const std::string& text, const std::string& file = "t.rad",
                    const LoadOptions& options = {}) {
    try {
        parseScene(text, file, options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Reader, RecordsArgumentsAndLocations) {
    Scene s = parseScene(
        "# comment line\n"
        "void plastic white\n0\n0\n5 .75 .75 .75 0 0\n"
        "\n"
        "white polygon floor 0 0 9\n  0 0 0  1 0 0\n  0 1 0\n"
        "void brightfunc sky 2 skybr skybright.cal 0 1 1\n",
        "room.rad");
    ASSERT_EQ(s.prims.size(), 3u);
    const Primitive& m = s.prims[0];
    EXPECT_EQ(m.type, PrimType::Plastic);
    EXPECT_EQ(m.name, "white");
    EXPECT_EQ(m.modifierName, "void");
    EXPECT_EQ(m.modifier, kVoid);
    EXPECT_EQ(m.rargs, (std::vector<double>{0.75, 0.75, 0.75, 0, 0}));
    EXPECT_EQ(m.loc.file, "room.rad");
    EXPECT_EQ(m.loc.line, 2);
    const Primitive& f = s.prims[1];
    EXPECT_EQ(f.type, PrimType::Polygon);
    EXPECT_EQ(f.modifier, 0);
    EXPECT_EQ(f.loc.line, 7);
    EXPECT_EQ(f.rargs.size(), 9u);
    EXPECT_EQ(s.prims[2].sargs, (std::vector<std::string>{"skybr", "skybright.cal"}));
    EXPECT_EQ(s.prims[2].loc.line, 10);
}

TEST(Reader, NumbersInEveryForm) {
    Scene s =
        parseScene("void spectrum sp 0 +0 12 1 -1. .5 +2e-3 1E+2 -0.25e1 3.E0 +4 0 7e2 1e-2 5.\n");
    ASSERT_EQ(s.prims.size(), 1u);
    EXPECT_EQ(s.prims[0].rargs,
              (std::vector<double>{1, -1, 0.5, 0.002, 100, -2.5, 3, 4, 0, 700, 0.01, 5}));
}

TEST(Reader, QuotedStringArguments) {
    Scene s = parseScene("void colorfunc c 4 \"Px * 2\" 'g b' b . 0 0\n");
    EXPECT_EQ(s.prims[0].sargs, (std::vector<std::string>{"Px * 2", "g b", "b", "."}));
}

TEST(Reader, ModifierIsMostRecentDefinition) {
    Scene s = parseScene(
        "void plastic m 0 0 5 1 0 0 0 0\n"
        "m sphere a 0 0 4 0 0 0 1\n"
        "void plastic m 0 0 5 0 1 0 0 0\n"
        "m sphere b 0 0 4 0 0 0 1\n"
        "m plastic m 0 0 5 0 0 1 0 0\n"  // modifies itself: the earlier m
        "m sphere c 0 0 4 0 0 0 1\n");
    ASSERT_EQ(s.prims.size(), 6u);
    EXPECT_EQ(s.prims[1].modifier, 0);
    EXPECT_EQ(s.prims[3].modifier, 2);
    EXPECT_EQ(s.prims[4].modifier, 2);
    EXPECT_EQ(s.prims[5].modifier, 4);
}

TEST(Reader, AliasTakesDefinition) {
    Scene s = parseScene(
        "void brightfunc pat 2 f f.cal 0 0\n"
        "pat plastic paint 0 0 5 .5 .5 .5 0 0\n"
        "inherit alias paint2 paint\n"  // keeps pat as modifier
        "void alias paint3 paint\n"     // void replaces it
        "pat alias paint4 paint3\n"     // another modifier replaces it
        "paint3 sphere s 0 0 4 0 0 0 1\n",
        "a.rad");
    ASSERT_EQ(s.prims.size(), 6u);
    for (int i : {2, 3, 4}) {
        EXPECT_EQ(s.prims[i].type, PrimType::Plastic) << i;
        EXPECT_EQ(s.prims[i].rargs, s.prims[1].rargs) << i;
        EXPECT_EQ(s.prims[i].loc.line, i + 1);
    }
    EXPECT_EQ(s.prims[2].name, "paint2");
    EXPECT_EQ(s.prims[2].modifier, 0);
    EXPECT_EQ(s.prims[3].modifier, kVoid);
    EXPECT_EQ(s.prims[4].modifier, 0);
    EXPECT_EQ(s.prims[5].modifier, 3);
    for (const auto& p : s.prims) EXPECT_NE(p.type, PrimType::Alias);
}

TEST(Reader, AliasErrors) {
    EXPECT_EQ(errorOf("void alias a nothing\n"),
              "t.rad:1: alias 'a': undefined reference 'nothing'");
    EXPECT_EQ(errorOf("void sphere s 0 0 4 0 0 0 1\nvoid alias a s\n"),
              "t.rad:2: alias 'a': cannot alias 's', a surface");
    EXPECT_EQ(errorOf("inherit sphere s 0 0 4 0 0 0 1\n"),
              "t.rad:1: sphere 's': 'inherit' is only a modifier for an alias");
}

TEST(Reader, CommandOutputIsParsedInPlace) {
    WarningCapture quiet;
    Scene s = parseScene(
        "void plastic m 0 0 5 1 1 1 0 0\n"
        "!echo m sphere s1 0 0 4 0 0 0 1; \\\n"
        "  echo m sphere s2 0 0 4 0 0 0 2\n"
        "m sphere s3 0 0 4 0 0 0 3\n"
        "!echo '!echo m sphere s4 0 0 4 0 0 0 4'\n",
        "cmd.rad");
    ASSERT_EQ(s.prims.size(), 5u);
    EXPECT_EQ(s.prims[1].name, "s1");
    EXPECT_EQ(s.prims[1].loc.file, "cmd.rad");
    EXPECT_EQ(s.prims[1].loc.line, 2);  // the command's line
    EXPECT_EQ(s.prims[2].name, "s2");
    EXPECT_EQ(s.prims[2].loc.line, 2);
    EXPECT_EQ(s.prims[3].loc.line, 4);  // continuation counted
    EXPECT_EQ(s.prims[4].name, "s4");   // nested command
    EXPECT_EQ(s.prims[4].loc.line, 5);
}

TEST(Reader, CommandHookInterceptsCommands) {
    LoadOptions opt;
    std::vector<std::string> seen;
    opt.commandHook = [&](const std::string& cmd, const SourceLoc&) -> std::optional<std::string> {
        seen.push_back(cmd);
        if (cmd.rfind("genbox", 0) == 0)
            return std::string("void plastic boxmat 0 0 5 1 1 1 0 0\n");
        return std::nullopt;
    };
    Scene s = parseScene("!genbox m b 1 2 3\n!echo void light l 0 0 3 1 1 1\n", "h.rad", opt);
    ASSERT_EQ(s.prims.size(), 2u);
    EXPECT_EQ(s.prims[0].name, "boxmat");
    EXPECT_EQ(s.prims[1].name, "l");
    EXPECT_EQ(seen,
              (std::vector<std::string>{"genbox m b 1 2 3", "echo void light l 0 0 3 1 1 1"}));
}

TEST(ReaderErrors, UnknownType) {
    EXPECT_EQ(errorOf("\nvoid plastik wall 0 0 5 1 1 1 0 0\n"), "t.rad:2: unknown type 'plastik'");
}

TEST(ReaderErrors, WrongArgumentCount) {
    EXPECT_EQ(errorOf("void plastic wall\n0\n0\n4 .5 .5 .5 0\n"),
              "t.rad:1: plastic 'wall': expected 5 real arguments, got 4");
}

TEST(ReaderErrors, NonNumericReal) {
    EXPECT_EQ(errorOf("void plastic wall\n0\n0\n5 .5 .5\n abc 0 0\n"),
              "t.rad:5: plastic 'wall': expected a real number, got 'abc'");
    EXPECT_EQ(errorOf("void plastic wall 0 0 5 1e 0 0 0 0\n"),
              "t.rad:1: plastic 'wall': expected a real number, got '1e'");
    // Beyond double range (RADIANCE's atof gives HUGE_VAL, and its oconv then crashes).
    EXPECT_EQ(errorOf("void plastic p 0 0 5 .5 .5 .5 0 0\np sphere s 0 0 4 0 0 1.4e5914 1\n"),
              "t.rad:2: sphere 's': expected a real number, got '1.4e5914'");
    EXPECT_EQ(errorOf("void plastic wall x 0 5 1 0 0 0 0\n"),
              "t.rad:1: plastic 'wall': expected the number of string arguments, got 'x'");
}

TEST(ReaderErrors, UndefinedModifier) {
    EXPECT_EQ(errorOf("void plastic a 0 0 5 1 1 1 0 0\n\nb polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
              "t.rad:3: polygon 'p': undefined modifier 'b'");
}

TEST(ReaderErrors, SurfaceAsModifier) {
    EXPECT_EQ(errorOf("void sphere s 0 0 4 0 0 0 1\ns sphere t 0 0 4 0 0 0 1\n"),
              "t.rad:2: sphere 't': 's' is a sphere, a surface, and cannot be used as a modifier");
}

TEST(ReaderErrors, TruncatedFile) {
    EXPECT_EQ(errorOf("void plastic a 0 0 5 1 1 1 0 0\nvoid plastic wall\n0\n0\n5 .5 .5\n"),
              "t.rad:2: unexpected end of file in plastic 'wall' (expected real argument 3 of 5)");
    EXPECT_EQ(errorOf("void plastic\n"),
              "t.rad:1: unexpected end of file in a primitive (expected an identifier)");
    EXPECT_EQ(errorOf("void colorfunc c 1 \"unterminated\n0 0\n"),
              "t.rad:1: unexpected end of file in colorfunc 'c' (expected string argument 1 of 1)");
}

TEST(ReaderErrors, DegeneratePolygonIsWarnedAndSkipped) {
    WarningCapture w;
    Scene s = parseScene(
        "void plastic m 0 0 5 1 1 1 0 0\n"
        "m polygon line 0 0 9 0 0 0 1 0 0 2 0 0\n"
        "m polygon dup 0 0 12 0 0 0 1 0 0 1 0 0 0 0 0\n"
        "m polygon ok 0 0 9 0 0 0 1 0 0 0 1 0\n",
        "d.rad");
    ASSERT_EQ(s.prims.size(), 2u);
    EXPECT_EQ(s.prims[1].name, "ok");
    ASSERT_EQ(w.lines.size(), 2u);
    EXPECT_EQ(w.lines[0], "d.rad:2: polygon 'line': degenerate polygon (zero area), skipped");
    EXPECT_EQ(w.lines[1], "d.rad:3: polygon 'dup': degenerate polygon (zero area), skipped");
}

TEST(ReaderErrors, MissingFile) {
    SceneReader r;
    try {
        r.readFile("/nonexistent/dir/room.rad");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/dir/room.rad: cannot open file", 0), 0u)
            << e.what();
    }
}

TEST(ReaderErrors, FailingCommand) {
    EXPECT_EQ(errorOf("void plastic a 0 0 5 1 1 1 0 0\n\n!exit 3\n"),
              "t.rad:3: command failed with exit status 3: !exit 3");
    // An error in a command's output points at the command's line.
    WarningCapture quiet;
    EXPECT_EQ(errorOf("\n!echo void plastic w 0 0 1 2\n"),
              "t.rad:2: plastic 'w': expected 5 real arguments, got 1 (in output of !echo void "
              "plastic w 0 0 1 2)");
}

TEST(ReaderErrors, InstanceAndMeshArguments) {
    EXPECT_EQ(errorOf("void instance i 0 0 0\n"),
              "t.rad:1: instance 'i': expected at least 1 string argument, got 0");
    EXPECT_EQ(errorOf("void mesh m 3 m.rtm -s x 0 0\n").substr(0, 17), "t.rad:1: mesh 'm'");
}

}  // namespace
}  // namespace rp
