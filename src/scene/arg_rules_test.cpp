// Argument rules, value checks, number syntax and transform parsing.
#include "scene/arg_rules.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/lexer.h"
#include "scene/reader.h"
#include "scene/xform.h"
#include "util/warnings.h"

namespace rp {
namespace {

std::string errorOf(const std::string& text) {
    try {
        parseScene(text, "t.rad");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Numbers, RealAndIntegerSyntax) {
    double d;
    for (const char* ok : {"1", "-1.", ".5", "+2e-3", "1E+2", "0", "-0.0", "3.e5"})
        EXPECT_TRUE(parseReal(ok, d)) << ok;
    for (const char* bad :
         {"abc", "", ".", "-", "1e", "1e+", "inf", "nan", "0x10", "1.5x", "--1", "1..2"})
        EXPECT_FALSE(parseReal(bad, d)) << bad;
    long n;
    EXPECT_TRUE(parseInteger("+12", n));
    EXPECT_EQ(n, 12);
    EXPECT_TRUE(parseInteger("-3", n));
    EXPECT_EQ(n, -3);
    for (const char* bad : {"1.0", "x", "", "+", "1e2"}) EXPECT_FALSE(parseInteger(bad, n)) << bad;
}

TEST(ArgRules, CountPatterns) {
    EXPECT_EQ(errorOf("void glass g 0 0 5 1 1 1 1.5 0\n"),
              "t.rad:1: glass 'g': expected 3 or 4 real arguments, got 5");
    EXPECT_EQ(errorOf("void glass g 0 0 4 1 1 1 1.5\n"), "(no error)");
    EXPECT_EQ(errorOf("void illum i 2 a b 0 3 1 1 1\n"),
              "t.rad:1: illum 'i': expected 0 or 1 string arguments, got 2");
    EXPECT_EQ(errorOf("void mirror m 1 void 0 3 1 1 1\n"), "(no error)");
    EXPECT_EQ(errorOf("void mist m 0 0 4 1 1 1 1\n"),
              "t.rad:1: mist 'm': expected 0, 3, 6 or 7 real arguments, got 4");
    EXPECT_EQ(errorOf("void plastic p 0 0 5 1 1 1 0 0\np polygon q 0 0 10 0 0 0 1 0 0 0 1 0 7\n"),
              "t.rad:2: polygon 'q': expected a multiple of 3 real arguments (at least 9), got 10");
    EXPECT_EQ(errorOf("void plastic p 0 0 5 1 1 1 0 0\np polygon q 0 0 6 0 0 0 1 0 0\n"),
              "t.rad:2: polygon 'q': expected a multiple of 3 real arguments (at least 9), got 6");
    EXPECT_EQ(errorOf("void BRTDfunc b 9 0 0 0 0 0 0 0 0 0 0 9 0 0 0 0 0 0 0 0 0\n"),
              "t.rad:1: BRTDfunc 'b': expected at least 10 string arguments, got 9");
    EXPECT_EQ(errorOf("void plastic p 0 1 7 5 1 1 1 0 0\n"),
              "t.rad:1: plastic 'p': expected 0 integer arguments, got 1");
    EXPECT_EQ(errorOf("void light l 1 x 0 3 1 1 1\n"),
              "t.rad:1: light 'l': expected 0 string arguments, got 1");
    EXPECT_EQ(errorOf("void BSDF b 6 0 f.xml 0 0 1 . 0 3 .1 .1 .1\n"), "(no error)");
    EXPECT_EQ(errorOf("void specfile s 1 d65.dat 0 0\n"), "(no error)");
}

TEST(ArgRules, TransformArgumentsChecked) {
    EXPECT_EQ(errorOf("void colorfunc c 17 r g b f.cal -t 1 2 3 -rz 90 -s 2 -mx -i 2 -ry 5 0 0\n"),
              "(no error)");
    EXPECT_EQ(errorOf("void colorfunc c 5 r g b f.cal -q 0 0\n"),
              "t.rad:1: colorfunc 'c': bad transform argument '-q'");
    EXPECT_EQ(errorOf("void brightfunc c 4 r f.cal -t 1\n0 0\n"),
              "t.rad:1: brightfunc 'c': transform option -t: missing value");
    EXPECT_EQ(errorOf("void brightfunc c 4 r f.cal -s x 0 0\n"),
              "t.rad:1: brightfunc 'c': transform option -s: expected a real number, got 'x'");
    // Data types: coordinate functions first, then the transform.
    EXPECT_EQ(errorOf("void brightdata d 7 f d.dat f.cal Px-1 Py -s 2 0 0\n"), "(no error)");
}

TEST(ArgRules, ValueChecksAsRadiance) {
    std::vector<std::string> warnings;
    setWarningSink([&](const std::string& m) { warnings.push_back(m); });
    Scene s = parseScene(
        "void plastic m 0 0 5 1 1 1 0 0\n"
        "m sphere s 0 0 4 0 0 0 -1\n"
        "m cylinder c 0 0 7 0 0 0 0 0 1 -1\n"
        "m cone k 0 0 8 0 0 0 0 0 1 -1 0\n",
        "v.rad");
    setWarningSink(nullptr);
    EXPECT_EQ(s.prims[1].type, PrimType::Bubble);
    EXPECT_EQ(s.prims[1].rargs[3], 1);
    EXPECT_EQ(s.prims[2].type, PrimType::Tube);
    EXPECT_EQ(s.prims[3].type, PrimType::Cup);
    EXPECT_EQ(s.prims[3].rargs[6], 1);
    EXPECT_EQ(warnings.size(), 3u);
    EXPECT_EQ(warnings[0], "v.rad:2: sphere 's': negative radius, made a bubble");

    std::string m = "void plastic m 0 0 5 1 1 1 0 0\n";
    EXPECT_EQ(errorOf(m + "m sphere s 0 0 4 0 0 0 0\n"), "t.rad:2: sphere 's': zero radius");
    EXPECT_EQ(errorOf(m + "m cone c 0 0 8 0 0 0 0 0 1 0 0\n"), "t.rad:2: cone 'c': illegal radii");
    EXPECT_EQ(errorOf(m + "m cone c 0 0 8 0 0 0 0 0 1 1 -1\n"), "t.rad:2: cone 'c': illegal radii");
    EXPECT_EQ(errorOf(m + "m ring r 0 0 8 0 0 0 0 0 1 -1 -2\n"),
              "t.rad:2: ring 'r': negative radii");
    EXPECT_EQ(errorOf(m + "m ring r 0 0 8 0 0 0 0 0 0 0 1\n"),
              "t.rad:2: ring 'r': zero orientation");
    EXPECT_EQ(errorOf(m + "m cylinder c 0 0 7 1 1 1 1 1 1 1\n"),
              "t.rad:2: cylinder 'c': zero orientation");
    EXPECT_EQ(errorOf(m + "m ring r 0 0 8 0 0 0 0 0 1 0 1\n"), "(no error)");
}

TEST(Xform, OptionsApplyInOrder) {
    SourceLoc loc{"x.rad", 3};
    auto near = [](std::array<double, 3> a, std::array<double, 3> b) {
        for (int i = 0; i < 3; ++i)
            if (std::fabs(a[i] - b[i]) > 1e-12) return false;
        return true;
    };
    // Rotate then translate: (1,0,0) -> (0,1,0) -> (0,1,5).
    Transform t = parseTransform({"f.cal", "-rz", "90", "-t", "0", "0", "5"}, 1, loc);
    EXPECT_TRUE(near(t.point({1, 0, 0}), {0, 1, 5}));
    // Translate then rotate: the origin goes to (0,0,5), then about x to (0,-5,0).
    Transform u = parseTransform({"-t", "0", "0", "5", "-rx", "90"}, 0, loc);
    EXPECT_TRUE(near(u.point({0, 0, 0}), {0, -5, 0}));
    EXPECT_TRUE(near(parseTransform({"-ry", "90"}, 0, loc).point({0, 0, 1}), {1, 0, 0}));
    Transform s = parseTransform({"-s", "-2", "-my"}, 0, loc);
    EXPECT_EQ(s.scale, 2);
    EXPECT_TRUE(near(s.point({1, 1, 1}), {-2, 2, -2}));
    EXPECT_TRUE(parseTransform({"-mz"}, 0, loc).mirrors());
    // -i repeats the options that follow it.
    Transform r = parseTransform({"-t", "1", "0", "0", "-i", "3", "-t", "0", "2", "0"}, 0, loc);
    EXPECT_TRUE(near(r.point({0, 0, 0}), {1, 6, 0}));
    EXPECT_TRUE(parseTransform({"-i", "0", "-t", "1", "1", "1"}, 0, loc).isIdentity());
    EXPECT_TRUE(parseTransform({}, 0, loc).isIdentity());
}

TEST(Xform, BadArgumentsAreInputErrors) {
    SourceLoc loc{"x.rad", 3};
    EXPECT_THROW(parseTransform({"-t", "1", "2"}, 0, loc), InputError);
    EXPECT_THROW(parseTransform({"-s", "0"}, 0, loc), InputError);
    EXPECT_THROW(parseTransform({"-i", "-1"}, 0, loc), InputError);
    EXPECT_THROW(parseTransform({"-rq", "1"}, 0, loc), InputError);
    EXPECT_THROW(parseTransform({"1"}, 0, loc), InputError);
    try {
        parseTransform({"-rx", "abc"}, 0, loc);
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "x.rad:3: transform option -rx: expected a real number, got 'abc'");
    }
}

}  // namespace
TEST(Transform, InverseUndoesASimilarity) {
    Transform t =
        parseTransform({"-s", "2.5", "-rx", "30", "-mz", "-rz", "-75", "-t", "1", "-2", "3"}, 0,
                       SourceLoc{"t.rad", 1});
    Transform inv = t.inverse();
    auto p = inv.point(t.point({0.3, -4, 7}));
    EXPECT_NEAR(p[0], 0.3, 1e-12);
    EXPECT_NEAR(p[1], -4, 1e-12);
    EXPECT_NEAR(p[2], 7, 1e-12);
    auto d = inv.direction(t.direction({1, 2, 3}));
    EXPECT_NEAR(d[0], 1, 1e-12);
    EXPECT_NEAR(d[1], 2, 1e-12);
    EXPECT_NEAR(d[2], 3, 1e-12);
    EXPECT_NEAR(inv.scale, 0.4, 1e-15);
    EXPECT_TRUE((t * inv).isIdentity() || std::fabs((t * inv).m[0][0] - 1) < 1e-12);
}

}  // namespace rp
