// PNG files (read back with libpng, compressed) and the display mapping of ra_png.
#include "image/png.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cmath>

#include "image/tonemap.h"
#include "util/error.h"
#include "util/spectrum.h"

namespace rp {
namespace {

uint32_t be32(const std::string& s, size_t at) {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<uint8_t>(s[at + i]);
    return v;
}

// Chunk types in file order.
std::string chunkTypes(const std::string& png) {
    std::string types;
    for (size_t pos = 8; pos + 8 <= png.size();) {
        const uint32_t len = be32(png, pos);
        types += png.substr(pos + 4, 4) + " ";
        pos += 12 + len;
    }
    return types;
}

// The pixels libpng's own reader gets back (it checks every CRC and the zlib stream).
std::vector<uint8_t> decode(const std::string& png, int& w, int& h) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    EXPECT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size()));
    image.format = PNG_FORMAT_RGB;
    std::vector<uint8_t> out(PNG_IMAGE_SIZE(image));
    EXPECT_TRUE(png_image_finish_read(&image, nullptr, out.data(), 0, nullptr));
    w = int(image.width);
    h = int(image.height);
    return out;
}

TEST(Png, RoundTripThroughLibpng) {
    const int w = 200, h = 120;
    std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 7);
    const std::string png = encodePng(w, h, rgb, std::nullopt);
    ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png.substr(12, 4), "IHDR");
    EXPECT_EQ(be32(png, 16), 200u);
    EXPECT_EQ(be32(png, 20), 120u);
    EXPECT_EQ(chunkTypes(png).substr(0, 10), "IHDR sRGB ");
    int dw = 0, dh = 0;
    EXPECT_EQ(decode(png, dw, dh), rgb);
    EXPECT_EQ(dw, w);
    EXPECT_EQ(dh, h);
    const std::string g = encodePng(1, 1, {1, 2, 3}, 2.2);
    EXPECT_NE(chunkTypes(g).find("gAMA"), std::string::npos);
    EXPECT_EQ(chunkTypes(g).find("sRGB"), std::string::npos);
    EXPECT_EQ(be32(g, g.find("gAMA") + 4), uint32_t(std::lround(100000 / 2.2)));
}

// Pictures compress: a smooth 400 x 400 rendering-like gradient, 480 kB raw (what the
// stored blocks we used to write took), is a few kB.
TEST(Png, Compressed) {
    const int w = 400, h = 400;
    std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(size_t(y) * w + x) * 3 + c] = static_cast<uint8_t>((x + y * (c + 1)) / 4);
    const std::string png = encodePng(w, h, rgb, std::nullopt);
    EXPECT_LT(png.size(), size_t(60000)) << png.size();
    int dw = 0, dh = 0;
    EXPECT_EQ(decode(png, dw, dh), rgb);
}

TEST(Tonemap, ExposureArgument) {
    EXPECT_DOUBLE_EQ(parseExposureArg("+2"), 4);
    EXPECT_DOUBLE_EQ(parseExposureArg("-1"), 0.5);
    EXPECT_DOUBLE_EQ(parseExposureArg("0.25"), 0.25);
    EXPECT_THROW(parseExposureArg("0"), InputError);
    EXPECT_THROW(parseExposureArg("bright"), InputError);
}

TEST(Tonemap, AutoExposureMapsLogAverageToMidGrey) {
    Picture pic(2, 1);
    pic.at(0, 0) = {2, 2, 2};
    pic.at(1, 0) = {8, 8, 8};  // log-average 4
    EXPECT_NEAR(autoExposure(pic), 0.18 / 4, 1e-6);
    EXPECT_EQ(autoExposure(Picture(3, 3)), 1.0);  // black
}

TEST(Tonemap, SrgbGammaAndXyz) {
    Picture pic(3, 1);
    pic.at(0, 0) = {0.18f, 1.0f, 2.0f};
    pic.at(1, 0) = {0.0031308f, 0, -1};
    auto v = toDisplayRgb8(pic, 1, std::nullopt);
    EXPECT_EQ(v[0], 118);  // sRGB(0.18) = 0.4614
    EXPECT_EQ(v[1], 255);
    EXPECT_EQ(v[2], 255);  // clipped
    EXPECT_EQ(v[3], 10);   // linear segment: 0.04045 * 255
    EXPECT_EQ(v[5], 0);
    auto g = toDisplayRgb8(pic, 0.5, 2.0);
    EXPECT_EQ(g[1], std::lround(std::sqrt(0.5) * 255));
    // XYZ white (equal energy) stays neutral; primaries map to themselves.
    Picture xyz(1, 1);
    xyz.format = PictureFormat::kXyze;
    xyz.at(0, 0) = {0.4f, 0.4f, 0.4f};
    auto n = toDisplayRgb8(xyz, 1, 1.0);
    EXPECT_EQ(n[0], 102);
    EXPECT_EQ(n[1], 102);
    EXPECT_EQ(n[2], 102);
    auto m = spectral::rgbFromXyz({0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290});
    // The published sRGB (D65) matrix, first row.
    EXPECT_NEAR(m[0], 3.2406, 2e-3);
    EXPECT_NEAR(m[1], -1.5372, 2e-3);
    EXPECT_NEAR(m[2], -0.4986, 2e-3);
}

}  // namespace
}  // namespace rp
