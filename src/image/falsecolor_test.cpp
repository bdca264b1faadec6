// falsecolor: value -> colour for every palette and contour mode, legend numbers and
// layout, against RADIANCE 5.4's falsecolor on the same synthetic picture.
//
// The reference picture (made outside RADIANCE, bytes as below) is 256 x 3 grey pixels
// whose RGBE bytes are (x, x, x, 131), so luminance 179 (x + .5)/32 cd/m2 from 2.8 to 1434.
// Reference colours are RADIANCE's output at column 100 + x of the picture's middle row:
//   falsecolor [options] -i grad.hdr > ref.hdr      (RADIANCE 5.4, falsecolor.pl 2.17)
// read back as RGBE bytes.
#include "image/falsecolor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "image/legend_font.h"
#include "util/error.h"

namespace rp {
namespace {

Picture gradient() {
    Picture p(256, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 256; ++x) {
            auto b = static_cast<uint8_t>(x);
            p.at(x, y) = toPixel(Colr{b, b, b, 131});
        }
    return p;
}

struct Ref {
    int x;
    Colr c;
};

// Within one RGBE step: components differ by at most one unit of the larger exponent.
bool nearColr(const Colr& a, const Colr& b) {
    Pixel pa = toPixel(a), pb = toPixel(b);
    int e = std::max(a[3], b[3]);
    double step = std::ldexp(1.0, e - 136);
    for (int i = 0; i < 3; ++i)
        if (std::abs(pa[i] - pb[i]) > step * 1.0001) return false;
    return true;
}

std::string show(const Colr& c) {
    return std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + "," +
           std::to_string(c[3]);
}

// Runs our falsecolor on the gradient and checks the image's middle row.
void expectColumns(const std::vector<std::string>& args, int width, int height,
                   const std::vector<Ref>& refs) {
    FalseColorOptions o = parseFalseColorArgs(args);
    Picture out = falseColorPicture(gradient(), nullptr, o, "falsecolor");
    ASSERT_EQ(out.width, width);
    ASSERT_EQ(out.height, height);
    for (const Ref& r : refs) {
        Colr got = toColr(out.at(100 + r.x, height - 2));
        EXPECT_TRUE(nearColr(got, r.c))
            << "x=" << r.x << " got " << show(got) << " want " << show(r.c);
    }
}

TEST(FalseColor, DefaultPaletteMatchesRadiance) {
    expectColumns({}, 356, 247,
                  {{0, {92, 0, 139, 127}},
                   {16, {0, 0, 244, 127}},
                   {48, {0, 215, 210, 127}},
                   {80, {83, 139, 42, 127}},
                   {112, {189, 22, 21, 127}},
                   {128, {219, 3, 7, 127}},
                   {144, {189, 1, 0, 128}},
                   {176, {253, 225, 5, 128}},
                   {255, {252, 248, 6, 128}}});
}

TEST(FalseColor, LogDecadesMatchRadiance) {
    expectColumns({"-log", "2"}, 356, 247,
                  {{0, {96, 0, 136, 127}},
                   {16, {250, 212, 96, 126}},
                   {48, {218, 3, 7, 127}},
                   {80, {205, 6, 0, 128}},
                   {112, {251, 68, 0, 128}},
                   {128, {128, 57, 0, 129}},
                   {144, {128, 81, 0, 129}},
                   {176, {252, 243, 6, 128}}});
}

TEST(FalseColor, ContourLinesMatchRadiance) {
    // Lines fall where the division changes between left and right neighbours: 1000/8
    // cd/m2 steps are 22.35 columns apart, so x = 112 (first column of 500-625) is a line.
    expectColumns({"-cl"}, 356, 222,
                  {{0, {0, 0, 0, 0}},
                   {80, {0, 0, 0, 0}},
                   {112, {177, 45, 34, 127}},
                   {128, {0, 0, 0, 0}},
                   {255, {0, 0, 0, 0}}});
}

TEST(FalseColor, ContourBandsMatchRadiance) {
    expectColumns({"-cb", "-n", "5"}, 356, 230,
                  {{0, {0, 0, 0, 0}},
                   {112, {0, 0, 0, 0}},
                   {144, {144, 0, 1, 128}},
                   {176, {253, 219, 4, 128}},
                   {208, {0, 0, 0, 0}}});
}

TEST(FalseColor, PosterizeMatchesRadiance) {
    expectColumns({"-cp"}, 356, 222,
                  {{0, {96, 0, 136, 127}},
                   {16, {96, 0, 136, 127}},
                   {48, {0, 61, 134, 128}},
                   {80, {6, 227, 35, 127}},
                   {112, {192, 17, 18, 127}},
                   {144, {168, 0, 1, 128}},
                   {176, {128, 58, 0, 129}},
                   {208, {252, 248, 6, 128}}});
}

TEST(FalseColor, OtherPalettesMatchRadiance) {
    expectColumns({"-pal", "spec"}, 356, 247,
                  {{0, {0, 1, 254, 128}},
                   {48, {0, 185, 70, 128}},
                   {128, {140, 115, 0, 128}},
                   {176, {250, 5, 0, 128}},
                   {255, {128, 0, 0, 129}}});
    expectColumns({"-pal", "pm3d"}, 356, 247,
                  {{0, {203, 0, 18, 119}},
                   {48, {60, 0, 250, 128}},
                   {128, {178, 28, 0, 128}},
                   {176, {252, 235, 0, 128}},
                   {255, {128, 128, 0, 129}}});
    expectColumns({"-pal", "hot"}, 356, 247,
                  {{0, {227, 0, 0, 113}},
                   {48, {162, 0, 0, 128}},
                   {128, {128, 128, 2, 129}},
                   {176, {128, 128, 117, 129}},
                   {255, {128, 128, 128, 129}}});
    expectColumns({"-pal", "eco"}, 356, 247,
                  {{0, {0, 0, 252, 128}},
                   {48, {133, 0, 91, 127}},
                   {128, {128, 20, 0, 129}},
                   {176, {128, 120, 0, 129}},
                   {255, {128, 128, 0, 129}}});
    expectColumns({"-pal", "tbo"}, 356, 247,
                  {{0, {110, 15, 199, 124}},
                   {48, {2, 149, 190, 128}},
                   {128, {253, 81, 5, 128}},
                   {176, {246, 0, 0, 126}},
                   {255, {203, 0, 0, 126}}});
}

TEST(FalseColor, ScaleAndDivisionsMatchRadiance) {
    expectColumns({"-s", "500", "-n", "4"}, 356, 285,
                  {{0, {88, 0, 142, 127}},
                   {16, {0, 34, 137, 128}},
                   {48, {167, 63, 43, 127}},
                   {80, {251, 69, 0, 128}},
                   {112, {252, 248, 6, 128}}});
}

TEST(FalseColor, PaletteEndsAndMiddles) {
    // Straight from the palette definitions: spec is blue at 0, green-yellow at .5, red
    // at 1; hot is black, then red ramps in before green and blue.
    auto spec0 = paletteColor(FalseColorPalette::kSpec, 0);
    EXPECT_DOUBLE_EQ(spec0[2], 1);
    auto spec1 = paletteColor(FalseColorPalette::kSpec, 1);
    EXPECT_DOUBLE_EQ(spec1[0], 1);
    EXPECT_DOUBLE_EQ(spec1[1], 0);
    auto specHalf = paletteColor(FalseColorPalette::kSpec, 0.5);
    EXPECT_NEAR(specHalf[0], 0.2, 1e-12);
    EXPECT_NEAR(specHalf[1], 0.8, 1e-12);
    auto hot = paletteColor(FalseColorPalette::kHot, 0.5);
    EXPECT_DOUBLE_EQ(hot[0], 1);
    EXPECT_NEAR(hot[1], std::pow(0.5, 2.2), 1e-12);
    EXPECT_DOUBLE_EQ(hot[2], 0);
    // def's first and last table entries hold beyond the ends.
    auto d0 = paletteColor(FalseColorPalette::kDef, -0.3);
    EXPECT_DOUBLE_EQ(d0[0], 0.18848);
    auto d1 = paletteColor(FalseColorPalette::kDef, 1.7);
    EXPECT_DOUBLE_EQ(d1[1], 0.9707);
}

TEST(FalseColor, LegendNumbersAsRadianceWritesThem) {
    // RADIANCE's falsecolor.pl label loop (perl, same expressions) printed these.
    auto labels = [](std::vector<std::string> args) {
        return legendValues(parseFalseColorArgs(args));
    };
    using V = std::vector<std::string>;
    EXPECT_EQ(labels({}), (V{"1000", "875", "750", "625", "500", "375", "250", "125", "0"}));
    EXPECT_EQ(labels({"-log", "2"}), (V{"1000", "562.341", "316.227", "177.827", "100", "56.234",
                                        "31.622", "17.782", "10"}));
    EXPECT_EQ(labels({"-s", "500", "-n", "4"}), (V{"500", "375", "250", "125", "0"}));
    EXPECT_EQ(labels({"-n", "5", "-log", "3", "-d", "1"}),
              (V{"1000", "251.1", "63.0", "15.8", "3.9", "1"}));
    EXPECT_EQ(labels({"-s", "1234.5678", "-n", "3", "-d", "2"}),
              (V{"1234.56", "823.04", "411.52", "0"}));
    EXPECT_EQ(labels({"-cl"}), (V{"1000", "875", "750", "625", "500", "375", "250", "125"}));
    EXPECT_EQ(labels({"-log", "2", "-d", "0"}),
              (V{"1000", "562.", "316.", "177.", "100", "56.", "31.", "17.", "10"}));
    EXPECT_EQ(labels({"-s", "0.001", "-n", "4"}), (V{"0.001", "0.000", "0.000", "0.000", "0"}));
    EXPECT_EQ(labels({"-s", "1e6", "-n", "6", "-log", "4"}),
              (V{"1000000", "215443.469", "46415.888", "10000", "2154.434", "464.158", "100"}));
}

TEST(FalseColor, LegendSitsLeftOfTheImage) {
    // RADIANCE: 356 x 247 for the 256 x 3 gradient (100-pixel legend; the unit label's
    // top at 247); the image's bottom-left pixel lands at column 100 of the last row.
    Picture out = falseColorPicture(gradient(), nullptr, FalseColorOptions{}, "falsecolor");
    EXPECT_EQ(out.width, 356);
    EXPECT_EQ(out.height, 247);
    // The colour bar: 100 wide, 238 rows from 12 below the picture's bottom, so its top
    // row is 226 from the bottom: row 247-226 = 21 from the top is the first bar row.
    EXPECT_EQ(toColr(out.at(99, 20))[3], 0);
    EXPECT_GT(toColr(out.at(99, 21))[3], 0);
    // No legend when it would be too small to read: just the image.
    FalseColorOptions small;
    small.legendWidth = 20;
    Picture bare = falseColorPicture(gradient(), nullptr, small, "falsecolor");
    EXPECT_EQ(bare.width, 256);
    EXPECT_EQ(bare.height, 3);
}

TEST(FalseColor, LongLabelsAreNarrowedNotCut) {
    // -log 2 -s 30000 -n 4 labels 9486.832: 8 glyphs of our font at the legend's text
    // height (20) are 107 pixels, wider than the 100-pixel legend (RADIANCE's
    // proportional font fits). The label is narrowed to fit, every glyph drawn.
    const TextMask wide = renderText("9486.832", 20);
    EXPECT_EQ(wide.width, 107);
    const TextMask fit = renderText("9486.832", 20, 98);
    EXPECT_EQ(fit.width, 98);
    EXPECT_EQ(fit.height, 20);
    int lastGlyphStrokes = 0;  // the final '2' occupies the last eighth
    for (int y = 0; y < fit.height; ++y)
        for (int x = fit.width * 7 / 8; x < fit.width; ++x) lastGlyphStrokes += fit.at(x, y);
    EXPECT_GT(lastGlyphStrokes, 20);
    EXPECT_EQ(renderText("300", 20, 98).width, renderText("300", 20).width);  // short: as is
}

TEST(FalseColor, BackgroundShowsBetweenContours) {
    Picture bg(256, 3);
    for (Pixel& p : bg.pixels) p = {0.5f, 0.25f, 0.125f};
    FalseColorOptions o = parseFalseColorArgs({"-cl", "-p", "bg.hdr"});
    Picture out = falseColorPicture(gradient(), &bg, o, "falsecolor");
    EXPECT_FLOAT_EQ(out.at(100 + 80, out.height - 2)[0], 0.5f);
    Picture wrong(10, 3);
    EXPECT_THROW(falseColorPicture(gradient(), &wrong, o, "falsecolor"), InputError);
}

TEST(FalseColor, CustomChannelExpressions) {
    FalseColorOptions o = parseFalseColorArgs({"-r", "v*v", "-g", "0", "-b", "1-v"});
    FalseColorMap map(o);
    auto c = map.color(0.5);
    EXPECT_DOUBLE_EQ(c[0], 0.25);
    EXPECT_DOUBLE_EQ(c[1], 0);
    EXPECT_DOUBLE_EQ(c[2], 0.5);
    EXPECT_THROW(FalseColorMap{parseFalseColorArgs({"-r", "v*("})}, InputError);
}

TEST(FalseColor, AutoScaleNearRadiance) {
    // RADIANCE: phisto grad.hdr | tail -2 puts the second-highest bin at 3.16041, so
    // falsecolor -s a uses 10^3.16041 = 1446.8. Our 128-wide reduction is a box average
    // where pfilt filters, hence a tolerance of 1 %.
    EXPECT_NEAR(autoScaleTop(gradient(), 179), 1446.8, 14.5);
    // On the 256 x 256 Cornell box rendering the two agree to 6 digits (7232.69).
}

TEST(FalseColor, BadOptions) {
    EXPECT_THROW(parseFalseColorArgs({"-x"}), InputError);
    EXPECT_THROW(parseFalseColorArgs({"-pal", "rainbow"}), InputError);
    EXPECT_THROW(parseFalseColorArgs({"-n"}), InputError);
    EXPECT_THROW(parseFalseColorArgs({"-n", "0"}), InputError);
    EXPECT_THROW(parseFalseColorArgs({"-s", "big"}), InputError);
    EXPECT_TRUE(parseFalseColorArgs({"-s", "auto"}).autoScale);
}

TEST(LegendFont, DigitsAreDrawnAtTheAskedHeight) {
    TextMask m = renderText("10", 18);
    EXPECT_EQ(m.height, 18);
    EXPECT_EQ(m.width, 24);  // two 6-unit cells at 2 pixels a unit
    int inked = 0;
    for (bool b : m.on) inked += b;
    EXPECT_GT(inked, 20);
    // The top and bottom units are spacing.
    for (int x = 0; x < m.width; ++x) {
        EXPECT_FALSE(m.at(x, 0));
        EXPECT_FALSE(m.at(x, 17));
    }
}

// A RADIANCE 6 spectral picture is mapped as RADIANCE's falsecolor maps it after
// "ra_rgbe room.hsr room_rgbe.hdr" (RADIANCE 6.1a's own falsecolor stops at pcomb: "not
// a Radiance picture or float matrix"); both files are spectral_picture_test.cpp's.
TEST(FalseColor, SpectralInputAsAfterRaRgbe) {
    const std::string dir = std::string(RP_SOURCE_DIR) + "/tests/data/spectral/";
    auto mapped = [](const std::string& input) {
        FalseColorOptions o = parseFalseColorArgs({"-i", input, "-s", "50", "-e"});
        std::istringstream in;
        std::ostringstream out;
        runFalseColor(o, "falsecolor", in, out);
        std::istringstream back(out.str());
        return readPicture(back, "out.hdr").pixels;
    };
    EXPECT_EQ(mapped(dir + "room.hsr"), mapped(dir + "room_rgbe.hdr"));
}

}  // namespace
}  // namespace rp
