#include "render/rcontrib_output.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "image/spectral_picture.h"
#include "render/rcontrib_run.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::render {
namespace {

RcontribOptions options(std::vector<ContribModifier> mods, char format = 'a', bool header = true) {
    RcontribOptions o = rcontribDefaults();
    o.modifiers = std::move(mods);
    o.outputFormat = format;
    o.header = header;
    o.commandWords = {"rcontrib", "-I+", "-m", "lamp"};
    return o;
}

ContribModifier mod(const std::string& name, int bins = 1, const std::string& out = "") {
    ContribModifier m;
    m.name = name;
    m.bins = bins;
    m.binExpr = bins > 1 ? "b" : "0";
    m.outSpec = out;
    return m;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The header with its date lines removed.
std::string stableHeader(const std::string& text) {
    std::istringstream in(text);
    std::string out, line;
    while (std::getline(in, line)) {
        if (line.rfind("CAPDATE=", 0) == 0 || line.rfind("GMT=", 0) == 0) continue;
        out += line + "\n";
        if (line.empty()) break;
    }
    return out;
}

TEST(ContribOutputName, RadiancesConversions) {
    std::string n;
    bool m = false, b = false;
    ASSERT_TRUE(contribOutputName("c_%s_%03d.txt", "sky", 7, n, m, b));
    EXPECT_EQ(n, "c_sky_007.txt");
    EXPECT_TRUE(m && b);
    ASSERT_TRUE(contribOutputName("%d_%s.txt", "sun", 2, n, m, b));  // either order
    EXPECT_EQ(n, "2_sun.txt");
    ASSERT_TRUE(contribOutputName("100%%_%x", "s", 255, n, m, b));
    EXPECT_EQ(n, "100%_ff");
    EXPECT_FALSE(m);
    EXPECT_FALSE(contribOutputName("x_%s_%s.txt", "a", 0, n, m, b));
    EXPECT_FALSE(contribOutputName("x_%d_%i.txt", "a", 0, n, m, b));
    EXPECT_FALSE(contribOutputName("x_%f.txt", "a", 0, n, m, b));
}

TEST(ContribOutput, StandardOutputHeaderAndRecordsAsRadiance) {
    // Layout checked against RADIANCE 5.4a: `rcontrib -I+ -m lampA -m lampB -m skyglow`
    // writes NCOMP=3, NCOLS=<values per record>, FORMAT=ascii, and each record as
    // "%.6e\t" per component with a newline after the last tab.
    RcontribOptions o = options({mod("lamp"), mod("sky", 2)});
    std::ostringstream out;
    ContribOutput co(o, {"oconv scene.rad"}, out);
    co.writeRecord({Color{1, 2, 3}, Color{0.5, 0, 0}, Color{}}, 1, false);
    co.writeRecord({Color{2, 4, 6}, Color{}, Color{1, 1, 1}}, 0.5, false);
    co.close();
    const std::string text = out.str();
    EXPECT_EQ(stableHeader(text),
              "#?RADIANCE\noconv scene.rad\nrcontrib -I+ -m lamp\nSOFTWARE= radphoton\n"
              "NCOMP=3\nNCOLS=3\nFORMAT=ascii\n\n");
    EXPECT_NE(text.find("\n\n1.000000e+00\t2.000000e+00\t3.000000e+00\t5.000000e-01\t"
                        "0.000000e+00\t0.000000e+00\t0.000000e+00\t0.000000e+00\t0.000000e+00\t\n"
                        "1.000000e+00\t2.000000e+00\t3.000000e+00\t0.000000e+00\t"),
              std::string::npos)
        << text;
}

TEST(ContribOutput, FilesPerModifierAndBin) {
    TempDir dir;
    const std::string spec = dir.file("c_%s_%d.dat");
    RcontribOptions o = options({mod("sky", 2, spec)}, 'f');
    std::ostringstream out;
    {
        ContribOutput co(o, {}, out);
        co.writeRecord({Color{1, 2, 3}, Color{4, 5, 6}}, 1, true);
        co.close();
    }
    EXPECT_TRUE(out.str().empty());
    const std::string f1 = slurp(dir.file("c_sky_1.dat"));
    // RADIANCE compat: MODIFIER= and BIN= for files, byte order for binary formats.
    const std::string h = stableHeader(f1);
    EXPECT_NE(h.find("MODIFIER=sky\nBIN=1\nNCOLS=1\nBigEndian=0\nFORMAT=float\n\n"),
              std::string::npos)
        << h;
    const size_t data = f1.find("\n\n") + 2;
    ASSERT_EQ(f1.size(), data + 12);
    float v[3];
    std::memcpy(v, f1.data() + data, sizeof v);
    EXPECT_EQ(v[0], 4);
    EXPECT_EQ(v[2], 6);
}

TEST(ContribOutput, ExistingFileIsKeptWithoutForce) {
    TempDir dir;
    const std::string f = dir.file("lamp.txt");
    std::ofstream(f) << "precious";
    RcontribOptions o = options({mod("lamp", 1, f)});
    std::ostringstream out;
    try {
        ContribOutput co(o, {}, out);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot open '" + f + "' for writing: File exists");
    }
    EXPECT_EQ(slurp(f), "precious");
    o.force = true;
    ContribOutput co(o, {}, out);
    co.writeRecord({Color{1, 1, 1}}, 1, false);
    co.close();
    EXPECT_NE(slurp(f).find("1.000000e+00"), std::string::npos);
}

TEST(ContribOutput, PicturesOfSeveralModifiersTakeTheirOwnBinNumbers) {
    // rcontrib.c addmodifier: with -fc -x -y, "img_%d.hdr" shared by two modifiers gives
    // the second bins 1.. instead of writing both into img_0.hdr.
    TempDir dir;
    RcontribOptions o =
        options({mod("a", 1, dir.file("img_%d.hdr")), mod("b", 2, dir.file("img_%d.hdr"))}, 'c');
    o.xres = 1;
    o.yres = 1;
    std::ostringstream out;
    ContribOutput co(o, {}, out);
    co.writeRecord({Color{1, 1, 1}, Color{2, 2, 2}, Color{3, 3, 3}}, 1, false);
    co.close();
    for (int k = 0; k < 3; ++k) {
        const std::string t = slurp(dir.file("img_" + std::to_string(k) + ".hdr"));
        EXPECT_NE(t.find("\n\n-Y 1 +X 1\n"), std::string::npos) << k;
    }
    EXPECT_NE(slurp(dir.file("img_2.hdr")).find("MODIFIER=b\nBIN=2\nNROWS=1\n"), std::string::npos);
}

// Three rays of `values` values each to `file` (one modifier's), the file cut inside its
// third record as a killed run leaves it, and -r continuing it: two records are kept,
// and the file ends as the whole run's.
void expectRecovered(RcontribOptions o, const std::string& file, size_t values,
                     const ContribTraceFn& trace) {
    std::ostringstream out;
    RcontribRunSettings s;
    s.values = values;
    const std::string rays = "0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n";
    {
        std::istringstream in(rays);
        ContribOutput co(o, {}, out);
        runRcontrib(s, in, &co, trace);
    }
    const std::string full = slurp(file);
    std::filesystem::resize_file(file, full.size() - 20);
    o.recover = true;
    {
        ContribOutput co(o, {}, out);
        s.skipRecords = co.recover();
        EXPECT_EQ(s.skipRecords, 2u);
        std::istringstream in(rays);
        runRcontrib(s, in, &co, trace);
    }
    EXPECT_EQ(slurp(file), full);
}

// A run that stops after `n` records leaves files that -r continues.
TEST(ContribOutput, RecoverKeepsCompleteRecords) {
    TempDir dir;
    expectRecovered(options({mod("lamp", 2, dir.file("r_%s.bin"))}, 'd'), dir.file("r_lamp.bin"), 2,
                    [](const Vec3&, const Vec3&, uint64_t i, double, std::vector<Color>& v) {
                        v[0] = Color::grey(double(i));
                        v[1] = Color::grey(10.0 + double(i));
                    });
}

// Two runs of two rays with -c 0, the second with -r reloading the first's totals
// (rc2.c reload_output); `values` per ray from `trace`.
void runTwiceReloading(RcontribOptions o, size_t values, const ContribTraceFn& trace) {
    o.accumulate = 0;
    RcontribRunSettings s;
    s.values = values;
    s.accumulate = 0;
    std::ostringstream out;
    for (int run = 0; run < 2; ++run) {
        std::istringstream in("0 0 0 0 0 1\n0 0 0 0 0 1\n");
        ContribOutput co(o, {}, out);
        if (run == 1) s.totals = co.reload();
        runRcontrib(s, in, &co, trace);
        o.recover = true;
    }
}

TEST(ContribOutput, ReloadAddsToTotals) {
    // rc2.c reload_output: with -c 0 and -r, a second run adds to what the files hold.
    TempDir dir;
    runTwiceReloading(options({mod("lamp", 2, dir.file("t_%s.txt"))}), 2,
                      [](const Vec3&, const Vec3&, uint64_t i, double, std::vector<Color>& v) {
                          v[0] = Color::grey(1.0 + double(i));
                          v[1] = Color{0.5, 0, 0};
                      });
    const std::string t = slurp(dir.file("t_lamp.txt"));
    EXPECT_NE(t.find("\n\n6.000000e+00\t6.000000e+00\t6.000000e+00\t2.000000e+00\t0.000000e+00"),
              std::string::npos)
        << t;
}

TEST(ContribOutput, RecoveryRules) {
    RcontribOptions o = options({mod("lamp")});
    o.recover = true;
    std::ostringstream out;
    ContribOutput ascii(o, {}, out);
    EXPECT_THROW(ascii.recover(), InputError);  // "cannot recover ASCII output"
    o.outputFormat = 'f';
    ContribOutput toStdout(o, {}, out);
    EXPECT_THROW(toStdout.recover(), InputError);  // "cannot recover from stdout"
}

// -cs 9 (RADIANCE 6's rcontrib): the nine samples of a bin come from three passes, pass p
// giving samples 3p..3p+2 (rcontrib_tool.cpp lays values out pass by pass).
void spectralTrace(const Vec3&, const Vec3&, uint64_t i, double, std::vector<Color>& v) {
    for (size_t p = 0; p < 3; ++p)
        v[p] = Color{1.0 + double(3 * p) + double(i), 2.0 + double(3 * p), 3.0 + double(3 * p)};
}

// -fc with spectral samples writes RADIANCE 6.1a's hyperspectral pictures: FORMAT=
// Radiance_spectra, its padded resolution line and n+1 byte common-exponent pixels (the
// same bytes as RADIANCE 6.1a's rcontrib -cs 9 -fac -x 2 -y 2 wrote for the lamps of
// ../shared/validation/contrib, checked by hand when this was written).
TEST(ContribOutput, SpectralPicturesAreRadiance6s) {
    TempDir dir;
    RcontribOptions o = options({mod("lamp", 1, dir.file("p_%s.hsr"))}, 'c');
    o.render.spectralSamples = 9;
    o.xres = 2;
    o.yres = 2;
    std::ostringstream out;
    RcontribRunSettings s;
    s.values = 3;
    {
        std::istringstream in("0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n");
        ContribOutput co(o, {}, out);
        runRcontrib(s, in, &co, spectralTrace);
    }
    const std::string pic = slurp(dir.file("p_lamp.hsr"));
    EXPECT_NE(pic.find("NCOMP=9\nWAVELENGTH_SPLITS= 780 588 480 380\n"), std::string::npos);
    EXPECT_NE(pic.find("FORMAT=Radiance_spectra\n\n-Y        2 +X        2\n"), std::string::npos)
        << pic;
    const size_t data = pic.find("+X        2\n") + 12;
    ASSERT_EQ(pic.size() - data, 4u * 10u);  // four pixels of 9 mantissas and an exponent
    float v[9];  // the second pixel (ray 1): samples 3p + c are c + 1 + 3p, plus 1 for c = 0
    unpackSpectrum({reinterpret_cast<const uint8_t*>(pic.data() + data + 10), 10}, v);
    for (int k = 0; k < 9; ++k) {
        const double want = double(k % 3 + 1 + k / 3 * 3) + (k % 3 == 0 ? 1 : 0);
        EXPECT_NEAR(v[k], want, want / 64) << k;  // 8-bit mantissas under a shared exponent
    }
}

// -r continues spectral records as RGB ones, and with -c 0 reloads the nine samples of
// each bin into the passes' totals.
TEST(ContribOutput, SpectralRecoverAndReload) {
    TempDir dir;
    RcontribOptions o = options({mod("lamp", 1, dir.file("r_%s.bin"))}, 'f');
    o.render.spectralSamples = 9;
    expectRecovered(o, dir.file("r_lamp.bin"), 3, spectralTrace);

    RcontribOptions t = options({mod("lamp", 1, dir.file("t_%s.txt"))});
    t.render.spectralSamples = 9;
    runTwiceReloading(t, 3, spectralTrace);
    // Each run adds rays 0 and 1: sample 0 is (1 + 0) + (1 + 1) = 3 a run, sample 8 is 9 + 9.
    const std::string text = slurp(dir.file("t_lamp.txt"));
    EXPECT_NE(text.find("\n\n6.000000e+00\t8.000000e+00\t1.200000e+01\t1.800000e+01"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("3.600000e+01\t\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace rp::render
