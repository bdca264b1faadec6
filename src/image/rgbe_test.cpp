// RGBE packing against RADIANCE's setcolr/colr_color values, and scanline codecs.
#include "image/rgbe.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

namespace rp {
namespace {

std::string decode(const std::string& bytes, std::vector<Colr>& scan) {
    std::istringstream in(bytes);
    return decodeScanline(*in.rdbuf(), scan.data(), static_cast<int>(scan.size()));
}

TEST(Rgbe, RadianceSetcolrValues) {
    // Hand-computed from setcolr(): d = max, scale = frexp(d)*256/d, truncate.
    EXPECT_EQ(toColr(1, 1, 1), (Colr{128, 128, 128, 129}));
    EXPECT_EQ(toColr(0.5, 0.25, 0.125), (Colr{128, 64, 32, 128}));
    EXPECT_EQ(toColr(0.3, 0.6, 0.9), (Colr{76, 153, 230, 128}));
    EXPECT_EQ(toColr(1000, 0, 0.001), (Colr{250, 0, 0, 138}));
    EXPECT_EQ(toColr(-1, 1, 0), (Colr{0, 128, 0, 129}));  // negatives clamp to 0
    EXPECT_EQ(toColr(1e-33, 1e-33, 1e-33), (Colr{0, 0, 0, 0}));
    EXPECT_EQ(toColr(0, 0, 0), (Colr{0, 0, 0, 0}));
    EXPECT_EQ(toColr(1e300, 1, 1), (Colr{255, 255, 255, 255}));  // saturates
    EXPECT_EQ(toColr(std::nan(""), 1, 1), (Colr{0, 128, 128, 129}));
}

TEST(Rgbe, RadianceColrColorValues) {
    // colr_color(): (m + 0.5) * 2^(e - 136).
    Pixel p = toPixel({128, 64, 32, 128});
    EXPECT_FLOAT_EQ(p[0], 128.5f / 256);
    EXPECT_FLOAT_EQ(p[1], 64.5f / 256);
    EXPECT_FLOAT_EQ(p[2], 32.5f / 256);
    p = toPixel({128, 128, 128, 129});
    EXPECT_FLOAT_EQ(p[0], 1.00390625f);
    p = toPixel({0, 0, 0, 0});
    EXPECT_EQ(p, (Pixel{0, 0, 0}));
    p = toPixel({250, 0, 0, 138});
    EXPECT_FLOAT_EQ(p[0], 250.5f * 4);
    EXPECT_FLOAT_EQ(p[1], 0.5f * 4);  // zero mantissas decode to half a step, as RADIANCE
}

TEST(Rgbe, RoundTripWithinOneStep) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> mant(0, 1), expo(-20, 20);
    for (int i = 0; i < 10000; ++i) {
        double s = std::exp2(expo(rng));
        double c[3] = {mant(rng) * s, mant(rng) * s, mant(rng) * s};
        double mx = std::max(c[0], std::max(c[1], c[2]));
        Colr packed = toColr(c[0], c[1], c[2]);
        Pixel p = toPixel(packed);
        // Truncation to 8 bits of the shared scale: error at most one mantissa step,
        // which is at most mx/128.
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], c[k], mx / 128) << i;
        // Packing the decoded value gives the same bytes back (decode is idempotent).
        EXPECT_EQ(toColr(p), packed);
    }
}

TEST(Rgbe, EncodeKnownBytes) {
    std::vector<Colr> scan(8, Colr{128, 128, 128, 129});
    std::string out;
    encodeScanline(scan.data(), 8, out);
    const unsigned char expect[] = {2, 2, 0, 8, 136, 128, 136, 128, 136, 128, 136, 129};
    EXPECT_EQ(out, std::string(reinterpret_cast<const char*>(expect), sizeof expect));

    // Short scanlines are flat.
    out.clear();
    encodeScanline(scan.data(), 3, out);
    EXPECT_EQ(out.size(), 12u);
}

TEST(Rgbe, RleRoundTripRunsAndNoise) {
    std::mt19937 rng(42);
    for (int len : {8, 9, 127, 128, 129, 300, 1000, 32767}) {
        std::vector<Colr> scan(len);
        for (int i = 0; i < len; ++i) {
            // Stretches of runs of random length (1..200) alternating with noise.
            if ((i / 37) % 2 == 0)
                scan[i] = i > 0 && rng() % 8 ? scan[i - 1] : Colr{200, 3, 3, 130};
            else
                scan[i] = {static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng() % 3),
                           static_cast<uint8_t>(rng()), 128};
        }
        std::string bytes;
        encodeScanline(scan.data(), len, bytes);
        std::vector<Colr> back(len);
        ASSERT_EQ(decode(bytes, back), "") << len;
        EXPECT_EQ(back, scan) << len;
        if (len >= 300) {
            EXPECT_LT(bytes.size(), scan.size() * 4) << "runs should compress";
        }
    }
}

TEST(Rgbe, OldStyleRuns) {
    // Pixel A, then 1,1,1,3 (repeat 3 times), then 1,1,1,1 (<< 8: 256 more).
    std::string bytes = {char(200), 10, 10, char(130), 1, 1, 1, 3};
    std::vector<Colr> scan(4);
    ASSERT_EQ(decode(bytes, scan), "");
    for (auto& c : scan) EXPECT_EQ(c, (Colr{200, 10, 10, 130}));

    std::string big = bytes + std::string{1, 1, 1, 1};
    std::vector<Colr> scan2(4 + 256);
    ASSERT_EQ(decode(big, scan2), "");
    EXPECT_EQ(scan2.back(), (Colr{200, 10, 10, 130}));

    // A run longer than the scanline, or with nothing to repeat, is corrupt.
    std::vector<Colr> small(3);
    EXPECT_EQ(decode(bytes, small), "bad run length");
    EXPECT_EQ(decode(std::string{1, 1, 1, 3}, small), "bad run length");
}

TEST(Rgbe, CorruptNewStyle) {
    std::vector<Colr> scan(8, Colr{128, 128, 128, 129});
    std::string bytes;
    encodeScanline(scan.data(), 8, bytes);
    std::vector<Colr> back(8);
    EXPECT_EQ(decode(bytes.substr(0, bytes.size() - 1), back), "truncated scanline");
    std::vector<Colr> wrongLen(9);
    EXPECT_EQ(decode(bytes, wrongLen), "scanline length mismatch");
    std::string overrun = bytes;
    overrun[4] = static_cast<char>(128 + 9);  // run of 9 in a scanline of 8
    EXPECT_EQ(decode(overrun, back), "bad run length");
    EXPECT_EQ(decode("", back), "truncated scanline");
}

}  // namespace
}  // namespace rp
