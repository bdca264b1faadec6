// Tests for mgf2rad: RADIANCE's mgf2rad output for every material kind and every surface
// kind (tests/data/gen_radiance/mgf2rad_*.rad, made from tests/data/mgf/*.mgf as their
// "## mgf2rad FILE" line shows, run in that folder), compared number by number since
// floats may round differently in the last printed digit; the genBSDF MGF of the
// validation blinds; colour conversion; and one test per kind of bad input.
#include "gen/mgf2rad.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "gen/mgf_color.h"
#include "gen/test_reference.h"
#include "util/error.h"

namespace rp::gen {
namespace {

const std::string kData = std::string(RP_SOURCE_DIR) + "/tests/data/mgf/";

std::vector<std::string> tokens(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> t;
    for (std::string w; in >> w;) t.push_back(w);
    return t;
}

bool isNumber(const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

// Word-for-word equality, numbers within one unit of the last printed digit (%f prints
// six decimals; %18.12g twelve significant digits).
::testing::AssertionResult sameScene(const std::string& got, const std::string& want) {
    auto g = tokens(got), w = tokens(want);
    for (size_t i = 0; i < std::min(g.size(), w.size()); ++i) {
        double a, b;
        bool same = g[i] == w[i] || (isNumber(g[i], a) && isNumber(w[i], b) &&
                                     std::fabs(a - b) <= 1.5e-6 + 1e-9 * std::fabs(b));
        if (!same)
            return ::testing::AssertionFailure()
                   << "word " << i << ": got '" << g[i] << "', RADIANCE '" << w[i] << "'";
    }
    if (g.size() != w.size())
        return ::testing::AssertionFailure() << g.size() << " words, RADIANCE " << w.size() << "\n"
                                             << got;
    return ::testing::AssertionSuccess();
}

std::string convertFile(const std::string& file) {
    std::vector<std::string> warnings;
    std::string out = mgf2rad({"mgf2rad", kData + file}, "", warnings);
    // The header names the file as given; RADIANCE ran in the data folder.
    for (size_t p; (p = out.find(kData)) != std::string::npos;) out.erase(p, kData.size());
    return out;
}

TEST(Mgf2rad, MaterialsMatchRadiance) {
    auto ref = testing::readReferenceOutput("mgf2rad_materials.rad");
    EXPECT_TRUE(sameScene(convertFile("materials.mgf"), ref.text));
}

TEST(Mgf2rad, ShapesTransformsArraysAndIncludesMatchRadiance) {
    auto ref = testing::readReferenceOutput("mgf2rad_shapes.rad");
    EXPECT_TRUE(sameScene(convertFile("shapes.mgf"), ref.text));
}

// genBSDF's <MGFblock> of the validation blinds (tests/data/mgf/genbsdf_blinds.mgf, cut
// from shared/validation/bsdf/blinds_klems.xml): materials, xf -t, o, v/p and f.
TEST(Mgf2rad, GenbsdfBlindsMatchRadiance) {
    auto ref = testing::readReferenceOutput("mgf2rad_genbsdf_blinds.rad");
    EXPECT_TRUE(sameScene(convertFile("genbsdf_blinds.mgf"), ref.text));
}

// RADIANCE dithers spectral samples with glibc's rand() (never seeded): the sequence
// must be glibc's, 1804289383, 846930886, 1681692777 ... (a C program printing rand()).
TEST(MgfColor, DitherIsGlibcRand) {
    MgfDither d;
    for (double r : {1804289383.0, 846930886.0, 1681692777.0, 1714636915.0, 1957747793.0})
        EXPECT_DOUBLE_EQ(d.next(), r / (2147483647 + .5));
}

TEST(MgfColor, WhiteIsGreyAndSaturatedColoursAreClippedToTheGamut) {
    MgfColor white;
    EXPECT_TRUE(white.isGrey());
    auto rgb = mgfColorToRgb(white, 0.5);
    for (float c : rgb) EXPECT_NEAR(c, 0.5, 1e-5);  // equal-energy white is RADIANCE's white
    MgfColor green;
    ASSERT_TRUE(green.setXy(0.1, 0.8));
    EXPECT_FALSE(green.isGrey());
    rgb = mgfColorToRgb(green, 0.5);
    for (float c : rgb) EXPECT_GE(c, 0);  // outside the primaries: desaturated, not negative
    EXPECT_GT(rgb[1], rgb[0]);
    EXPECT_FALSE(green.setXy(0.7, 0.5));  // x + y > 1
}

// Spectra and colour temperatures go through xy exactly as RADIANCE's (materials.mgf
// covers them against RADIANCE); here the physics: a 3000 K black body is reddish.
TEST(MgfColor, BlackBodyAndSpectrum) {
    MgfDither d;
    MgfColor warm;
    ASSERT_TRUE(warm.setBlackBody(3000, d));
    warm.convert(MgfColor::XySet);
    EXPECT_NEAR(warm.x, 0.437, 0.005);  // CIE 1931 Planckian locus at 3000 K: (0.437, 0.404)
    EXPECT_NEAR(warm.y, 0.404, 0.005);
    EXPECT_FALSE(warm.setBlackBody(900, d));
    MgfColor flat;
    ASSERT_TRUE(flat.setSpectrum(380, 780, std::vector<float>(41, 1.f), d));
    EXPECT_TRUE(flat.isGrey());
    EXPECT_FALSE(flat.setSpectrum(800, 900, {1, 1, 1}, d));  // outside the visible
    // Degenerate spectra (overflowing sums, all zero) store saturated samples rather than
    // converting NaN or huge values to int16 (undefined behaviour; found by fuzz_mgf).
    // 1 nm data is box-filtered in floats, whose sums overflow to infinity here: the
    // scale becomes 0 and infinity times 0 is NaN.
    MgfColor huge;
    huge.setSpectrum(400, 500, std::vector<float>(101, 3e38f), d);
    for (int16_t v : huge.samples) EXPECT_EQ(v, 0);
}

// ---- bad input: one-line InputErrors naming the MGF file and line ----

std::string errorOf(const std::string& mgf) {
    try {
        mgfToRad(mgf, "bad.mgf", {});
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Mgf2radErrors, UndefinedVertex) {
    EXPECT_EQ(errorOf("v a =\n\tp 0 0 0\nv b =\n\tp 1 0 0\nf a b c\n"),
              "bad.mgf:5: Undefined reference: f a b c");
}

TEST(Mgf2radErrors, WrongArgumentCount) {
    EXPECT_EQ(errorOf("v a =\np 0 0 0\nsph a\n"), "bad.mgf:3: Wrong number of arguments: sph a");
    EXPECT_EQ(errorOf("v a =\np 0 0\n"), "bad.mgf:2: Wrong number of arguments: p 0 0");
    EXPECT_EQ(errorOf("m x =\nrs 0.5\n"), "bad.mgf:2: Wrong number of arguments: rs 0.5");
}

TEST(Mgf2radErrors, WrongTypeIllegalValueAndContext) {
    EXPECT_EQ(errorOf("v a =\np 0 x 0\n"), "bad.mgf:2: Wrong argument type: p 0 x 0");
    EXPECT_EQ(errorOf("m x =\nrd 1.5\n"), "bad.mgf:2: Illegal argument value: rd 1.5");
    EXPECT_EQ(errorOf("o a\no\no\n"), "bad.mgf:3: Unmatched context close: o");
    EXPECT_EQ(errorOf("xf -t 1 0\n"), "bad.mgf:1: Wrong argument type: xf -t 1 0");
    EXPECT_EQ(errorOf("m x\n"), "bad.mgf:1: Undefined reference: m x");
    // Reflectances adding up to more than one: no RADIANCE material fits.
    EXPECT_EQ(errorOf("m x =\nrd .8\nrs .5 0\nv a =\np 0 0 0\nv b =\np 1 0 0\n"
                      "v c =\np 0 1 0\nf a b c\n"),
              "bad.mgf:10: Illegal material specification: f a b c");
    EXPECT_EQ(errorOf("i nowhere.mgf\n"), "bad.mgf:1: Cannot open input file: i nowhere.mgf");
    // A continued line is reported at its last physical line, as RADIANCE counts.
    EXPECT_EQ(errorOf("# one\nsph \\\nq 1\n"), "bad.mgf:3: Undefined reference: sph q 1");
}

// RADIANCE skips entities it does not know (the format asks readers to, for later
// versions), counts them and names the first; so do we, as a warning, not an error.
TEST(Mgf2radErrors, UnknownEntityIsCountedAndReported) {
    std::vector<std::string> warnings;
    unsigned unknown = 0;
    std::string out = mgfToRad("# hello\nfoo 1 2\nbar\n", "odd.mgf", {}, &warnings, &unknown);
    EXPECT_EQ(out, "# hello\n");
    EXPECT_EQ(unknown, 2u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "odd.mgf:2: Unknown entity: foo");
    // The command adds RADIANCE's count line (as `mgf2rad odd.mgf` prints it).
    std::vector<std::string> w2;
    out = mgf2rad({"mgf2rad"}, "foo\n", w2);
    EXPECT_EQ(out,
              "## Translated from MGF Version 2.0\n## mgf2rad\n## mgf2rad: 1 unknown entities\n");
}

TEST(Mgf2radCommand, OptionsGoIntoTheHeaderAndEmittersBecomeGlow) {
    std::vector<std::string> w;
    std::string out =
        mgf2rad({"mgf2rad", "-g", "2", "-e", "3"}, "m l =\ned 100\nv a =\np 0 0 0\nsph a 1\n", w);
    // RADIANCE: mgf2rad -g 2 -e 3 < this input
    EXPECT_EQ(out,
              "## Translated from MGF Version 2.0\n## mgf2rad -g 2 -e 3\n\n"
              "void glow l\n0\n0\n4 0.533480 0.533480 0.533480 2.000000\n\n"
              "l sphere s1\n0\n0\n4                  0                  0                  0 "
              "                 1\n");
    EXPECT_THROW(mgf2rad({"mgf2rad", "-x"}, "", w), InputError);
    EXPECT_THROW(mgf2rad({"mgf2rad", "-m", "mats.rad"}, "", w), InputError);
}

}  // namespace
}  // namespace rp::gen
