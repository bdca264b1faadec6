// Surface modifier chains: each pattern, texture and mixture type against values worked
// out by hand, RADIANCE's walking order, and bad input named at its line.
#include "material/surface_chain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "image/picture.h"
#include "image/spectral_picture.h"
#include "scene/reader.h"
#include "scene/scene_load.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::material {

namespace {

int32_t indexOf(const Scene& s, const std::string& name) {
    for (size_t i = s.prims.size(); i-- > 0;)
        if (s.prims[i].name == name) return int32_t(i);
    return -2;
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

struct Fixture {
    TempDir dir;
    std::unique_ptr<Scene> scene;
    std::unique_ptr<SurfaceChains> chains;
    std::unique_ptr<SurfaceChainEvaluator> eval;
    Rng rng{7, RngDomain::Test, 0};

    void load(const std::string& text) {
        scene = std::make_unique<Scene>(parseScene(text, "c.rad"));
        chains = std::make_unique<SurfaceChains>(
            *scene,
            std::vector<std::string>{dir.path().string(), std::string(RP_SOURCE_DIR) + "/lib"});
        eval = std::make_unique<SurfaceChainEvaluator>(*chains);
    }
    int32_t mod(const std::string& name) const { return indexOf(*scene, name); }
    ChainResult at(const std::string& name, Vec3 p, Vec3 n = {0, 0, 1}) {
        PatternPoint pp;
        pp.point = p;
        pp.normal = n;
        pp.dir = {0, 0, -1};
        pp.rdot = 1;
        chains->checkChain(mod(name));
        return eval->resolve(mod(name), pp, rng);
    }
};

class SurfaceChain : public ::testing::Test {
protected:
    Fixture f;
};

void expectColor(const Color& c, double r, double g, double b, double tol = 1e-9) {
    SCOPED_TRACE(::testing::Message() << "colour " << c.r << " " << c.g << " " << c.b);
    EXPECT_NEAR(c.r, r, tol);
    EXPECT_NEAR(c.g, g, tol);
    EXPECT_NEAR(c.b, b, tol);
}

}  // namespace

TEST_F(SurfaceChain, PlainMaterialIsOneLayerWithoutEvaluation) {
    f.load(
        "void plastic m 0 0 5 .5 .5 .5 0 0\n"
        "void brightfunc b 2 2 . 0 0\nb plastic pm 0 0 5 .5 .5 .5 0 0\n");
    EXPECT_TRUE(f.chains->isPlain(f.mod("m")));
    EXPECT_EQ(f.chains->plainMaterial(f.mod("m")), f.mod("m"));
    EXPECT_TRUE(f.chains->isPlain(kVoid));
    EXPECT_FALSE(f.chains->isPlain(f.mod("pm")));
    ChainResult r = f.at("m", {0, 0, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, f.mod("m"));
    EXPECT_EQ(r.layers[0].weight, 1);
    expectColor(r.layers[0].pattern, 1, 1, 1);
}

TEST_F(SurfaceChain, BrightfuncAndColorfuncInObjectSpace) {
    f.load(
        "void brightfunc bx 6 Px . -t 1 0 0 0 0\n"
        "bx colorfunc cf 4 Py 2 A1 . 0 1 3\n"
        "cf plastic m 0 0 5 .5 .5 .5 0 0\n");
    ChainResult r = f.at("m", {3, 5, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, f.mod("m"));
    // brightfunc: object Px = 3 - 1; colorfunc (Py, 2, A1) = (5, 2, 3).
    expectColor(r.layers[0].pattern, 2 * 5, 2 * 2, 2 * 3);
}

TEST_F(SurfaceChain, BrightdataInterpolatesAOneDimensionalFile) {
    writeFile(f.dir.file("ramp.dat"), "1\n0 2 3\n1 2 4\n");
    f.load("void brightdata bd 4 noop ramp.dat . Px 0 0\nbd plastic m 0 0 5 1 1 1 0 0\n");
    expectColor(f.at("m", {0.5, 0, 0}).layers[0].pattern, 1.5, 1.5, 1.5);
    expectColor(f.at("m", {1.5, 0, 0}).layers[0].pattern, 3, 3, 3);
}

TEST_F(SurfaceChain, ColordataWithOneAndThreeArgumentFunctions) {
    writeFile(f.dir.file("r.dat"), "1\n0 1 2\n0 1\n");
    writeFile(f.dir.file("g.dat"), "1\n0 1 2\n2 4\n");
    writeFile(f.dir.file("b.dat"), "1\n0 1 2\n10 20\n");
    writeFile(f.dir.file("f.cal"), "twice(x) = 2*x;\nsum3(r, g, b) = r + g + b;\n");
    f.load(
        "void colordata cd 8 twice noop sum3 r.dat g.dat b.dat f.cal Px 0 0\n"
        "cd plastic m 0 0 5 1 1 1 0 0\n");
    // At x = .25: r .25, g 2.5, b 12.5.
    expectColor(f.at("m", {0.25, 0, 0}).layers[0].pattern, 0.5, 2.5, 0.25 + 2.5 + 12.5);
}

TEST_F(SurfaceChain, ColorpictReadsThePictureAtUV) {
    Picture pic(2, 2);
    pic.at(0, 0) = {1, 0, 0};  // top left
    pic.at(1, 0) = {0, 1, 0};  // top right
    pic.at(0, 1) = {0, 0, 1};  // bottom left
    pic.at(1, 1) = {1, 1, 1};  // bottom right
    writePicture(f.dir.file("p.hdr"), pic);
    f.load(
        "void colorpict cp 7 red green blue p.hdr picture.cal pic_u pic_v 0 0\n"
        "cp plastic m 0 0 5 1 1 1 0 0\n");
    // RGBE keeps 1 exactly but decodes 0 beside it as half a mantissa step (1/256).
    const double q = 1.0 / 128;
    expectColor(f.at("m", {0, 0, 0}).layers[0].pattern, 0, 0, 1, q);
    expectColor(f.at("m", {1, 0, 0}).layers[0].pattern, 1, 1, 1, q);
    expectColor(f.at("m", {0, 1, 0}).layers[0].pattern, 1, 0, 0, q);
    expectColor(f.at("m", {1, 1, 0}).layers[0].pattern, 0, 1, 0, q);
    expectColor(f.at("m", {.5, .5, 0}).layers[0].pattern, .5, .5, .5, q);
    // RADIANCE's edge rule: linear extrapolation for one more pixel (then clipped to
    // zero by the channel functions): u = 1.5 on the bottom row is 1.5*BR - .5*BL.
    expectColor(f.at("m", {1.5, 0, 0}).layers[0].pattern, 1.5, 1.5, 1.0, q);
}

TEST_F(SurfaceChain, TexfuncAddsATransformedPerturbation) {
    f.load(
        "void texfunc t 4 .1 0 A1 . 0 1 .05\n"
        "t texfunc t2 8 .1 0 0 . -rz 90 -s 2 0 0\n"
        "t2 plastic m 0 0 5 1 1 1 0 0\n");
    ChainResult r = f.at("m", {0, 0, 0});
    ASSERT_EQ(r.count, 1);
    // t2: (.1, 0, 0) rotated to +y, not scaled (t_func.c divides by the scale: RADIANCE
    // 5.4 gives normal (0.805 0.0537 0.590) for (1.5, .1, .1) under -s 0.2); t: (.1, 0, .05).
    EXPECT_NEAR(r.layers[0].perturbation.x, 0.1, 1e-12);
    EXPECT_NEAR(r.layers[0].perturbation.y, 0.1, 1e-12);
    EXPECT_NEAR(r.layers[0].perturbation.z, 0.05, 1e-12);
}

TEST_F(SurfaceChain, TexdataCallsItsFunctionsWithTheThreeValues) {
    writeFile(f.dir.file("x.dat"), "1\n0 1 2\n0 1\n");
    writeFile(f.dir.file("z.dat"), "1\n0 1 2\n1 1\n");
    writeFile(f.dir.file("t.cal"), "px(a, b, c) = a*c;\npz(a, b, c) = b;\n");
    f.load(
        "void texdata td 8 px pz pz x.dat z.dat x.dat t.cal Py 0 0\n"
        "td plastic m 0 0 5 1 1 1 0 0\n");
    Vec3 p = f.at("m", {0, 0.5, 0}).layers[0].perturbation;
    EXPECT_NEAR(p.x, 0.25, 1e-12);  // a = c = x.dat at .5
    EXPECT_NEAR(p.y, 1.0, 1e-12);
    EXPECT_NEAR(p.z, 1.0, 1e-12);
}

TEST_F(SurfaceChain, MixfuncSplitsIntoWeightedLayers) {
    f.load(
        "void plastic red 0 0 5 1 0 0 0 0\n"
        "void plastic blue 0 0 5 0 0 1 0 0\n"
        "void mixfunc mx 4 red blue .25 . 0 0\n"
        "void mixfunc all 4 red blue Px . 0 0\n");
    ChainResult r = f.at("mx", {0, 0, 0});
    ASSERT_EQ(r.count, 2);
    EXPECT_EQ(r.layers[0].material, f.mod("red"));
    EXPECT_DOUBLE_EQ(r.layers[0].weight, .25);
    EXPECT_EQ(r.layers[1].material, f.mod("blue"));
    EXPECT_DOUBLE_EQ(r.layers[1].weight, .75);
    // Coefficients 0 and 1 (and beyond, clipped) give one layer.
    r = f.at("all", {1, 0, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, f.mod("red"));
    r = f.at("all", {-3, 0, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, f.mod("blue"));
}

TEST_F(SurfaceChain, VoidSideOfAMaterialMixtureIsTransparent) {
    f.load(
        "void plastic red 0 0 5 1 0 0 0 0\n"
        "void mixfunc cut 4 red void .3 . 0 0\n");
    ChainResult r = f.at("cut", {0, 0, 0});
    ASSERT_EQ(r.count, 2);
    EXPECT_EQ(r.layers[0].material, f.mod("red"));
    EXPECT_DOUBLE_EQ(r.layers[0].weight, .3);
    EXPECT_EQ(r.layers[1].material, kVoid);
    EXPECT_DOUBLE_EQ(r.layers[1].weight, .7);
}

TEST_F(SurfaceChain, MixtureOfPatternsBlendsColourAndPerturbation) {
    f.load(
        "void brightfunc two 2 2 . 0 0\n"
        "void brightfunc four 2 4 . 0 0\n"
        "four texfunc bump 4 0 0 1 . 0 0\n"
        "void mixfunc mp 4 two bump .25 . 0 0\n"
        "mp plastic m 0 0 5 1 1 1 0 0\n");
    ChainResult r = f.at("m", {0, 0, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, f.mod("m"));
    expectColor(r.layers[0].pattern, 3.5, 3.5, 3.5);  // .25*2 + .75*4
    EXPECT_NEAR(r.layers[0].perturbation.z, 0.75, 1e-12);
}

TEST_F(SurfaceChain, MaterialPatternsApplyInsideEachLayer) {
    f.load(
        "void brightfunc half 2 .5 . 0 0\n"
        "half plastic red 0 0 5 1 0 0 0 0\n"
        "void plastic blue 0 0 5 0 0 1 0 0\n"
        "void mixfunc mx 4 red blue .5 . 0 0\n");
    ChainResult r = f.at("mx", {0, 0, 0});
    ASSERT_EQ(r.count, 2);
    expectColor(r.layers[0].pattern, .5, .5, .5);
    expectColor(r.layers[1].pattern, 1, 1, 1);
}

TEST_F(SurfaceChain, NestedMixturesMultiplyWeights) {
    f.load(
        "void plastic a 0 0 5 1 0 0 0 0\n"
        "void plastic b 0 0 5 0 1 0 0 0\n"
        "void plastic c 0 0 5 0 0 1 0 0\n"
        "void mixfunc ab 4 a b .5 . 0 0\n"
        "void mixfunc abc 4 ab c .4 . 0 0\n");
    ChainResult r = f.at("abc", {0, 0, 0});
    ASSERT_EQ(r.count, 3);
    EXPECT_EQ(r.layers[0].material, f.mod("a"));
    EXPECT_DOUBLE_EQ(r.layers[0].weight, .2);
    EXPECT_EQ(r.layers[1].material, f.mod("b"));
    EXPECT_DOUBLE_EQ(r.layers[1].weight, .2);
    EXPECT_EQ(r.layers[2].material, f.mod("c"));
    EXPECT_DOUBLE_EQ(r.layers[2].weight, .6);
}

TEST_F(SurfaceChain, MoreThanFourLayersChooseSidesAtRandomWithTheRightExpectation) {
    f.load(
        "void plastic a 0 0 5 1 0 0 0 0\nvoid plastic b 0 0 5 0 1 0 0 0\n"
        "void plastic c 0 0 5 0 0 1 0 0\nvoid plastic d 0 0 5 1 1 0 0 0\n"
        "void plastic e 0 0 5 0 1 1 0 0\n"
        "void mixfunc ab 4 a b .5 . 0 0\nvoid mixfunc cd 4 c d .5 . 0 0\n"
        "void mixfunc abcd 4 ab cd .5 . 0 0\nvoid mixfunc all 4 abcd e .8 . 0 0\n");
    const int n = 20000;
    double sum[5] = {};
    for (int i = 0; i < n; ++i) {
        ChainResult r = f.at("all", {0, 0, 0});
        ASSERT_LE(r.count, ChainResult::kMaxLayers);
        double total = 0;
        for (int k = 0; k < r.count; ++k) {
            total += r.layers[k].weight;
            for (const char* m : {"a", "b", "c", "d", "e"})
                if (r.layers[k].material == f.mod(m)) sum[m[0] - 'a'] += r.layers[k].weight;
        }
        ASSERT_NEAR(total, 1, 1e-12);
    }
    // a..d: .2 each, e: .2. The choice is between abcd (weights .25*1/.8... ) and e:
    // each estimate is a Bernoulli mean; 5 sigma of p=.8 over n draws.
    double tol = 5 * std::sqrt(.8 * .2 / n);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(sum[k] / n, .2, tol) << k;
}

TEST_F(SurfaceChain, ChainWithoutMaterialIsTransparent) {
    f.load("void brightfunc b 2 2 . 0 0\n");
    ChainResult r = f.at("b", {0, 0, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, kVoid);
}

TEST_F(SurfaceChain, MixdataAndMixpictCoefficients) {
    writeFile(f.dir.file("c.dat"), "1\n0 1 2\n0 1\n");
    Picture pic(1, 1);
    pic.at(0, 0) = {.5, .5, .5};
    writePicture(f.dir.file("g.hdr"), pic);
    f.load(
        "void plastic a 0 0 5 1 0 0 0 0\nvoid plastic b 0 0 5 0 1 0 0 0\n"
        "void mixdata md 6 a b noop c.dat . Px 0 0\n"
        "void mixpict mp 7 a b grey g.hdr picture.cal pic_u pic_v 0 0\n");
    ChainResult r = f.at("md", {0.3, 0, 0});
    ASSERT_EQ(r.count, 2);
    EXPECT_NEAR(r.layers[0].weight, .3, 1e-12);
    r = f.at("mp", {0.3, 0.3, 0});
    ASSERT_EQ(r.count, 2);
    EXPECT_NEAR(r.layers[0].weight, .5, 1.0 / 256);  // grey of (.5,.5,.5), RGBE-rounded
}

TEST_F(SurfaceChain, TextPatternsAndMixtext) {
    // 'A' fills its cell; 'B' only the left part (x < 100).
    writeFile(f.dir.file("tiny.fnt"),
              "# test font\n65 4 0 0 255 0 255 255 0 255\n"
              "66 4 0 0 100 0 100 255 0 255\n32 0\n");
    f.load(
        "void plastic fg 0 0 5 1 0 0 0 0\nvoid plastic bg 0 0 5 0 1 0 0 0\n"
        "void colortext ct 3 tiny.fnt . AB 0 15 0 1 0 1 0 0 0 -1 0 2 3 4 .5 .5 .5\n"
        "ct plastic m 0 0 5 1 1 1 0 0\n"
        "void brighttext bt 3 tiny.fnt . AB 0 11 0 1 0 1 0 0 0 -1 0 5 1\n"
        "bt plastic mb 0 0 5 1 1 1 0 0\n"
        "void mixtext mt 5 fg bg tiny.fnt . AB 0 9 0 1 0 1 0 0 0 -1 0\n");
    // The text's upper left corner is (0,1); one character per unit of x, line 0 is
    // y in (0,1].
    expectColor(f.at("m", {0.5, 0.5, 0}).layers[0].pattern, 2, 3, 4);
    expectColor(f.at("m", {1.2, 0.5, 0}).layers[0].pattern, 2, 3, 4);      // in B
    expectColor(f.at("m", {1.6, 0.5, 0}).layers[0].pattern, .5, .5, .5);   // right of B
    expectColor(f.at("m", {2.5, 0.5, 0}).layers[0].pattern, .5, .5, .5);   // past the line
    expectColor(f.at("m", {0.5, -0.5, 0}).layers[0].pattern, .5, .5, .5);  // below
    expectColor(f.at("mb", {0.5, 0.5, 0}).layers[0].pattern, 5, 5, 5);
    expectColor(f.at("mb", {1.6, 0.5, 0}).layers[0].pattern, 1, 1, 1);
    ChainResult r = f.at("mt", {0.5, 0.5, 0});
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.layers[0].material, f.mod("fg"));
    EXPECT_EQ(f.at("mt", {1.6, 0.5, 0}).layers[0].material, f.mod("bg"));
}

TEST_F(SurfaceChain, TextFromAFileHasOneLinePerFileLine) {
    // RADIANCE compat: a character without a glyph takes no room, so the space needs one.
    writeFile(f.dir.file("tiny.fnt"), "65 4 0 0 255 0 255 255 0 255\n32 0\n");
    writeFile(f.dir.file("lines.txt"), "A\n A\n");
    f.load(
        "void brighttext bt 2 tiny.fnt lines.txt 0 11 0 2 0 1 0 0 0 -1 0 1 0\n"
        "bt plastic m 0 0 5 1 1 1 0 0\n");
    EXPECT_EQ(f.at("m", {0.5, 1.5, 0}).layers[0].pattern.r, 1);
    EXPECT_EQ(f.at("m", {1.5, 1.5, 0}).layers[0].pattern.r, 0);
    EXPECT_EQ(f.at("m", {0.5, 0.5, 0}).layers[0].pattern.r, 0);  // the space
    EXPECT_EQ(f.at("m", {1.5, 0.5, 0}).layers[0].pattern.r, 1);
}

// ---- errors

TEST_F(SurfaceChain, MissingFilesNameTheRecordLine) {
    auto expectLine = [&](const std::string& text, int line, const std::string& what) {
        try {
            f.load(text);
            FAIL() << text;
        } catch (const InputError& e) {
            EXPECT_EQ(e.loc().line, line) << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    expectLine("\nvoid brightdata bd 4 noop none.dat . Px 0 0\n", 2, "none.dat");
    expectLine("\n\nvoid colorpict cp 7 red green blue none.hdr . Px Py 0 0\n", 3, "none.hdr");
    expectLine("void brighttext t 3 none.fnt . A 0 11 0 1 0 1 0 0 0 -1 0 1 0\n", 1, "none.fnt");
    expectLine("void texfunc t 4 0 0 0 none.cal 0 0\n", 1, "none.cal");
    expectLine("void mixfunc m 4 nosuch void .5 . 0 0\n", 1, "undefined modifier 'nosuch'");
    expectLine("void brightdata bd 4 nofunc x.dat . Px 0 0\n", 1, "x.dat");
}

TEST_F(SurfaceChain, UndefinedNamesAreReportedAtTheirLine) {
    writeFile(f.dir.file("x.dat"), "1\n0 1 2\n0 1\n");
    try {
        f.load("void brightdata bd 4 nofunc x.dat . Px 0 0\n");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().line, 1);
        EXPECT_NE(std::string(e.what()).find("undefined function 'nofunc'"), std::string::npos);
    }
    f.load("\nvoid brightfunc b 2 Px+nosuch . 0 0\nb plastic m 0 0 5 1 1 1 0 0\n");
    try {
        f.at("m", {0, 0, 0});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().line, 2) << e.what();
        EXPECT_NE(std::string(e.what()).find("nosuch"), std::string::npos) << e.what();
    }
}

TEST_F(SurfaceChain, DataDimensionsMustMatchTheCoordinates) {
    writeFile(f.dir.file("two.dat"), "2\n0 1 2\n0 1 2\n1 2 3 4\n");
    try {
        f.load("void brightdata bd 4 noop two.dat . Px 0 0\n");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("dimension"), std::string::npos) << e.what();
    }
    f.load("void brightdata bd 5 noop two.dat . Px Py 0 0\nbd plastic m 0 0 5 1 1 1 0 0\n");
    expectColor(f.at("m", {0.5, 0.5, 0}).layers[0].pattern, 2.5, 2.5, 2.5);
}

TEST_F(SurfaceChain, MaterialInsideAMaterialsChainConflicts) {
    f.load(
        "void plastic a 0 0 5 1 0 0 0 0\n"
        "void mixfunc mx 4 a void .5 . 0 0\n"
        "mx plastic m 0 0 5 1 1 1 0 0\n");
    EXPECT_THROW(f.chains->checkChain(f.mod("m")), InputError);
}

// Spectral patterns in RGB (RADIANCE 6 at -cs 3): the spectrum integrated against the
// CIE observer. The same spectrum given four ways gives one colour, and a flat one is
// grey.
TEST_F(SurfaceChain, SpectralPatternsOfOneSpectrumAgree) {
    // The same ramp every 10 nm.
    std::string fineRamp;
    for (int k = 0; k <= 40; ++k) fineRamp += " " + std::to_string(.2 + .6 * k / 40);
    // Rising from 0.2 at 380 nm to 0.8 at 780 nm, in 5 samples.
    writeFile(f.dir.file("ramp.dat"), "1\n380 780 5\n.2 .35 .5 .65 .8\n");
    // Two rows: flat 0.5, then the ramp; wavelength last.
    writeFile(f.dir.file("rows.dat"), "2\n0 1 2\n380 780 5\n.5 .5 .5 .5 .5\n.2 .35 .5 .65 .8\n");
    writeFile(f.dir.file("ramp.cal"), "ramp(wl) = .2 + .6 * (wl - 380) / 400;\nhalf(wl) = .5;\n");
    f.load(
        "void spectrum flat 0 0 7 380 780 .5 .5 .5 .5 .5\nflat plastic m0 0 0 5 1 1 1 0 0\n"
        "void spectrum sp 0 0 7 380 780 .2 .35 .5 .65 .8\nsp plastic m1 0 0 5 1 1 1 0 0\n"
        "void specfile sf 1 ramp.dat 0 0\nsf plastic m2 0 0 5 1 1 1 0 0\n"
        "void specfunc fn 2 ramp ramp.cal 0 2 380 780\nfn plastic m3 0 0 5 1 1 1 0 0\n"
        "void spectrum fine 0 0 43 380 780" +
        fineRamp +
        "\nfine plastic m6 0 0 5 1 1 1 0 0\n"
        "void specfunc fh 2 half ramp.cal 0 2 380 780\nfh plastic m5 0 0 5 1 1 1 0 0\n"
        "void specdata sd 4 noop rows.dat . Px 0 0\nsd plastic m4 0 0 5 1 1 1 0 0\n");
    const Color flat = f.at("m0", {0, 0, 0}).layers[0].pattern;
    expectColor(flat, 0.5, 0.5, 0.5, 5e-4);
    const Color ramp = f.at("m1", {0, 0, 0}).layers[0].pattern;
    EXPECT_GT(ramp.r, ramp.g);
    EXPECT_GT(ramp.g, ramp.b);
    const Color file = f.at("m2", {0, 0, 0}).layers[0].pattern;
    expectColor(file, ramp.r, ramp.g, ramp.b, 1e-12);
    expectColor(f.at("m5", {0, 0, 0}).layers[0].pattern, flat.r, flat.g, flat.b, 1e-12);
    // The ramp sampled at jittered wavelengths in 12 bands (each off by up to 0.022),
    // against the same ramp every 10 nm: close, not equal.
    const Color fine = f.at("m6", {0, 0, 0}).layers[0].pattern;
    const Color func = f.at("m3", {0, 0, 0}).layers[0].pattern;
    expectColor(func, fine.r, fine.g, fine.b, 0.02);
    expectColor(f.at("m4", {0, 0, 0}).layers[0].pattern, flat.r, flat.g, flat.b, 1e-12);
    expectColor(f.at("m4", {1, 0, 0}).layers[0].pattern, ramp.r, ramp.g, ramp.b, 1e-12);
    const Color half = f.at("m4", {0.5, 0, 0}).layers[0].pattern;
    expectColor(half, (flat.r + ramp.r) / 2, (flat.g + ramp.g) / 2, (flat.b + ramp.b) / 2, 1e-12);
}

// specpict reads a spectral picture as colorpict reads a picture (the bottom-left pixel
// at (0, 0)), each sample through f(value, wavelength) at its band's centre: here a
// 4 x 3 picture of 12 bands over 700..400 nm made by RADIANCE 6.1a's rtrace.
TEST_F(SurfaceChain, SpecpictReadsTheBottomLeftPixelAtTheOrigin) {
    const std::string data = std::string(RP_SOURCE_DIR) + "/tests/data/spectral";
    const SpectralPicture pic = readSpectralPicture(data + "/room12.hsr");
    ASSERT_EQ(pic.sampling.n, 12);
    writeFile(f.dir.file("half.cal"), "half(v, wl) = if(wl - 550, v, v / 2);\n");
    f.load("void specpict sp 5 half " + data + "/room12.hsr half.cal 0 0\n0\n0\n" +
           "sp plastic m 0 0 5 1 1 1 0 0\n");
    PatternPoint pp;
    pp.point = {0, 0, 0};
    pp.normal = {0, 0, 1};
    pp.dir = {0, 0, -1};
    pp.rdot = 1;
    const auto px = pic.at(0, pic.height - 1);
    std::vector<double> halved(px.begin(), px.end());
    for (int i = 0; i < 12; ++i)
        if (pic.sampling.centre(i) < 550) halved[size_t(i)] /= 2;
    double rgb[3];
    spectral::toWorking(halved, 700, 400, spectral::Sampling{}, std::span<double>(rgb, 3));
    f.chains->checkChain(f.mod("m"));
    const Color c = f.eval->resolve(f.mod("m"), pp, f.rng).layers[0].pattern;
    expectColor(c, rgb[0], rgb[1], rgb[2], 1e-6);
}

TEST_F(SurfaceChain, SpectralRecordsCheckTheirData) {
    writeFile(f.dir.file("flat.dat"), "1\n380 780 5\n1 1 1 1 1\n");
    try {
        f.load("void specdata sd 4 noop flat.dat . Px 0 0\n");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().line, 1);
        EXPECT_NE(std::string(e.what()).find("2-dimensional"), std::string::npos) << e.what();
    }
    writeFile(f.dir.file("rows.dat"), "2\n0 1 2\n380 780 5\n1 1 1 1 1\n1 1 1 1 1\n");
    EXPECT_THROW(f.load("void specfile sf 1 rows.dat 0 0\n"), InputError);
    EXPECT_THROW(f.load("void specfile sf 1 none.dat 0 0\n"), InputError);
}

// A luminaire distribution in inches (rect_fixture.rad's transform): the data's angle is
// off the fixture's axis, read from a unit D, and the flat-source correction divides by
// Rdot. Before directions were made unit again, acos(Dz) saw 1/0.0254 times D and read
// the table at 0 degrees in every direction.
TEST_F(SurfaceChain, LuminaireDataSeesUnitDirectionsThroughAScaledTransform) {
    writeFile(f.dir.file("dist.dat"), "1\n0 90 3\n1 0.5 0\n");
    writeFile(f.dir.file("flat.cal"), "flat(v) = v / Rdot;\ntheta = Acos(Dz) / DEGREE;\n");
    f.load(
        "void brightdata dist 8 flat dist.dat flat.cal theta -s 0.0254 -rz 90 0 0\n"
        "dist light lamp 0 0 3 10 10 10\n");
    PatternPoint pp;
    pp.normal = {0, 0, -1};              // facing the floor
    pp.dir = {0.5, 0, std::sqrt(0.75)};  // from the floor up to the lamp, 30 degrees off
    pp.rdot = -dot(pp.dir, pp.normal);
    f.chains->checkChain(f.mod("lamp"));
    ChainResult r = f.eval->resolve(f.mod("lamp"), pp, f.rng);
    ASSERT_EQ(r.count, 1);
    // 30 degrees: two thirds of the way from 1 to 0.5 (at 0 and 45), divided by cos 30.
    const double v = (2.0 / 3.0) / std::sqrt(0.75);
    expectColor(r.layers[0].pattern, v, v, v);
}

TEST_F(SurfaceChain, DirectionalOnlyWithoutPositionVariables) {
    writeFile(f.dir.file("d.dat"), "1\n0 1 2\n0 1\n");
    writeFile(f.dir.file("any.cal"), "g = Dz;\nh(x) = x * Py;\nk = h(Dz);\n");
    const std::string hsr = std::string(RP_SOURCE_DIR) + "/tests/data/spectral/room12.hsr";
    f.load(
        "void colorfunc dirs 6 Dx Dy Dz . -rz 90 0 0\n"
        "dirs brightfunc twice 2 2 . 0 0\n"
        "twice light a 0 0 3 1 1 1\n"
        "void brightdata dd 4 noop d.dat . Dz 0 0\n"
        "dd light b 0 0 3 1 1 1\n"
        "void brightfunc pos 2 A1*Px+Ts . 0 1 2\n"
        "pos light c 0 0 3 1 1 1\n"
        "void brightfunc file 2 g any.cal 0 0\n"
        "file light d 0 0 3 1 1 1\n"
        "void brightfunc hidden 2 k any.cal 0 0\n"
        "hidden light h 0 0 3 1 1 1\n"
        "void brightfunc half 2 .5 . 0 0\n"
        "void mixfunc mx 4 half void .5 . 0 0\n"
        "mx light e 0 0 3 1 1 1\n"
        "void specpict sky 5 noop " +
        hsr +
        " . 'Atan2(Dy,Dx)/PI+1' '1-Acos(Dz)/PI' 0 0\n"
        "sky glow s 0 0 4 1 1 1 0\n"
        "void specpict at 5 noop " +
        hsr +
        " . Px Py 0 0\n"
        "at glow p 0 0 4 1 1 1 0\n");
    auto chainOf = [&](const char* light) { return f.scene->prims[f.mod(light)].modifier; };
    EXPECT_TRUE(f.chains->directionalOnly(chainOf("a")));
    EXPECT_TRUE(f.chains->directionalOnly(chainOf("b")));
    EXPECT_FALSE(f.chains->directionalOnly(chainOf("c")));  // reads P and Ts
    EXPECT_TRUE(f.chains->directionalOnly(chainOf("d")));   // the file's g reads D only
    EXPECT_FALSE(f.chains->directionalOnly(chainOf("h")));  // k calls h, which reads Py
    EXPECT_FALSE(f.chains->directionalOnly(chainOf("e")));  // mixtures are not judged
    EXPECT_TRUE(f.chains->directionalOnly(kVoid));
    // Pictures too (genssky's sky: every port point sees the same sky).
    EXPECT_TRUE(f.chains->directionalOnly(chainOf("s")));
    EXPECT_FALSE(f.chains->directionalOnly(chainOf("p")));  // reads Px, Py
    // Rotated +90 degrees about z, the world x axis is the object's -y axis; x 2.
    PatternPoint pp;
    pp.dir = {1, 0, 0};
    expectColor(f.eval->resolve(f.mod("a"), pp, f.rng).layers[0].pattern, 0, -2, 0);
}

// gensky's skyfunc (skybright.cal) at the zenith against the CIE clear sky written out.
TEST(SurfaceChainSky, DaylightSkyAtZenithMatchesCieClearSky) {
    RP_REQUIRE_SHARED("validation/daylight");
    Scene s = loadScene({std::string(RP_SHARED_DIR) + "/validation/daylight/scene.rad"});
    SurfaceChains chains(s, {std::string(RP_SOURCE_DIR) + "/lib"});
    int32_t glow = indexOf(s, "sky_glow");
    ASSERT_GE(glow, 0);
    chains.checkChain(glow);
    // skybright.cal reads the direction only: one emission table serves every port point.
    EXPECT_TRUE(chains.directionalOnly(s.prims[glow].modifier));
    SurfaceChainEvaluator ev(chains);
    Rng rng{7, RngDomain::Test, 0};
    PatternPoint at;
    at.dir = {0, 0, 1};
    Color c = ev.resolve(glow, at, rng).layers[0].pattern;
    // skyfunc args: 1 8.79 20.0 0.526 | sun 0.153855 -0.727432 0.668708 (gensky +s).
    double zen = 8.79, ground = 20.0, norm = 0.526, cosg = 0.668708;
    double gamma = std::acos(cosg);
    double clear = zen * (0.91 + 10 * std::exp(-3 * gamma) + 0.45 * cosg * cosg) *
                   (1 - std::exp(-0.32)) / norm;
    double w = std::pow(2.01, 10);
    double expected = (w * clear + ground / w) / (w + 1 / w);
    EXPECT_NEAR(c.r, expected, 1e-9 * expected);
    EXPECT_EQ(c.r, c.g);
    EXPECT_EQ(c.g, c.b);
}

}  // namespace rp::material
