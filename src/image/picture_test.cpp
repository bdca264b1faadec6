// RADIANCE picture files: round trips, all 8 resolution orientations, header fields
// and one test per kind of bad input.
#include "image/picture.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "util/error.h"

namespace rp {
namespace {

// A picture whose pixels are exactly representable (decode(encode(p)) == p) and all
// different, so misplaced pixels show.
Picture numbered(int w, int h) {
    Picture pic(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            pic.at(x, y) =
                toPixel(Colr{static_cast<uint8_t>(128 + x), static_cast<uint8_t>(y), 7, 130});
    return pic;
}

std::string bytesOf(const Picture& pic) {
    std::ostringstream out;
    writePicture(out, pic);
    return out.str();
}

Picture parse(const std::string& bytes, const std::string& name = "test.hdr") {
    std::istringstream in(bytes);
    return readPicture(in, name);
}

std::string errorOf(const std::string& bytes) {
    try {
        parse(bytes, "bad.hdr");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Resolution, ParseAndFormat) {
    auto r = parseResolution("-Y 480 +X 640");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->xres, 640);
    EXPECT_EQ(r->yres, 480);
    EXPECT_TRUE(r->yMajor && r->yDecreasing && !r->xDecreasing);
    EXPECT_EQ(formatResolution(*r), "-Y 480 +X 640");
    r = parseResolution("+X 10 -Y 20");
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->yMajor);
    EXPECT_EQ(r->xres, 10);
    EXPECT_EQ(r->yres, 20);
    EXPECT_EQ(r->scanlineLength(), 20);
    EXPECT_EQ(formatResolution(*r), "+X 10 -Y 20");
    for (const char* bad : {"", "-Y 480", "-Y 480 +Y 640", "-Y 0 +X 5", "-Y -3 +X 5", "Y 4 X 5",
                            "-Y 4 +X 5 junk", "-Y 4.5 +X 5", "*Y 4 +X 5"})
        EXPECT_FALSE(parseResolution(bad)) << bad;
}

TEST(Picture, RoundTripRunsAndNoise) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0, 1);
    for (auto [w, h] : {std::pair{64, 5}, std::pair{5, 3}, std::pair{300, 2}}) {
        Picture pic(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                pic.at(x, y) = x < w / 2 ? Pixel{0.25f, 0.5f, 1.0f}  // a run
                                         : toPixel(toColr(u(rng), u(rng) * 10, u(rng) * 1e-3));
        pic.header.lines = {"rpict -x 64 scene.oct", "EXPOSURE=2.000000e+00"};
        // The run half is not exactly representable: compare after one quantisation.
        Picture expect = pic;
        for (auto& p : expect.pixels) p = toPixel(toColr(p));
        Picture back = parse(bytesOf(pic));
        EXPECT_EQ(back.width, w);
        EXPECT_EQ(back.height, h);
        EXPECT_EQ(back.pixels, expect.pixels);
        EXPECT_EQ(back.header.lines, pic.header.lines);
        EXPECT_EQ(back.format, PictureFormat::kRgbe);
    }
}

TEST(Picture, WrittenBytesStartLikeRadiance) {
    Picture pic = numbered(8, 2);
    pic.header.lines = {"rpict -vf v.vf"};
    std::string b = bytesOf(pic);
    const std::string head = "#?RADIANCE\nrpict -vf v.vf\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n";
    ASSERT_GT(b.size(), head.size());
    EXPECT_EQ(b.substr(0, head.size()), head);
    EXPECT_EQ(b.substr(head.size(), 4), std::string("\x02\x02\x00\x08", 4));
}

// The 8 orientations, described independently of the reader: outer loop over
// scanlines, inner over positions, with the direction each sign means.
struct Orientation {
    const char* axes;                   // printf format for the resolution line
    bool columns;                       // scanlines are columns (X written first)
    bool outerReversed, innerReversed;  // relative to left->right / top->bottom
};

TEST(Picture, ReadsAllEightOrientations) {
    const Orientation kOrients[] = {
        {"-Y %d +X %d", false, false, false}, {"-Y %d -X %d", false, false, true},
        {"+Y %d +X %d", false, true, false},  {"+Y %d -X %d", false, true, true},
        {"+X %d -Y %d", true, false, false},  {"+X %d +Y %d", true, false, true},
        {"-X %d -Y %d", true, true, false},   {"-X %d +Y %d", true, true, true},
    };
    for (auto [w, h] : {std::pair{9, 10}, std::pair{3, 2}}) {  // RLE and flat scanlines
        Picture pic = numbered(w, h);
        for (const auto& o : kOrients) {
            char res[64];
            if (o.columns)
                std::snprintf(res, sizeof res, o.axes, w, h);
            else
                std::snprintf(res, sizeof res, o.axes, h, w);
            std::string bytes = std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n") + res + "\n";
            int outerN = o.columns ? w : h, innerN = o.columns ? h : w;
            std::vector<Colr> scan(innerN);
            for (int s = 0; s < outerN; ++s) {
                int outer = o.outerReversed ? outerN - 1 - s : s;
                for (int p = 0; p < innerN; ++p) {
                    int inner = o.innerReversed ? innerN - 1 - p : p;
                    int x = o.columns ? outer : inner, y = o.columns ? inner : outer;
                    scan[p] = toColr(pic.at(x, y));
                }
                encodeScanline(scan.data(), innerN, bytes);
            }
            Picture back = parse(bytes);
            EXPECT_EQ(back.width, w) << res;
            EXPECT_EQ(back.height, h) << res;
            EXPECT_EQ(back.pixels, pic.pixels) << res;
        }
    }
}

TEST(Picture, HeaderFields) {
    Picture pic = numbered(2, 2);
    pic.header.lines = {"EXPOSURE=2",
                        "PIXASPECT=0.5",
                        "COLORCORR=1 2 3",
                        "EXPOSURE= 1.5",
                        "PRIMARIES=0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329",
                        "COLORCORR=2 2 2"};
    Picture back = parse(bytesOf(pic));
    EXPECT_DOUBLE_EQ(back.exposure(), 3.0);  // cumulative
    EXPECT_DOUBLE_EQ(back.pixelAspect(), 0.5);
    EXPECT_EQ(back.colorCorrection(), (std::array<double, 3>{2, 4, 6}));
    ASSERT_TRUE(back.primaries());
    EXPECT_DOUBLE_EQ((*back.primaries())[6], 0.3127);
    back.addExposure(0.5);
    EXPECT_DOUBLE_EQ(back.exposure(), 1.5);
    EXPECT_EQ(back.header.lines.back(), "EXPOSURE=5.000000e-01");
    EXPECT_DOUBLE_EQ(Picture().exposure(), 1.0);
    EXPECT_FALSE(Picture().primaries());
}

TEST(Picture, XyzeAndMissingFormat) {
    Picture pic = numbered(8, 1);
    pic.format = PictureFormat::kXyze;
    std::string b = bytesOf(pic);
    EXPECT_NE(b.find("FORMAT=32-bit_rle_xyze\n"), std::string::npos);
    EXPECT_EQ(parse(b).format, PictureFormat::kXyze);
    // Old pictures have no FORMAT line: RGBE.
    std::string noFormat = b;
    noFormat.erase(noFormat.find("FORMAT="), std::string("FORMAT=32-bit_rle_xyze\n").size());
    Picture old = parse(noFormat);
    EXPECT_EQ(old.format, PictureFormat::kRgbe);
    EXPECT_EQ(old.pixels, pic.pixels);
}

TEST(Picture, BadInputIsInputError) {
    std::string good = bytesOf(numbered(16, 4));
    // Not a RADIANCE file at all.
    EXPECT_NE(errorOf("P6\n16 4\n255\n").find("bad.hdr: not a RADIANCE file"), std::string::npos);
    // A RADIANCE file that is not a picture.
    EXPECT_NE(errorOf("#?RADIANCE\nFORMAT=Radiance_Global_kdT_Photon_Map\n\n-Y 1 +X 1\n")
                  .find("bad.hdr: not a RADIANCE picture (FORMAT=Radiance_Global_kdT_Photon_Map)"),
              std::string::npos);
    // Bad or missing resolution line.
    EXPECT_EQ(errorOf("#?RADIANCE\n\n-Y 4 X 16\n"), "bad.hdr: bad resolution line");
    EXPECT_EQ(errorOf("#?RADIANCE\n\n"), "bad.hdr: missing resolution line after header");
    EXPECT_EQ(errorOf("#?RADIANCE\n\n-Y 100000 +X 100000\n"),
              "bad.hdr: picture too large (-Y 100000 +X 100000)");
    // Few pixels in all, but one scanline longer than any real picture's (fuzz_picture).
    EXPECT_EQ(errorOf("#?RADIANCE\n\n-Y 1 +X 1666699776\n"),
              "bad.hdr: scanlines too long (-Y 1 +X 1666699776)");
    // Truncated in the header, in a scanline, and with whole scanlines missing.
    EXPECT_NE(errorOf(good.substr(0, 12)).find("truncated header"), std::string::npos);
    EXPECT_EQ(errorOf(good.substr(0, good.size() - 3)),
              "bad.hdr: truncated scanline (scanline 4 of 4)");
    std::string tooTall = good;
    tooTall.replace(tooTall.find("-Y 4"), 4, "-Y 5");
    EXPECT_EQ(errorOf(tooTall), "bad.hdr: truncated scanline (scanline 5 of 5)");
    // Malformed header field.
    std::string badExp = good;
    badExp.replace(badExp.find("FORMAT"), 0, "EXPOSURE=abc\n");
    EXPECT_EQ(errorOf(badExp), "bad.hdr: bad header line 'EXPOSURE=abc'");
    // Missing file.
    try {
        readPicture("/nonexistent/x.hdr");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/x.hdr: cannot open picture");
    }
}

TEST(Picture, WriteFileIsAtomicAndReadable) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("rp_image_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string path = (dir / "out.hdr").string();
    Picture pic = numbered(12, 3);
    writePicture(path, pic);
    EXPECT_EQ(readPicture(path).pixels, pic.pixels);
    // Only the final file remains: no temporary siblings.
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 1);
    // Unwritable target folder.
    EXPECT_THROW(writePicture((dir / "missing" / "x.hdr").string(), pic), InputError);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace rp
