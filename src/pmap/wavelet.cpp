// Daubechies-4 coefficient compression (wavelet.h).
#include "pmap/wavelet.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "util/error.h"

namespace rp::pmap {

namespace {

// D4 scaling filter h and wavelet filter g_k = (-1)^k h_{3-k}.
const double kS3 = std::sqrt(3.0);
const double kNorm = 4 * std::sqrt(2.0);
const double kH[4] = {(1 + kS3) / kNorm, (3 + kS3) / kNorm, (3 - kS3) / kNorm, (1 - kS3) / kNorm};
const double kG[4] = {kH[3], -kH[2], kH[1], -kH[0]};

// A multiple of 8 (three levels at least): padding a power of two would add up to as
// many mirrored bins as there are, which cost coefficients.
int paddedLength(int bins) { return std::max(8, (bins + 7) / 8 * 8); }

// The lengths the transform levels work on: halving while even and at least 4.
bool nextLevel(size_t n) { return n >= 4 && n % 2 == 0; }

// A coefficient triple in 4 bytes: a shared exponent and three signed 8-bit mantissas
// (RADIANCE's RGBE with a sign), 1/127 of the largest component at worst, well below
// the photon noise of a bin.
void packTriple(const double v[3], uint8_t* out) {
    const double m = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    int e = 0;
    if (m > 0) std::frexp(m, &e);
    e = std::clamp(e, -127, 127);
    out[0] = uint8_t(int8_t(e));
    for (int c = 0; c < 3; ++c)
        out[1 + c] = uint8_t(int8_t(std::clamp(std::lround(std::ldexp(v[c], 7 - e)), -127L, 127L)));
}

void unpackTriple(const uint8_t* in, double v[3]) {
    const int e = int8_t(in[0]);
    for (int c = 0; c < 3; ++c) v[c] = std::ldexp(double(int8_t(in[1 + c])), e - 7);
}

}  // namespace

void d4Forward(std::span<double> x, std::vector<double>& t) {
    t.resize(x.size());
    for (size_t n = x.size(); nextLevel(n); n /= 2) {
        const size_t half = n / 2;
        for (size_t i = 0; i < half; ++i) {
            double a = 0, d = 0;
            for (size_t k = 0; k < 4; ++k) {
                const double v = x[(2 * i + k) % n];
                a += kH[k] * v;
                d += kG[k] * v;
            }
            t[i] = a;
            t[half + i] = d;
        }
        std::copy(t.begin(), t.begin() + long(n), x.begin());
    }
}

void d4Inverse(std::span<double> x, std::vector<double>& t) {
    t.resize(x.size());
    size_t n0 = x.size();
    while (nextLevel(n0)) n0 /= 2;  // the coarsest level's approximation length
    for (size_t n = 2 * n0; n <= x.size(); n *= 2) {
        const size_t half = n / 2;
        std::fill(t.begin(), t.begin() + long(n), 0.0);
        for (size_t i = 0; i < half; ++i)
            for (size_t k = 0; k < 4; ++k) t[(2 * i + k) % n] += kH[k] * x[i] + kG[k] * x[half + i];
        std::copy(t.begin(), t.begin() + long(n), x.begin());
    }
}

CoeffCodec::CoeffCodec(int bins, double comp) : bins_(bins), length_(paddedLength(bins)) {
    RP_CHECK(bins > 0 && bins <= 65536 && comp >= 0 && comp <= 1);
    approx_ = length_;
    while (nextLevel(size_t(approx_))) approx_ /= 2;
    if (comp > 0) kept_ = approx_ + int(std::lround((1 - comp) * (length_ - approx_)));
}

void CoeffCodec::putIndex(uint8_t* at, uint32_t i) const {
    at[0] = uint8_t(i);
    if (indexBytes() == 2) at[1] = uint8_t(i >> 8);
}

uint32_t CoeffCodec::getIndex(const uint8_t* at) const {
    return indexBytes() == 2 ? uint32_t(at[0]) | uint32_t(at[1]) << 8 : at[0];
}

void CoeffCodec::encode(std::span<const Rgb> values, uint8_t* out, Scratch& s) const {
    if (raw()) {
        for (int b = 0; b < bins_; ++b)
            for (int c = 0; c < 3; ++c) {
                const float f = float(values[size_t(b)][size_t(c)]);
                std::memcpy(out + (size_t(b) * 3 + size_t(c)) * 4, &f, 4);
            }
        return;
    }
    const size_t n = size_t(length_);
    for (int c = 0; c < 3; ++c) {
        std::vector<double>& x = s.channels[size_t(c)];
        x.resize(n);
        // Mirror padding: no jump where the bins end.
        for (size_t i = 0; i < n; ++i) {
            size_t j = i;
            while (j >= size_t(bins_))
                j = j >= 2 * size_t(bins_) ? j - 2 * size_t(bins_) : 2 * size_t(bins_) - 1 - j;
            x[i] = values[j][size_t(c)];
        }
        d4Forward(x, s.tmp);
    }
    // The coarsest approximation coefficients are always kept: the wavelets sum to zero,
    // so they alone carry each record's total, which dropping one would bias.
    s.magnitude.resize(n);
    for (size_t i = 0; i < n; ++i)
        s.magnitude[i] = i < size_t(approx_)
                             ? HUGE_VAL
                             : std::fabs(s.channels[0][i]) + std::fabs(s.channels[1][i]) +
                                   std::fabs(s.channels[2][i]);
    s.order.resize(n);
    std::iota(s.order.begin(), s.order.end(), 0u);
    // The kept largest, ties to the lower index (the same record for the same bins), in
    // that order: a strict total order, so selecting and then sorting the kept gives what
    // a partial sort gives.
    auto before = [&](uint32_t a, uint32_t b) {
        const double ma = s.magnitude[a], mb = s.magnitude[b];
        return ma > mb || (ma == mb && a < b);
    };
    const auto keptEnd = s.order.begin() + kept_;
    std::nth_element(s.order.begin(), keptEnd, s.order.end(), before);
    std::sort(s.order.begin(), keptEnd, before);
    for (int k = 0; k < kept_; ++k) {
        const uint32_t i = s.order[size_t(k)];
        uint8_t* at = out + size_t(k) * coefficientBytes();
        putIndex(at, i);
        const double v[3] = {s.channels[0][i], s.channels[1][i], s.channels[2][i]};
        packTriple(v, at + indexBytes());
    }
}

void CoeffCodec::decode(const uint8_t* in, std::span<Rgb> values, Scratch& s) const {
    if (raw()) {
        for (int b = 0; b < bins_; ++b)
            for (int c = 0; c < 3; ++c) {
                float f;
                std::memcpy(&f, in + (size_t(b) * 3 + size_t(c)) * 4, 4);
                values[size_t(b)][size_t(c)] = f;
            }
        return;
    }
    const size_t n = size_t(length_);
    for (auto& x : s.channels) x.assign(n, 0.0);
    for (int k = 0; k < kept_; ++k) {
        const uint8_t* at = in + size_t(k) * coefficientBytes();
        const uint32_t idx = getIndex(at);
        if (idx >= n) continue;  // a damaged record reads as zero there
        double v[3];
        unpackTriple(at + indexBytes(), v);
        for (int c = 0; c < 3; ++c) s.channels[size_t(c)][idx] = v[c];
    }
    for (int c = 0; c < 3; ++c) {
        d4Inverse(s.channels[size_t(c)], s.tmp);
        for (int b = 0; b < bins_; ++b)
            values[size_t(b)][size_t(c)] = s.channels[size_t(c)][size_t(b)];
    }
}

}  // namespace rp::pmap
