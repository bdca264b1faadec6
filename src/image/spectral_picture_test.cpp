// RADIANCE 6 spectral pictures: packing, round trips, the 8 orientations, header lines,
// bad input, the RGB views the tools use.
#include "image/spectral_picture.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include "image/tonemap.h"
#include "util/error.h"

namespace rp {
namespace {

// RADIANCE's default 380..780 nm sampling with n samples, as a reader fills it in.
spectral::Sampling sampling(int n) { return spectral::makeSampling(n, 780, 380)->sampling; }

// A picture whose samples are exactly representable and all different: pixel (x, y)
// sample i has mantissa 128 + x, y + i, ... under exponent 130.
SpectralPicture numbered(int w, int h, int n) {
    SpectralPicture pic(w, h, sampling(n));
    std::vector<uint8_t> packed(n + 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            packed[0] = static_cast<uint8_t>(128 + x);
            for (int i = 1; i < n; ++i) packed[i] = static_cast<uint8_t>(y + 7 * i);
            packed[n] = 130;
            unpackSpectrum(packed, pic.at(x, y));
        }
    return pic;
}

std::string bytesOf(const SpectralPicture& pic) {
    std::ostringstream out;
    writeSpectralPicture(out, pic);
    return out.str();
}

SpectralPicture parse(const std::string& bytes, const std::string& name = "test.hsr") {
    std::istringstream in(bytes);
    return readSpectralPicture(in, name);
}

std::string errorOf(const std::string& bytes) {
    try {
        parse(bytes, "bad.hsr");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(SpectralPicture, PackUnpackIsExactForRadianceBytes) {
    std::mt19937 rng(3);
    // Exponents from 23 up: below, every value is under scolor2scolr's 1e-32 black cut.
    std::uniform_int_distribution<int> byte(0, 255), big(128, 255), exp(23, 255);
    for (int t = 0; t < 20000; ++t) {
        const int n = 3 + t % 22;
        std::vector<uint8_t> in(n + 1), out(n + 1);
        for (int i = 0; i < n; ++i) in[i] = static_cast<uint8_t>(byte(rng));
        in[t % n] = static_cast<uint8_t>(big(rng));  // scolor2scolr's largest is >= 128
        in[n] = static_cast<uint8_t>(exp(rng));
        std::vector<float> v(n);
        unpackSpectrum(in, v);
        packSpectrum(v, out);
        ASSERT_EQ(in, out) << "t " << t;
    }
}

TEST(SpectralPicture, PackLikeRadiance) {
    std::vector<uint8_t> out(5);
    // 1.0 is 0.5 * 2^1: mantissa 128, exponent 129; negatives become 0.
    packSpectrum(std::vector<float>{1.0f, 0.5f, -2.0f, 0.25f}, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{128, 64, 0, 32, 129}));
    packSpectrum(std::vector<float>{0, 1e-33f, 0, 0}, out);
    EXPECT_EQ(out, (std::vector<uint8_t>(5, 0)));
    packSpectrum(std::vector<float>{3e38f, 1, 0, 0}, out);  // past the exponent byte
    EXPECT_EQ(out, (std::vector<uint8_t>(5, 255)));
    std::vector<float> v(4);
    unpackSpectrum(std::vector<uint8_t>{9, 9, 9, 9, 0}, v);  // exponent 0: black
    EXPECT_EQ(v, (std::vector<float>(4, 0.0f)));
}

TEST(SpectralPicture, RoundTripAndHeader) {
    for (int n : {3, 4, 18, 24}) {
        SpectralPicture pic = numbered(20, 3, n);
        pic.header.lines = {"rpict -cs 18 x.oct", "EXPOSURE=2"};
        const std::string b = bytesOf(pic);
        const std::string head =
            "#?RADIANCE\nrpict -cs 18 x.oct\nEXPOSURE=2\nNCOMP=" + std::to_string(n) +
            "\nFORMAT=Radiance_spectra\n\n-Y 3 +X 20\n";
        EXPECT_EQ(b.substr(0, head.size()), head);
        // Flat n+1 byte pixels, except 3 samples: an RGBE scanline (RLE for 20 pixels).
        if (n > 3) {
            EXPECT_EQ(b.size(), head.size() + 20 * 3 * (n + 1));
        } else {
            EXPECT_EQ(b.substr(head.size(), 2), "\x02\x02");
        }
        SpectralPicture back = parse(b);
        EXPECT_EQ(back.width, 20);
        EXPECT_EQ(back.height, 3);
        EXPECT_EQ(back.sampling, pic.sampling);
        EXPECT_EQ(back.samples, pic.samples);
        EXPECT_EQ(back.header.lines, (std::vector<std::string>{"rpict -cs 18 x.oct", "EXPOSURE=2",
                                                               "NCOMP=" + std::to_string(n)}));
        EXPECT_DOUBLE_EQ(back.exposure(), 2);
        EXPECT_EQ(bytesOf(back), b);
    }
}

TEST(SpectralPicture, NcompAndSplitsLinesFollowTheSampling) {
    SpectralPicture pic = numbered(2, 1, 4);
    // Lines that match stay as they are, where they are; others are rewritten.
    pic.header.lines = {"WAVELENGTH_SPLITS= 780 588 480 380", "NCOMP=9", "VIEW= -vtv"};
    pic.sampling.wl = {700, 600, 500, 400};
    std::string b = bytesOf(pic);
    EXPECT_NE(b.find("\nWAVELENGTH_SPLITS= 700 600 500 400\nNCOMP=4\nVIEW= -vtv\nFORMAT="),
              std::string::npos);
    SpectralPicture back = parse(b);
    EXPECT_EQ(back.sampling.wl, (std::array<double, 4>{700, 600, 500, 400}));
    EXPECT_EQ(bytesOf(back), b);
    // Missing lines are added (no WAVELENGTH_SPLITS= for RADIANCE's default, which
    // readers assume); fractional splits are read as RADIANCE's floats.
    pic.header.lines.clear();
    pic.sampling.wl = {780.5, 588, 480, 380};
    b = bytesOf(pic);
    EXPECT_NE(b.find("\nWAVELENGTH_SPLITS= 780.5 588 480 380\nNCOMP=4\nFORMAT="),
              std::string::npos);
    pic.sampling.wl = {780, 588, 480, 380};
    EXPECT_EQ(bytesOf(pic).find("WAVELENGTH"), std::string::npos);
    // No NCOMP= at all: RADIANCE's 3 samples, RGBE scanlines.
    SpectralPicture three = parse("#?RADIANCE\nFORMAT=Radiance_spectra\n\n-Y 1 +X 1\n" +
                                  std::string("\x80\x40\x20\x81", 4));
    EXPECT_EQ(three.sampling.n, 3);
    EXPECT_EQ(three.samples, (std::vector<float>{1.00390625f, 0.50390625f, 0.25390625f}));
}

// The 8 orientations, described independently of the reader, as picture_test.cpp does.
TEST(SpectralPicture, ReadsAllEightOrientations) {
    struct Orientation {
        const char* axes;
        bool columns, outerReversed, innerReversed;
    };
    const Orientation kOrients[] = {
        {"-Y %d +X %d", false, false, false}, {"-Y %d -X %d", false, false, true},
        {"+Y %d +X %d", false, true, false},  {"+Y %d -X %d", false, true, true},
        {"+X %d -Y %d", true, false, false},  {"+X %d +Y %d", true, false, true},
        {"-X %d -Y %d", true, true, false},   {"-X %d +Y %d", true, true, true},
    };
    const int w = 4, h = 3, n = 5;
    SpectralPicture pic = numbered(w, h, n);
    for (const auto& o : kOrients) {
        char res[64];
        std::snprintf(res, sizeof res, o.axes, o.columns ? w : h, o.columns ? h : w);
        std::string bytes =
            std::string("#?RADIANCE\nNCOMP=5\nFORMAT=Radiance_spectra\n\n") + res + "\n";
        const int outerN = o.columns ? w : h, innerN = o.columns ? h : w;
        std::vector<uint8_t> packed(n + 1);
        for (int s = 0; s < outerN; ++s) {
            const int outer = o.outerReversed ? outerN - 1 - s : s;
            for (int p = 0; p < innerN; ++p) {
                const int inner = o.innerReversed ? innerN - 1 - p : p;
                packSpectrum(pic.at(o.columns ? outer : inner, o.columns ? inner : outer), packed);
                bytes.append(packed.begin(), packed.end());
            }
        }
        SpectralPicture back = parse(bytes);
        EXPECT_EQ(back.width, w) << res;
        EXPECT_EQ(back.height, h) << res;
        EXPECT_EQ(back.samples, pic.samples) << res;
    }
}

TEST(SpectralPicture, BadInputIsInputError) {
    const std::string good = bytesOf(numbered(3, 2, 6));
    auto with = [&](const std::string& from, const std::string& to) {
        std::string b = good;
        b.replace(b.find(from), from.size(), to);
        return b;
    };
    EXPECT_EQ(errorOf(good.substr(0, good.size() - 1)),
              "bad.hsr: truncated scanline (scanline 2 of 2)");
    EXPECT_EQ(errorOf(with("-Y 2", "-Y 9")), "bad.hsr: truncated scanline (scanline 3 of 9)");
    EXPECT_EQ(errorOf(with("NCOMP=6", "NCOMP=2")),
              "bad.hsr: bad header line 'NCOMP=2' (3 to 24 samples)");
    EXPECT_EQ(errorOf(with("NCOMP=6", "NCOMP=25")),
              "bad.hsr: bad header line 'NCOMP=25' (3 to 24 samples)");
    EXPECT_EQ(errorOf(with("NCOMP=6", "NCOMP=six")),
              "bad.hsr: bad header line 'NCOMP=six' (3 to 24 samples)");
    EXPECT_EQ(errorOf(with("NCOMP=6", "WAVELENGTH_SPLITS= 380 480 588 780")),
              "bad.hsr: bad header line 'WAVELENGTH_SPLITS= 380 480 588 780' (4 wavelengths, "
              "longest first, in nm)");
    EXPECT_NE(errorOf(with("NCOMP=6", "WAVELENGTH_SPLITS= 780 588")).find("bad header line"),
              std::string::npos);
    EXPECT_EQ(errorOf(with("NCOMP=6", "EXPOSURE=x")), "bad.hsr: bad header line 'EXPOSURE=x'");
    EXPECT_EQ(errorOf(with("Radiance_spectra", "32-bit_rle_rgbe")),
              "bad.hsr: not a spectral picture (FORMAT=32-bit_rle_rgbe)");
    EXPECT_EQ(errorOf(with("-Y 2 +X 3", "-Y 2 X 3")), "bad.hsr: bad resolution line");
    EXPECT_NE(errorOf(good.substr(0, 15)).find("bad.hsr: truncated header"), std::string::npos);
    EXPECT_NE(errorOf("P6\n").find("bad.hsr: not a RADIANCE file"), std::string::npos);
    try {
        readSpectralPicture("/nonexistent/x.hsr");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/x.hsr: cannot open picture");
    }
    // An RGB-only reader names the file in one line.
    std::istringstream in(good);
    try {
        readPicture(in, "x.hsr");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "x.hsr: spectral picture (FORMAT=Radiance_spectra) where RGB is needed");
    }
}

TEST(SpectralPicture, RgbViews) {
    // 6 bands over 780..380 nm, centres 746.7 680 613.3 (red), 546.7 480 (green: not
    // below the 480 split, in RADIANCE's accumulated centres either), 413.3 (blue).
    SpectralPicture pic(1, 1, sampling(6));
    const std::vector<float> s = {1, 2, 3, 4, 5, 6};
    std::copy(s.begin(), s.end(), pic.at(0, 0).begin());
    pic.header.lines = {"a", "NCOMP=6", "WAVELENGTH_SPLITS= 780 588 480 380", "b"};
    Picture avg = toRgbPicture(pic, SpectralToRgb::kBandAverages);
    EXPECT_EQ(avg.pixels[0], (Pixel{2, 4.5f, 6}));
    EXPECT_EQ(avg.header.lines, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(avg.format, PictureFormat::kRgbe);
    Picture rgbe = toRgbPicture(pic, SpectralToRgb::kBandAveragesRgbe);
    EXPECT_EQ(rgbe.pixels[0], toPixel(toColr(2.0, 4.5, 6.0)));

    // readPictureAsRgb takes both kinds; a spectral one is read, then viewed.
    const std::string bytes = bytesOf(pic);
    std::istringstream a(bytes);
    EXPECT_EQ(readPictureAsRgb(a, "a.hsr", SpectralToRgb::kBandAverages).pixels,
              toRgbPicture(parse(bytes), SpectralToRgb::kBandAverages).pixels);
    Picture rgb(9, 2);
    rgb.at(3, 1) = toPixel(toColr(1.0, 2.0, 3.0));
    rgb.header.lines = {"rgb"};
    std::ostringstream out;
    writePicture(out, rgb);
    std::istringstream b(out.str());
    Picture back = readPictureAsRgb(b, "b.hdr", SpectralToRgb::kBandAverages);
    EXPECT_EQ(back.pixels, rgb.pixels);
    EXPECT_EQ(back.header.lines, rgb.header.lines);
    std::istringstream c("#?RADIANCE\nFORMAT=ascii\n\n");
    try {
        readPictureAsRgb(c, "c.txt", SpectralToRgb::kBandAverages);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "c.txt: not a RADIANCE picture (FORMAT=ascii)");
    }
}

// RADIANCE 6.1a's files in tests/data/spectral (made there; room.rad was scene.rad then):
//   oconv scene.rad > scene.oct
//   V="-vp 0 -2.5 1 -vd 0 1 0 -vh 50 -vv 40"
//   vwrays -ff $V -x 8 -y 6 -pj 0 |
//       rtrace -u- -ab 1 -aa 0 -ad 64 -ffc -co+ -cs 18 $(vwrays $V -x 8 -y 6 -d) scene.oct
//       > room.hsr
//   V2="-vp 0 -2.5 1 -vd 0 1 0 -vh 40 -vv 30"
//   vwrays -ff $V2 -x 4 -y 3 -pj 0 |
//       rtrace -u- -ab 0 -ffc -co+ -cs 12 -cw 700 400 $(vwrays $V2 -x 4 -y 3 -d) scene.oct
//       > room12.hsr
//   ra_rgbe room.hsr room_rgbe.hdr
std::string dataPath(const std::string& name) {
    return std::string(RP_SOURCE_DIR) + "/tests/data/spectral/" + name;
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SpectralPicture, RadianceFilesReadAndWriteBackByteForByte) {
    const SpectralPicture room = readSpectralPicture(dataPath("room.hsr"));
    EXPECT_EQ(room.width, 8);
    EXPECT_EQ(room.height, 6);
    EXPECT_EQ(room.sampling.n, 18);
    EXPECT_EQ(room.sampling.wl, (std::array<double, 4>{780, 588, 480, 380}));
    EXPECT_TRUE(room.paddedResolution);  // rtrace's "-Y        6 +X        8"
    // FORMAT= aside, the header as rtrace wrote it.
    ASSERT_EQ(room.header.lines.size(), 7u);
    EXPECT_EQ(room.header.lines[5], "NCOMP=18");
    EXPECT_EQ(room.header.lines[6], "WAVELENGTH_SPLITS= 780 588 480 380");
    EXPECT_EQ(bytesOf(room), fileBytes(dataPath("room.hsr")));

    const SpectralPicture room12 = readSpectralPicture(dataPath("room12.hsr"));
    EXPECT_EQ(room12.width, 4);
    EXPECT_EQ(room12.height, 3);
    EXPECT_EQ(room12.sampling.n, 12);
    EXPECT_EQ(room12.sampling.wl, (std::array<double, 4>{700, 588, 480, 400}));
    EXPECT_EQ(bytesOf(room12), fileBytes(dataPath("room12.hsr")));
    // The bulb seen in the middle of the top row: 12 samples of one lamp colour, the
    // bands' averages as RADIANCE's pvalue prints them (room12_pvalue.txt: 1.003e+01
    // 9.031e+00 7.031e+00).
    const Pixel bulb = toRgbPicture(room12, SpectralToRgb::kBandAverages).at(1, 0);
    EXPECT_NEAR(bulb[0], 10.03, 0.005);
    EXPECT_NEAR(bulb[1], 9.031, 0.0005);
    EXPECT_NEAR(bulb[2], 7.031, 0.0005);
}

TEST(SpectralPicture, RgbeViewIsRaRgbes) {
    const Picture ours =
        toRgbPicture(readSpectralPicture(dataPath("room.hsr")), SpectralToRgb::kBandAveragesRgbe);
    const Picture theirs = readPicture(dataPath("room_rgbe.hdr"));
    EXPECT_EQ(ours.pixels, theirs.pixels);
    // ra_rgbe's header: the input's without NCOMP= and WAVELENGTH_SPLITS=, then its name.
    std::vector<std::string> lines = ours.header.lines;
    lines.push_back("ra_rgbe");
    EXPECT_EQ(lines, theirs.header.lines);
}

// ra_png reads a spectral picture as RADIANCE 6's 8-bit converters do (ra_tiff, ra_bmp:
// fread2colrs), so the PNG is the one made from ra_rgbe's output.
TEST(SpectralPicture, RaPngAsAfterRaRgbe) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("rp_spectral_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const DisplayOptions& opt : {DisplayOptions{}, DisplayOptions{2.0, 2.2}}) {
        convertPictureToPng(dataPath("room.hsr"), (dir / "a.png").string(), opt);
        convertPictureToPng(dataPath("room_rgbe.hdr"), (dir / "b.png").string(), opt);
        EXPECT_EQ(fileBytes((dir / "a.png").string()), fileBytes((dir / "b.png").string()));
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace rp
