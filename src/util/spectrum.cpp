// Colour science for RADIANCE 6 spectra (see spectrum.h).
#include "util/spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.h"
#include "util/observer_table.h"

namespace rp::spectral {

namespace {

// CIE 1931 2-degree standard observer, 360..830 nm every 5 nm (CIE 015:2018, table T.4;
// the copy distributed with colord, CIE1931-2deg-XYZ.cmf).
constexpr double kCieFirst = 360, kCieStep = 5;
constexpr std::array<double, 95> kX = {
    0.0001299,    0.0002321,    0.0004149,    0.0007416,    0.001368,     0.002236,
    0.004243,     0.00765,      0.01431,      0.02319,      0.04351,      0.07763,
    0.13438,      0.21477,      0.2839,       0.3285,       0.34828,      0.34806,
    0.3362,       0.3187,       0.2908,       0.2511,       0.19536,      0.1421,
    0.09564,      0.05795001,   0.03201,      0.0147,       0.0049,       0.0024,
    0.0093,       0.0291,       0.06327,      0.1096,       0.1655,       0.2257499,
    0.2904,       0.3597,       0.4334499,    0.5120501,    0.5945,       0.6784,
    0.7621,       0.8425,       0.9163,       0.9786,       1.0263,       1.0567,
    1.0622,       1.0456,       1.0026,       0.9384,       0.8544499,    0.7514,
    0.6424,       0.5419,       0.4479,       0.3608,       0.2835,       0.2187,
    0.1649,       0.1212,       0.0874,       0.0636,       0.04677,      0.0329,
    0.0227,       0.01584,      0.01135916,   0.008110916,  0.005790346,  0.004109457,
    0.002899327,  0.00204919,   0.001439971,  0.0009999493, 0.0006900786, 0.0004760213,
    0.0003323011, 0.0002348261, 0.0001661505, 0.000117413,  8.307527e-05, 5.870652e-05,
    4.150994e-05, 2.935326e-05, 2.067383e-05, 1.455977e-05, 1.025398e-05, 7.221456e-06,
    5.085868e-06, 3.581652e-06, 2.522525e-06, 1.776509e-06, 1.251141e-06};

constexpr std::array<double, 95> kY = {
    3.917e-06,  6.965e-06,  1.239e-05,  2.202e-05,  3.9e-05,    6.4e-05,    0.00012,    0.000217,
    0.000396,   0.00064,    0.00121,    0.00218,    0.004,      0.0073,     0.0116,     0.01684,
    0.023,      0.0298,     0.038,      0.048,      0.06,       0.0739,     0.09098,    0.1126,
    0.13902,    0.1693,     0.20802,    0.2586,     0.323,      0.4073,     0.503,      0.6082,
    0.71,       0.7932,     0.862,      0.9148501,  0.954,      0.9803,     0.9949501,  1.0,
    0.995,      0.9786,     0.952,      0.9154,     0.87,       0.8163,     0.757,      0.6949,
    0.631,      0.5668,     0.503,      0.4412,     0.381,      0.321,      0.265,      0.217,
    0.175,      0.1382,     0.107,      0.0816,     0.061,      0.04458,    0.032,      0.0232,
    0.017,      0.01192,    0.00821,    0.005723,   0.004102,   0.002929,   0.002091,   0.001484,
    0.001047,   0.00074,    0.00052,    0.0003611,  0.0002492,  0.0001719,  0.00012,    8.48e-05,
    6e-05,      4.24e-05,   3e-05,      2.12e-05,   1.499e-05,  1.06e-05,   7.4657e-06, 5.2578e-06,
    3.7029e-06, 2.6078e-06, 1.8366e-06, 1.2934e-06, 9.1093e-07, 6.4153e-07, 4.5181e-07};

constexpr std::array<double, 95> kZ = {
    0.0006061,  0.001086,    0.001946,   0.003486,    0.006450001,
    0.01054999, 0.02005001,  0.03621,    0.06785001,  0.1102,
    0.2074,     0.3713,      0.6456,     1.0390501,   1.3856,
    1.62296,    1.74706,     1.7826,     1.77211,     1.7441,
    1.6692,     1.5281,      1.28764,    1.0419,      0.8129501,
    0.6162,     0.46518,     0.3533,     0.272,       0.2123,
    0.1582,     0.1117,      0.07824999, 0.05725001,  0.04216,
    0.02984,    0.0203,      0.0134,     0.008749999, 0.005749999,
    0.0039,     0.002749999, 0.0021,     0.0018,      0.001650001,
    0.0014,     0.0011,      0.001,      0.0008,      0.0006,
    0.00034,    0.00024,     0.00019,    0.0001,      4.999999e-05,
    3e-05,      2e-05,       1e-05,      0,           0,
    0,          0,           0,          0,           0,
    0,          0,           0,          0,           0,
    0,          0,           0,          0,           0,
    0,          0,           0,          0,           0,
    0,          0,           0,          0,           0,
    0,          0,           0,          0,           0,
    0,          0,           0,          0,           0};

// The observer's integral, normalised so that an equal-energy spectrum has X = Y = Z = 1,
// and the dot product over bands (util/observer_table.h).
using detail::Cumulative;
using detail::observe;

const Cumulative& cumulX() {
    static const Cumulative c(kX, kCieFirst, kCieStep);
    return c;
}
const Cumulative& cumulY() {
    static const Cumulative c(kY, kCieFirst, kCieStep);
    return c;
}
const Cumulative& cumulZ() {
    static const Cumulative c(kZ, kCieFirst, kCieStep);
    return c;
}

using Mat3 = std::array<double, 9>;

Mat3 inverse(const Mat3& m) {
    const double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7],
                 i = m[8];
    const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    RP_CHECK(det != 0);
    const double k = 1 / det;
    return {(e * i - f * h) * k, (c * h - b * i) * k, (b * f - c * e) * k,
            (f * g - d * i) * k, (a * i - c * g) * k, (c * d - a * f) * k,
            (d * h - e * g) * k, (b * g - a * h) * k, (a * e - b * d) * k};
}

Color apply(const Mat3& m, const Color& c) {
    return {m[0] * c.r + m[1] * c.g + m[2] * c.b, m[3] * c.r + m[4] * c.g + m[5] * c.b,
            m[6] * c.r + m[7] * c.g + m[8] * c.b};
}

const Mat3& standardRgbFromXyz() {
    static const Mat3 m = rgbFromXyz(kStandardPrimaries);
    return m;
}

}  // namespace

std::array<double, 9> rgbFromXyz(const std::array<double, 8>& p) {
    // Columns: XYZ of each primary at Y=1, scaled so that they sum to the white point.
    auto xyz = [](double x, double y) { return std::array<double, 3>{x / y, 1, (1 - x - y) / y}; };
    auto r = xyz(p[0], p[1]), g = xyz(p[2], p[3]), b = xyz(p[4], p[5]), w = xyz(p[6], p[7]);
    Mat3 m = {r[0], g[0], b[0], r[1], g[1], b[1], r[2], g[2], b[2]};
    const Mat3 mi = inverse(m);
    double s[3];
    for (int i = 0; i < 3; ++i)
        s[i] = mi[3 * i] * w[0] + mi[3 * i + 1] * w[1] + mi[3 * i + 2] * w[2];
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) m[3 * row + col] *= s[col];
    return inverse(m);
}

Color clipNegative(const Color& rgb, double y) {
    if (y < 0) return {};
    double keep = 1;
    for (int i = 0; i < 3; ++i)
        if (rgb[i] < 0) keep = std::min(keep, -y / (rgb[i] - y));
    if (keep == 1) return rgb;
    return rgb * keep + Color::grey(y) * (1 - keep);
}

std::optional<SamplingChoice> makeSampling(int n, double wlA, double wlB) {
    // The primaries' peak wavelengths RADIANCE 6 tunes its RGB indices to.
    constexpr double kPeak[3] = {607, 553, 469};
    if (n < 3) return std::nullopt;
    const double longest = std::max(wlA, wlB), shortest = std::min(wlA, wlB);
    if (longest - shortest < 50) return std::nullopt;
    SamplingChoice c;
    Sampling& s = c.sampling;
    s.n = std::min(n, kMaxSamples);
    s.wl = {longest, 0, 0, shortest};
    if (shortest >= kPeak[2] || longest <= kPeak[0]) {
        s.wl[1] = longest + (shortest - longest) / 3;
        s.wl[2] = longest + 2 * (shortest - longest) / 3;
        s.rgb = {0, s.n / 3, s.n * 2 / 3};
        c.tuned = false;
        return c;
    }
    s.wl[1] = 588;  // RADIANCE's standard green channel
    s.wl[2] = 480;
    if (s.n == 3) return c;
    for (int j = 0; j < 3; ++j) {
        double best = -1;
        for (int i = s.n - 1; i >= 0; --i) {  // ties go to the longer wavelength
            const double d = std::fabs(s.centre(i) - kPeak[j]);
            if (best < 0 || d < best) {
                best = d;
                s.rgb[j] = i;
            }
        }
    }
    return c;
}

void fromRgb(const Color& rgb, const Sampling& s, std::span<double> out) {
    RP_CHECK(static_cast<int>(out.size()) == s.n);
    if (s.isRgb()) {
        for (int i = 0; i < 3; ++i) out[i] = rgb[i];
        return;
    }
    for (int i = 0; i < s.n; ++i) {
        const double c = s.centre(i);
        out[i] = c >= s.wl[1] ? rgb.r : (c >= s.wl[2] ? rgb.g : rgb.b);
    }
}

std::vector<Pass> passesOf(const Sampling& s) {
    std::vector<Pass> passes;
    std::vector<int> primaryOf(static_cast<size_t>(s.n));
    for (int c = 0; c < 3; ++c) {
        // Which primary each band takes: the one fromRgb puts there.
        Color unit;
        unit[c] = 1;
        std::vector<double> v(static_cast<size_t>(s.n));
        fromRgb(unit, s, v);
        for (int i = 0; i < s.n; ++i)
            if (v[size_t(i)] == 1) primaryOf[size_t(i)] = c;
    }
    for (int first = 0; first < s.n; first += 3) {
        Pass p{s, first, {}};
        for (int j = 0; j < 3; ++j) p.primary[size_t(j)] = primaryOf[size_t(p.band(j))];
        passes.push_back(p);
    }
    return passes;
}

std::string passFile(const std::string& name, const Pass& pass) {
    if (pass.first == 0) return name;
    return name + "." + std::to_string(pass.first) + "-" + std::to_string(pass.band(2));
}

std::string passLabel(const Pass& pass) {
    if (pass.sampling.isRgb()) return "";
    char buf[96];
    std::snprintf(buf, sizeof buf, "-cs %d -cw %g %g bands %d-%d", pass.sampling.n,
                  pass.sampling.wl[3], pass.sampling.wl[0], pass.first, pass.band(2));
    return buf;
}

void resample(std::span<double> dst, double dwl0, double dwl1, std::span<const double> src,
              double swl0, double swl1) {
    const int dn = static_cast<int>(dst.size()), sn = static_cast<int>(src.size());
    std::fill(dst.begin(), dst.end(), 0.0);
    if (dn == 0 || sn == 0 || !(dwl0 > dwl1) || swl0 == swl1) return;
    // The same bands: copied (RADIANCE's test, half a nanometre squared).
    if (dn == sn && (dwl0 - swl0) * (dwl0 - swl0) + (dwl1 - swl1) * (dwl1 - swl1) <= .5) {
        std::copy(src.begin(), src.end(), dst.begin());
        return;
    }
    const double dstep = (dwl0 - dwl1) / dn;
    const double sstep = (swl1 - swl0) / sn;  // signed: source bands run from swl0
    for (int d = 0; d < dn; ++d) {
        const double hi = dwl0 - d * dstep, lo = hi - dstep;
        double sum = 0;
        for (int k = 0; k < sn; ++k) {
            const double a = swl0 + k * sstep, b = a + sstep;
            const double overlap = std::min(hi, std::max(a, b)) - std::max(lo, std::min(a, b));
            if (overlap > 0) sum += src[k] * overlap;
        }
        dst[d] = sum / dstep;
    }
}

Color toXyz(std::span<const double> samples, const Sampling& s) {
    RP_CHECK(static_cast<int>(samples.size()) == s.n);
    if (s.isRgb()) {
        static const Mat3 m = inverse(standardRgbFromXyz());
        return apply(m, {samples[0], samples[1], samples[2]});
    }
    return {observe(samples, s.wl, cumulX()), observe(samples, s.wl, cumulY()),
            observe(samples, s.wl, cumulZ())};
}

Color toRgb(std::span<const double> samples, const Sampling& s) {
    RP_CHECK(static_cast<int>(samples.size()) == s.n);
    if (s.isRgb()) return {samples[0], samples[1], samples[2]};
    const Color xyz = toXyz(samples, s);
    return clipNegative(apply(standardRgbFromXyz(), xyz), xyz.g);
}

Color bandAverages(std::span<const double> samples, const Sampling& s) {
    Color sum;
    int count[3] = {0, 0, 0}, j = 0;
    for (int i = 0; i < s.n; ++i) {
        if (j < 2 && s.centre(i) < s.wl[j + 1]) ++j;
        sum[j] += samples[i];
        ++count[j];
    }
    for (int c = 0; c < 3; ++c)
        if (count[c] > 1) sum[c] /= count[c];
    return sum;
}

double photopic(std::span<const double> samples, const Sampling& s) {
    if (s.isRgb()) return Color(samples[0], samples[1], samples[2]).brightness();
    return observe(samples, s.wl, cumulY());
}

void toWorking(std::span<const double> src, double swl0, double swl1, const Sampling& s,
               std::span<double> out) {
    RP_CHECK(static_cast<int>(out.size()) == s.n);
    if (!s.isRgb()) {
        resample(out, s.wl[0], s.wl[3], src, swl0, swl1);
        return;
    }
    Color rgb;
    const int sn = static_cast<int>(src.size());
    if (sn == 0 || swl0 == swl1) {
        std::fill(out.begin(), out.end(), 0.0);
        return;
    }
    if (sn <= kMaxSamples && swl0 > swl1) {
        // Bands already run from long to short: observed as they are.
        const Sampling given{sn, {swl0, s.wl[1], s.wl[2], swl1}, {}};
        rgb = sn == 3 ? Color(src[0], src[1], src[2]) : toRgb(src, given);
    } else {
        // Re-binned over the working range first, about as finely as given (at least 4
        // bands, so that it stays a spectrum: RADIANCE would read 3 as RGB).
        int n = static_cast<int>(sn * (s.wl[0] - s.wl[3]) / std::fabs(swl0 - swl1) + .99);
        n = std::clamp(n, 4, kMaxSamples);
        std::vector<double> bands(static_cast<size_t>(n));
        resample(bands, s.wl[0], s.wl[3], src, swl0, swl1);
        rgb = toRgb(bands, Sampling{n, s.wl, {}});
    }
    out[0] = rgb.r;
    out[1] = rgb.g;
    out[2] = rgb.b;
}

}  // namespace rp::spectral
