// The #@mkillum variables: RADIANCE mkillum.c xoptions' rules, one test per kind of bad
// word, and the -defaults text (RADIANCE 5.4's `mkillum -defaults`, first lines).
#include "illum/illum_settings.h"

#include <gtest/gtest.h>

namespace rp::illum {
namespace {

const SourceLoc kLoc{"in.rad", 7};

IllumSettings apply(const std::string& line, IllumSettings s = {}) {
    applyOptionLine(line, s, kLoc);
    return s;
}

std::string errorOf(const std::string& line) {
    IllumSettings s;
    try {
        applyOptionLine(line, s, kLoc);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(IllumSettings, RecognisesOptionLines) {
    EXPECT_TRUE(isOptionLine("#@mkillum i=glass\n"));
    EXPECT_TRUE(isOptionLine("#@mkillum"));
    EXPECT_TRUE(isOptionLine("#@mkillum\tc=a"));
    EXPECT_FALSE(isOptionLine("#@mkillumx i=glass"));
    EXPECT_FALSE(isOptionLine("# mkillum i=glass"));
    EXPECT_FALSE(isOptionLine("#@mkill"));
}

TEST(IllumSettings, MaterialNamesTheDataFileUnlessFileGiven) {
    IllumSettings s = apply("#@mkillum m=win");
    EXPECT_EQ(s.material, "win");
    EXPECT_EQ(s.dataFile, "win");
    EXPECT_FALSE(s.clobber);
    s = apply("#@mkillum f=data m=other", s);
    EXPECT_EQ(s.material, "other");
    EXPECT_EQ(s.dataFile, "data");
    EXPECT_TRUE(s.clobber);
    s.dataFileNumber = 3;
    s = apply("#@mkillum f=", s);  // back to the material's name, not clobbered
    EXPECT_EQ(s.dataFile, "other");
    EXPECT_EQ(s.dataFileNumber, 0);
    EXPECT_FALSE(s.clobber);
}

TEST(IllumSettings, Selection) {
    IllumSettings s = apply("#@mkillum i=glass");
    EXPECT_TRUE(s.selects("glass"));
    EXPECT_FALSE(s.selects("wall"));
    s = apply("#@mkillum e=glass");
    EXPECT_FALSE(s.selects("glass"));
    EXPECT_TRUE(s.selects("wall"));
    s = apply("#@mkillum n", s);
    EXPECT_FALSE(s.selects("wall"));
    s = apply("#@mkillum a", s);
    EXPECT_TRUE(s.selects("glass"));
    EXPECT_TRUE(apply("#@mkillum i=void").selects("void"));
}

TEST(IllumSettings, Values) {
    IllumSettings s = apply("#@mkillum c=d d=100 s=128 b=.5 l+");
    EXPECT_EQ(s.colour, ColourMode::kDistribution);
    EXPECT_EQ(s.density, 100);
    EXPECT_EQ(s.samples, 128);
    EXPECT_DOUBLE_EQ(s.minBrightness, 0.5);
    EXPECT_TRUE(s.light);
    s = apply("#@mkillum c=avg l- d= b=-3", s);  // RADIANCE: c= reads one letter
    EXPECT_EQ(s.colour, ColourMode::kAverage);
    EXPECT_FALSE(s.light);
    EXPECT_EQ(s.density, 100);  // "d=" alone leaves it
    EXPECT_EQ(s.minBrightness, 0);
    EXPECT_EQ(apply("#@mkillum c=n", s).colour, ColourMode::kNone);
}

TEST(IllumSettings, OutputFileAndProcessedMark) {
    IllumSettings s;
    OptionLine o = applyOptionLine("#@mkillum o=rest.rad m=x\n", s, kLoc);
    ASSERT_TRUE(o.outputFile);
    EXPECT_EQ(*o.outputFile, "rest.rad");
    EXPECT_EQ(s.material, "x");
    o = applyOptionLine("#@mkillum ! whatever=1", s, kLoc);
    EXPECT_TRUE(o.processed);
}

TEST(IllumSettings, BadWordsAreErrorsAtTheLine) {
    EXPECT_EQ(errorOf("#@mkillum d=x"),
              "in.rad:7: bad #@mkillum option 'd=x': expected an integer density (BSDF input "
              "is not supported)");
    EXPECT_NE(errorOf("#@mkillum q=1").find("'q=1': unknown variable"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum glass").find("'glass': unknown variable"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum s=many").find("'s=many'"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum s=-2").find("'s=-2'"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum b=bright").find("'b=bright'"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum c=x").find("'c=x'"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum l").find("expected l+ or l-"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum m=").find("'m='"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum i=").find("'i='"), std::string::npos);
    EXPECT_NE(errorOf("#@mkillum o=").find("'o='"), std::string::npos);
}

TEST(IllumSettings, DefaultsText) {
    EXPECT_EQ(formatSettings(IllumSettings{}),
              "m=illum_mat      \t\t# material name\n"
              "f=illum          \t\t# data file name\n"
              "c=n\t\t\t\t# color none\n"
              "l-\t\t\t\t# light type off\n"
              "d=48\t\t\t\t# density of directions\n"
              "s=32\t\t\t\t# samples per direction\n"
              "b=0.000000\t\t\t# minimum average brightness\n");
}

}  // namespace
}  // namespace rp::illum
