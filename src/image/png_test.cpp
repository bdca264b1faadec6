// PNG framing (CRC, Adler-32, stored deflate) and the display mapping of ra_png.
#include "image/png.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image/tonemap.h"
#include "util/error.h"

namespace rp {
namespace {

uint32_t be32(const std::string& s, size_t at) {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<uint8_t>(s[at + i]);
    return v;
}

TEST(Png, Checksums) {
    // Known values: every PNG ends with IEND and CRC ae426082; Adler-32 of "Wikipedia"
    // is 11e60398 (RFC 1950 example commonly quoted).
    const std::string iend = "IEND";
    EXPECT_EQ(pngCrc32(reinterpret_cast<const uint8_t*>(iend.data()), 4), 0xae426082u);
    const std::string w = "Wikipedia";
    EXPECT_EQ(adler32(reinterpret_cast<const uint8_t*>(w.data()), w.size()), 0x11e60398u);
}

TEST(Png, StructureAndStoredBlocks) {
    // 200 x 120 pixels: 72120 raw bytes, so two stored blocks.
    int w = 200, h = 120;
    std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 7);
    std::string png = encodePng(w, h, rgb, std::nullopt);
    ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(be32(png, 8), 13u);
    EXPECT_EQ(png.substr(12, 4), "IHDR");
    EXPECT_EQ(be32(png, 16), 200u);
    EXPECT_EQ(be32(png, 20), 120u);
    // Walk the chunks, checking every CRC, and collect the zlib stream.
    size_t pos = 8;
    std::string z, types;
    while (pos < png.size()) {
        uint32_t len = be32(png, pos);
        std::string type = png.substr(pos + 4, 4);
        types += type + " ";
        EXPECT_EQ(pngCrc32(reinterpret_cast<const uint8_t*>(png.data()) + pos + 4, len + 4),
                  be32(png, pos + 8 + len))
            << type;
        if (type == "IDAT") z += png.substr(pos + 8, len);
        pos += 12 + len;
    }
    EXPECT_EQ(pos, png.size());
    EXPECT_EQ(types, "IHDR sRGB IDAT IEND ");
    // Unwrap the stored blocks and compare with the filtered rows.
    ASSERT_EQ((static_cast<uint8_t>(z[0]) * 256 + static_cast<uint8_t>(z[1])) % 31, 0);
    std::string raw;
    size_t p = 2;
    bool last = false;
    while (!last) {
        last = z[p] & 1;
        EXPECT_EQ((z[p] >> 1) & 3, 0);
        size_t n = static_cast<uint8_t>(z[p + 1]) | (static_cast<uint8_t>(z[p + 2]) << 8);
        size_t nn = static_cast<uint8_t>(z[p + 3]) | (static_cast<uint8_t>(z[p + 4]) << 8);
        EXPECT_EQ(n ^ 0xffff, nn);
        raw += z.substr(p + 5, n);
        p += 5 + n;
    }
    ASSERT_EQ(raw.size(), static_cast<size_t>(h) * (1 + 3 * w));
    EXPECT_EQ(be32(z, p), adler32(reinterpret_cast<const uint8_t*>(raw.data()), raw.size()));
    for (int y = 0; y < h; ++y) {
        EXPECT_EQ(raw[y * (1 + 3 * w)], 0);
        EXPECT_EQ(static_cast<uint8_t>(raw[y * (1 + 3 * w) + 1]), rgb[y * 3 * w]);
    }
    EXPECT_NE(encodePng(1, 1, {1, 2, 3}, 2.2).find("gAMA"), std::string::npos);
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
    auto m = rgbFromXyz({0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290});
    // The published sRGB (D65) matrix, first row.
    EXPECT_NEAR(m[0], 3.2406, 2e-3);
    EXPECT_NEAR(m[1], -1.5372, 2e-3);
    EXPECT_NEAR(m[2], -0.4986, 2e-3);
}

}  // namespace
}  // namespace rp
