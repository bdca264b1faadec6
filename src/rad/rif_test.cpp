// RIF variables: RADIANCE 5.4 loadvars.c semantics (lines, escapes, comments,
// abbreviations, joining, checks) and printvars' listing.
#include "rad/rif.h"

#include <gtest/gtest.h>

#include <fstream>

#include "util/temp_dir_for_tests.h"
#include "util/warning_capture_for_tests.h"

namespace rp::rad {
namespace {

RifVars loaded(const std::string& text, const TempDir& dir) {
    const std::string path = dir.file("t.rif");
    std::ofstream(path) << text;
    RifVars v;
    v.load(path);
    return v;
}

TEST(Rif, AbbreviationsNeedTheirNickLength) {
    Var v;
    ASSERT_TRUE(matchVar("QUA", v));
    EXPECT_EQ(v, Var::kQuality);
    ASSERT_TRUE(matchVar("PG", v));  // PGMAP takes two
    EXPECT_EQ(v, Var::kPgmap);
    ASSERT_TRUE(matchVar("PC", v));
    EXPECT_EQ(v, Var::kPcmap);
    EXPECT_FALSE(matchVar("QU", v));
    EXPECT_FALSE(matchVar("QUALITYX", v));  // longer than the name
    EXPECT_FALSE(matchVar("quality", v));   // case matters
    ASSERT_TRUE(matchVar("view", v));
    EXPECT_EQ(v, Var::kViews);
    ASSERT_TRUE(matchVar("mat", v));
    EXPECT_EQ(v, Var::kMaterial);
    ASSERT_TRUE(matchVar("mkp", v));
    EXPECT_EQ(v, Var::kMkpmap);
}

TEST(Rif, LinesContinueCommentsEndThemAndSpacesSqueeze) {
    TempDir dir;
    RifVars v = loaded(
        "# a comment\n"
        "scene = a.rad   b.rad \\\n"
        "   c.rad # the rest\n"
        "render = -av 1 1 1 \\# not a comment\n"
        "EXPOSURE=\n"  // no value: nothing
        "  \n"
        "PICT  =  out\r\n",
        dir);
    v.check(true);
    EXPECT_EQ(v.value(Var::kScene), "a.rad b.rad c.rad");
    EXPECT_EQ(v.value(Var::kRender), "-av 1 1 1 # not a comment");
    EXPECT_FALSE(v.defined(Var::kExposure));
    EXPECT_EQ(v.value(Var::kPicture), "out");
}

TEST(Rif, UnknownVariableNamesFileAndLine) {
    TempDir dir;
    try {
        loaded("scene = a.rad\n\\\n\nFOO = 1\n", dir);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().line, 4);
        EXPECT_NE(std::string(e.what()).find("unknown variable: FOO = 1"), std::string::npos);
    }
}

TEST(Rif, ListsJoinOneValuesKeepTheLastWithAWarning) {
    RifVars v;
    ASSERT_TRUE(v.assign("scene= a.rad", SourceLoc{"x.rif", 1}));
    ASSERT_TRUE(v.assign("scene b.rad c.rad", SourceLoc{"x.rif", 2}));
    ASSERT_TRUE(v.assign("QUAL= Low", SourceLoc{"x.rif", 3}));
    ASSERT_TRUE(v.assign("QUAL= hi", SourceLoc{"x.rif", 4}));
    ASSERT_TRUE(v.assign("view= a -vf a.vf", SourceLoc{"x.rif", 5}));
    ASSERT_TRUE(v.assign("view= b -vf b.vf", SourceLoc{"x.rif", 6}));
    EXPECT_FALSE(v.assign("NOPE= 1", SourceLoc{}));
    WarningCapture w;
    v.check(true);
    EXPECT_TRUE(w.any("multiple assignment of variable 'QUALITY'"));
    EXPECT_EQ(v.value(Var::kScene), "a.rad b.rad c.rad");
    EXPECT_EQ(v.assignments(Var::kScene).size(), 2u);  // each with its line
    EXPECT_EQ(v.assignments(Var::kScene)[1].loc.line, 2);
    EXPECT_EQ(v.value(Var::kQuality), "hi");
    EXPECT_EQ(v.letter(Var::kQuality), 'H');
    ASSERT_NE(v.nth(Var::kViews, 1), nullptr);
    EXPECT_EQ(v.nth(Var::kViews, 1)->value, "b -vf b.vf");
    EXPECT_EQ(v.nth(Var::kViews, 2), nullptr);
}

TEST(Rif, IllegalValuesAreErrorsAtTheirLine) {
    auto error = [](const std::string& assignment) {
        RifVars v;
        EXPECT_TRUE(v.assign(assignment, SourceLoc{"x.rif", 7}));
        try {
            v.check(false);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error("QUAL= Lower"), "x.rif:7: illegal value for qualitative variable 'QUALITY'");
    EXPECT_EQ(error("DET= x"), "x.rif:7: illegal value for qualitative variable 'DETAIL'");
    EXPECT_EQ(error("PEN= yes"), "x.rif:7: illegal value for boolean variable 'PENUMBRAS'");
    EXPECT_EQ(error("IND= 1.5"), "x.rif:7: illegal value for integer variable 'INDIRECT'");
    EXPECT_EQ(error("EXP= +x"), "x.rif:7: illegal value for real variable 'EXPOSURE'");
    EXPECT_EQ(error("EXP= 2e"), "x.rif:7: illegal value for real variable 'EXPOSURE'");
    EXPECT_EQ(error("QUAL= m"), "");
    EXPECT_EQ(error("PEN= T"), "");
    EXPECT_EQ(error("EXP= -2.5e-1"), "");
    EXPECT_EQ(error("IND= +3"), "");
}

TEST(Rif, ListingBreaksLongListsAsPrintvars) {
    RifVars v;
    std::string files;
    for (int i = 0; i < 12; ++i) files += " file" + std::to_string(i) + ".rad";
    ASSERT_TRUE(v.assign("objects=" + files, SourceLoc{}));
    ASSERT_TRUE(v.assign("ZONE= I 0 1 0 1 0 1", SourceLoc{}));
    v.check(false);
    // 64 - strlen("objects") = 57 characters, then the word is finished.
    EXPECT_EQ(v.listing(),
              "objects= file0.rad file1.rad file2.rad file3.rad file4.rad file5.rad\n"
              "objects= file6.rad file7.rad file8.rad file9.rad file10.rad file11.rad\n"
              "ZONE= I 0 1 0 1 0 1\n");
}

TEST(Rif, ValueWordsKeepQuotedCommandsWhole) {
    EXPECT_EQ(valueWords("a.rad \"!xform -t 1 2 3 b.rad\" 'c d' e"),
              (std::vector<std::string>{"a.rad", "!xform -t 1 2 3 b.rad", "c d", "e"}));
}

}  // namespace
}  // namespace rp::rad
