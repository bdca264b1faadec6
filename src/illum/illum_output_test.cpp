// mkillum's text (RADIANCE mkillum3.c's layout, the strings below as RADIANCE 5.4
// printed them) and its data files, read back with calc/data_file.h at the coordinates
// illum.cal gives the direction each bin's light leaves in.
#include "illum/illum_output.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "calc/data_file.h"
#include "util/temp_dir_for_tests.h"

namespace rp::illum {
namespace {

InputObject object(const std::string& mod, PrimType type, const std::string& typeName,
                   const std::string& name, std::vector<double> rargs) {
    InputObject o;
    o.modifier = mod;
    o.type = type;
    o.typeName = typeName;
    o.name = name;
    o.rargs = std::move(rargs);
    return o;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// A distribution whose bin (i, j) holds `samples` times 1 + i + j / 10.
Distribution ramp(int nalt, int nazi, int samples) {
    Distribution d;
    d.altitudes = nalt;
    d.azimuths = nazi;
    d.samples = samples;
    for (int i = 0; i < nalt; ++i)
        for (int j = 0; j < nazi; ++j) d.sums.push_back(Color::grey(samples * (1 + i + j / 10.0)));
    return d;
}

TEST(IllumOutput, ObjectsInRadianceLayout) {
    const InputObject pipe =
        object("wall_paint", PrimType::Cylinder, "cylinder", "pipe", {1, 1, 0, 1, 1, 2, .1});
    EXPECT_EQ(formatObject(pipe.modifier, pipe),
              "\nwall_paint cylinder pipe\n0\n0\n7\n"
              "                  1                  1                  0\n"
              "                  1                  1                  2\n"
              "                0.1\n");
    InputObject glass = object("void", PrimType::Glass, "glass", "g", {.92, .92, .92});
    glass.sargs = {"a"};
    EXPECT_EQ(formatObject("void", glass),
              "\nvoid glass g\n1 a\n0\n3\n               0.92               0.92               "
              "0.92\n");
    // Surfaces modified by void are dropped; modifiers are not.
    EXPECT_EQ(formatObject("void", object("void", PrimType::Polygon, "polygon", "p", {})), "");
    InputObject alias = object("void", PrimType::Alias, "alias", "other_paint", {});
    alias.aliasOf = "wall_paint";
    EXPECT_EQ(formatAlias(alias), "\nvoid alias other_paint\twall_paint\n");
}

TEST(IllumOutput, IllumAndLightMaterials) {
    IllumSettings s;
    const InputObject win = object("pane_glass", PrimType::Polygon, "polygon", "window",
                                   {0, -1, .5, 0, 1, .5, 0, 1, 1.5});
    s.colour = ColourMode::kAverage;
    EXPECT_TRUE(startsWith(
        formatIllum(s, "pane_glass", Color{0.483316, 0.516245, 0.591257}, win),
        "\nillum_mat.dist illum illum_mat\n1 pane_glass\n0\n3 0.483316 0.516245 0.591257\n"
        "\nillum_mat polygon window\n0\n0\n9\n"));
    s.light = true;
    s.density = 0;
    s.material = "named";
    s.colour = ColourMode::kNone;  // the brightness in each channel
    EXPECT_TRUE(startsWith(formatIllum(s, "wall_paint", Color{1, 1, 1}, win),
                           "\nvoid light named\n0\n0\n3 1.000000 1.000000 1.000000\n\nnamed "));
    s.light = false;
    EXPECT_TRUE(
        startsWith(formatIllum(s, "void", Color{1, 1, 1}, win), "\nvoid illum named\n0\n0\n3 1."));
}

TEST(IllumOutput, DataFileText) {
    EXPECT_EQ(formatDataFile(1.125, .125, {{1, 2, 3}, {4, 5, -6}}),
              "2\n1.125000 0.125000 2\n0.000000 6.283185 4\n\n"
              " 1.000000e+00 2.000000e+00 3.000000e+00 1.000000e+00 4.000000e+00\n"
              " 5.000000e+00 -6.000000e+00 4.000000e+00\n");
}

TEST(IllumOutput, FileNamesCountUpUnlessClobbered) {
    TempDir dir;
    IllumSettings s;
    s.dataFile = "win";
    EXPECT_EQ(nextDataFile(s, 0, dir.path().string()), "win.dat");
    { std::ofstream(dir.file("win.dat")) << "x"; }
    { std::ofstream(dir.file("win1.dat")) << "x"; }
    EXPECT_EQ(nextDataFile(s, 0, dir.path().string()), "win2.dat");
    EXPECT_EQ(nextDataFile(s, 'R', dir.path().string()), "winR2.dat");
    s.clobber = true;
    s.dataFileNumber = 0;
    EXPECT_EQ(nextDataFile(s, 0, dir.path().string()), "win.dat");
}

TEST(IllumOutput, FlatFileReadsBackAtIllumCalCoordinates) {
    TempDir dir;
    IllumSettings s;
    s.dataFile = "flat";
    s.clobber = true;
    const Distribution d = ramp(4, 13, 10);
    const Color average = d.average();
    const FlatFrame f{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
    const std::string text = writeFlatDistribution(s, d, average, f, dir.path().string());
    EXPECT_EQ(text,
              "\nvoid brightdata illum_mat.dist\n5 noneg flat.dat\n\tillum.cal il_alth il_azih\n"
              "0\n9\n\t0.000000\t1.000000\t0.000000\n\t0.000000\t0.000000\t1.000000\n"
              "\t1.000000\t0.000000\t0.000000\n");
    EXPECT_EQ(s.dataFileNumber, 1);
    const calc::DataFile data = calc::DataFile::load(dir.file("flat.dat"));
    const double norm = illumBrightness(average);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 13; ++j) {
            // The bin's centre: il_alth = cos^2 of the way the light leaves, il_azih its
            // angle about the normal from u.
            const double alth = 1 - (i + .5) / 4, azih = 2 * kPi * j / 13;
            const double want = illumBrightness(d.sums[size_t(i * 13 + j)]) / 10 / norm;
            EXPECT_NEAR(data.value(std::vector<double>{alth, azih}), want, 1e-6 * want);
        }
    // Across the pole the first row is mirrored about its mean (1.6 here).
    EXPECT_NEAR(data.value(std::vector<double>{1 + .125, 0}), (2 * 1.6 - 1) / norm, 1e-6);
}

TEST(IllumOutput, ColourSphereFiles) {
    TempDir dir;
    IllumSettings s;
    s.dataFile = "ball";
    s.material = "ball";
    s.clobber = true;
    s.colour = ColourMode::kDistribution;
    Distribution d = ramp(3, 4, 2);
    for (Color& c : d.sums) c.b = 0;  // a channel the average lacks is written as zeros
    const Color average = d.average();
    const std::string text = writeRoundDistribution(s, d, average, dir.path().string());
    EXPECT_EQ(text,
              "\nvoid colordata ball.dist\n9 red green blue ballR.dat ballG.dat ballB.dat\n"
              "\tillum.cal il_alt il_azi\n0\n0\n");
    const calc::DataFile red = calc::DataFile::load(dir.file("ballR.dat"));
    EXPECT_EQ(red.axis(0).count, 5);                    // the rows and a mirrored row at each pole
    EXPECT_NEAR(red.axis(0).begin, 1 + 1.0 / 3, 1e-6);  // printed "%f"
    EXPECT_NEAR(red.axis(0).end, -1 - 1.0 / 3, 1e-6);
    for (int i = 0; i < 3; ++i)  // row i at z = 1 - (2i + 1)/n
        EXPECT_NEAR(red.value(std::vector<double>{1 - (2 * i + 1) / 3.0, 2 * kPi / 4}),
                    (1 + i + .1) / average.r, 1e-6);
    const calc::DataFile blue = calc::DataFile::load(dir.file("ballB.dat"));
    EXPECT_EQ(blue.value(std::vector<double>{0, 1}), 0);
}

}  // namespace
}  // namespace rp::illum
