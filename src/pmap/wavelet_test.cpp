#include "pmap/wavelet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "util/rng.h"

namespace rp::pmap {
namespace {

TEST(Wavelet, D4IsOrthonormalAndInvertible) {
    Rng rng(7, RngDomain::Sampling, 1);
    for (size_t n : {4u, 8u, 64u, 152u, 256u}) {
        std::vector<double> x(n), y, t;
        for (double& v : x) v = rng.uniform() - 0.3;
        y = x;
        d4Forward(y, t);
        double ex = 0, ey = 0;
        for (size_t i = 0; i < n; ++i) ex += x[i] * x[i], ey += y[i] * y[i];
        EXPECT_NEAR(ex, ey, 1e-12 * ex) << n;  // Parseval
        d4Inverse(y, t);
        for (size_t i = 0; i < n; ++i) EXPECT_NEAR(x[i], y[i], 1e-12) << n << " " << i;
    }
}

TEST(Wavelet, D4ConstantHasNoDetail) {
    // The wavelet filter sums to zero: a constant keeps only approximation coefficients.
    std::vector<double> x(16, 2.5), t;
    d4Forward(x, t);
    for (size_t i = 2; i < x.size(); ++i) EXPECT_NEAR(x[i], 0, 1e-12) << i;
}

std::vector<Rgb> skyLike(int bins) {
    // A smooth sky with one bright sun bin: what a sensor sees through a window.
    std::vector<Rgb> v(static_cast<size_t>(bins));
    for (int b = 0; b < bins; ++b) {
        double s = 1 + 0.5 * std::sin(b * 0.2);
        v[size_t(b)] = {s, 0.9 * s, 0.8 * s};
    }
    v[size_t(bins / 3)] = {60, 55, 50};
    return v;
}

TEST(Wavelet, RawRecordsAreExactFloats) {
    CoeffCodec codec(145, 0);
    ASSERT_TRUE(codec.raw());
    EXPECT_EQ(codec.recordBytes(), 145u * 12);
    std::vector<Rgb> in = skyLike(145), out(145);
    std::vector<uint8_t> rec(codec.recordBytes());
    CoeffCodec::Scratch s;
    codec.encode(in, rec.data(), s);
    codec.decode(rec.data(), out, s);
    for (size_t b = 0; b < in.size(); ++b)
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(float(in[b][c]), float(out[b][c]));
}

double relativeRms(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
    double num = 0, den = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            num += (a[i][c] - b[i][c]) * (a[i][c] - b[i][c]);
            den += a[i][c] * a[i][c];
        }
    return std::sqrt(num / den);
}

TEST(Wavelet, AllCoefficientsKeptReconstructToQuantisation) {
    CoeffCodec codec(145, 1e-9);  // keeps all 152
    ASSERT_EQ(codec.kept(), 152);
    std::vector<Rgb> in = skyLike(145), out(145);
    std::vector<uint8_t> rec(codec.recordBytes());
    CoeffCodec::Scratch s;
    codec.encode(in, rec.data(), s);
    codec.decode(rec.data(), out, s);
    // 8-bit mantissas: each coefficient within 1/254 of its largest component.
    EXPECT_LT(relativeRms(in, out), 4e-3);
    EXPECT_EQ(codec.recordBytes(), 152u * 5);
}

TEST(Wavelet, ErrorGrowsAsCoefficientsAreDropped) {
    std::vector<Rgb> in = skyLike(145), out(145);
    CoeffCodec::Scratch s;
    double last = 0;
    for (double comp : {0.5, 0.8, 0.9, 0.97}) {
        CoeffCodec codec(145, comp);
        std::vector<uint8_t> rec(codec.recordBytes());
        codec.encode(in, rec.data(), s);
        codec.decode(rec.data(), out, s);
        const double e = relativeRms(in, out);
        EXPECT_GE(e, last * 0.999) << comp;
        last = e;
        // Measured 0.0040, 0.0060, 0.013, 0.18 (86, 46, 32, 23 of 152 kept, 19 of them the
        // approximation): the sun bin and the smooth sky survive; at 0.5 the error is the
        // 8-bit mantissas' (4e-3 with all kept).
        if (comp == 0.5) {
            EXPECT_LT(e, 0.005);
        }
        if (comp == 0.8) {
            EXPECT_LT(e, 0.01);
        }
    }
    EXPECT_GT(last, 0.05);  // 4 details cannot hold a sine and a spike
}

TEST(Wavelet, OneBinAndZeroRecords) {
    CoeffCodec codec(1, 0.5);
    EXPECT_EQ(codec.length(), 8);
    std::vector<Rgb> in = {{3, 2, 1}}, out(1);
    std::vector<uint8_t> rec(codec.recordBytes());
    CoeffCodec::Scratch s;
    codec.encode(in, rec.data(), s);
    codec.decode(rec.data(), out, s);
    EXPECT_NEAR(out[0][0], 3, 0.02);
    EXPECT_NEAR(out[0][2], 1, 0.02);
    std::vector<Rgb> zero(145, Rgb{0, 0, 0}), back(145);
    CoeffCodec c2(145, 0.9);
    rec.resize(c2.recordBytes());
    c2.encode(zero, rec.data(), s);
    c2.decode(rec.data(), back, s);
    for (const Rgb& v : back) EXPECT_EQ(v[0] + v[1] + v[2], 0);
}

}  // namespace
}  // namespace rp::pmap
