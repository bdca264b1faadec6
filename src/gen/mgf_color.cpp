// MGF colour conversions (RADIANCE's ccolor.c and cie_rgb, rewritten).
#include "gen/mgf_color.h"

#include <algorithm>
#include <cmath>

namespace rp::gen {

namespace {

using Samples = std::array<int16_t, MgfColor::kSamples>;

// CIE 1931 standard observer at 10 nm, scaled to a peak of 10000, with each curve's sum
// and efficacy: the tables the MGF library works with.
constexpr Samples kX31 = {14,    42,    143,  435,  1344, 2839, 3483, 3362, 2908, 1954, 956,
                          320,   49,    93,   633,  1655, 2904, 4334, 5945, 7621, 9163, 10263,
                          10622, 10026, 8544, 6424, 4479, 2835, 1649, 874,  468,  227,  114,
                          58,    29,    14,   7,    3,    2,    1,    0};
constexpr Samples kY31 = {0,    1,    4,    12,   40,   116,  230,  380,  600,  910,  1390,
                          2080, 3230, 5030, 7100, 8620, 9540, 9950, 9950, 9520, 8700, 7570,
                          6310, 5030, 3810, 2650, 1750, 1070, 610,  320,  170,  82,   41,
                          21,   10,   5,    2,    1,    1,    0,    0};
constexpr Samples kZ31 = {65,   201,  679,  2074, 6456, 13856, 17471, 17721, 16692, 12876, 8130,
                          4652, 2720, 1582, 782,  422,  203,   87,    39,    21,    17,    11,
                          8,    3,    2,    0,    0,    0,     0,     0,     0,     0,     0,
                          0,    0,    0,    0,    0,    0,     0,     0};
constexpr long kX31Sum = 106836, kY31Sum = 106856, kZ31Sum = 106770;
constexpr double kX31Eff = 362.230, kY31Eff = 493.525, kZ31Eff = 54.363;
constexpr double kLumensPerSample = 683.0 / MgfColor::kMaxSample;

// Spectra of the (imaginary) CIE XYZ primaries, for turning xy into a spectrum.
constexpr Samples kXPrim = {-174,  -198,  -195,  -197,  -202,  -213,  -235,  -272, -333, -444, -688,
                            -1232, -2393, -4497, -6876, -6758, -5256, -3100, -815, 1320, 3200, 4782,
                            5998,  6861,  7408,  7754,  7980,  8120,  8199,  8240, 8271, 8292, 8309,
                            8283,  8469,  8336,  8336,  8336,  8336,  8336,  8336};
constexpr Samples kYPrim = {-451,  -431,  -431,  -430,  -427,  -417,  -399,  -366,  -312,
                            -204,  57,    691,   2142,  4990,  8810,  9871,  9122,  7321,
                            5145,  3023,  1123,  -473,  -1704, -2572, -3127, -3474, -3704,
                            -3846, -3927, -3968, -3999, -4021, -4038, -4012, -4201, -4066,
                            -4066, -4066, -4066, -4066, -4066};
constexpr Samples kZPrim = {4051, 4054, 4052, 4053, 4054, 4056, 4059, 4064, 4071, 4074, 4056,
                            3967, 3677, 2933, 1492, 313,  -440, -795, -904, -918, -898, -884,
                            -869, -863, -855, -855, -851, -848, -847, -846, -846, -846, -845,
                            -846, -843, -845, -845, -845, -845, -845, -845};

// A stored sample: RADIANCE adds frand() and truncates (dithered rounding). Saturated to
// int16's range first (NaN: 0): a degenerate spectrum (all zero, or huge values) gives
// values whose conversion is undefined behaviour (found by fuzz_mgf).
int16_t toSample(double v, MgfDither& dither) {
    const double d = v + dither.next();
    if (!(d > -32768.0)) return d != d ? 0 : -32768;
    return d >= 32767.0 ? int16_t(32767) : static_cast<int16_t>(d);
}

}  // namespace

// glibc's random() (TYPE_3: additive feedback r[i] = r[i-3] + r[i-31], seeded through
// the Park-Miller generator), as rand() without srand().
MgfDither::MgfDither() {
    std::vector<uint32_t> r(344);
    int64_t v = 1;
    r[0] = 1;
    for (int i = 1; i < 31; ++i) r[i] = uint32_t(v = (16807 * v) % 2147483647);
    for (int i = 31; i < 34; ++i) r[i] = r[i - 31];
    for (int i = 34; i < 344; ++i) r[i] = r[i - 31] + r[i - 3];  // modulo 2^32
    for (int i = 344 - 31; i < 344; ++i) ring_[i % 31] = r[i];
    n_ = 344;  // the first 344 values are discarded
}

double MgfDither::next() {
    uint32_t& slot = ring_[n_ % 31];  // holds r[n - 31]
    slot += ring_[(n_ - 3) % 31];
    ++n_;
    return (slot >> 1) * (1. / (2147483647 + .5));
}

MgfColor::MgfColor() {
    samples.fill(kMaxSample);
    sampleSum = long(kSamples) * kMaxSample;
}

bool MgfColor::setXy(double cx, double cy) {
    x = float(cx);
    y = float(cy);
    flags = XyDefined | XySet;
    return !(x < 0 || y < 0 || x + y > 1);
}

bool MgfColor::setSpectrum(double wlMin, double wlMax, const std::vector<float>& values,
                           MgfDither& dither) {
    int n = int(values.size());
    const float* spec = values.data();
    if (n <= 1 || wlMin >= kMaxWl || wlMax <= kMinWl || wlMin >= wlMax) return false;
    double wlStep = (wlMax - wlMin) / (n - 1);
    for (; wlMin < kMinWl; wlMin += wlStep, --n, ++spec) {
    }
    for (; wlMax > kMaxWl; wlMax -= wlStep) --n;
    if (n <= 1 || wlMin >= wlMax) return false;
    // Finer data than our 10 nm is box-filtered down to it.
    int count = n;
    double boxPos = 0, boxStep = 1;
    if (wlStep < kWlStep) {
        count = int((wlMax - wlMin) / kWlStep + 1e-7);
        boxPos = (wlMin - kMinWl) / kWlStep;
        boxStep = wlStep / kWlStep;
        wlStep = kWlStep;
    }
    std::array<float, kSamples> va{};
    double peak = 0, lum = 0;
    for (int i = 0, pos = 0; i < count && i < kSamples; ++i) {
        int k = 0;
        for (; boxPos < i + .5 && pos < n; ++k, boxPos += boxStep) va[i] += spec[pos++];
        if (k > 1) va[i] = float(va[i] / double(k));
        peak = std::max(peak, double(std::fabs(va[i])));
        lum += va[i] * kY31[i];
    }
    // RADIANCE's setspectrum refuses a spectrum of (almost) no luminance.
    if (peak <= 1e-7 || lum / double(kY31Sum) <= 1e-6) return false;
    double scale = kMaxSample / peak;
    sampleSum = 0;
    double wl0 = wlMin;
    int pos = 0;
    for (int i = 0, wl = kMinWl; i < kSamples; ++i, wl += kWlStep) {
        if (wl < wlMin || wl > wlMax) {
            samples[i] = 0;
            continue;
        }
        for (; wl0 + wlStep < wl + 1e-7; wl0 += wlStep) ++pos;
        if (wl + 1e-7 >= wl0 && wl - 1e-7 <= wl0)
            samples[i] = toSample(scale * va[pos], dither);
        else  // between two given wavelengths: linear interpolation
            samples[i] = toSample(
                scale / wlStep * (va[pos] * (wl0 + wlStep - wl) + va[pos + 1] * (wl - wl0)),
                dither);
        sampleSum += samples[i];
    }
    flags = SpecDefined | SpecSet;
    return true;
}

bool MgfColor::setBlackBody(double kelvin, MgfDither& dither) {
    if (kelvin < 1000) return false;
    // Planck's law, scaled so that its peak (Wien: 2.9e-3 m K / T, clamped to the
    // visible range) is kMaxSample.
    auto planck = [kelvin](double wlM) {
        return 3.741832e-16 /
               (wlM * wlM * wlM * wlM * wlM * (std::exp(1.4388e-2 / (kelvin * wlM)) - 1));
    };
    double peakWl = std::clamp(1.4388e-2 * 0.2 / kelvin, kMinWl * 1e-9, kMaxWl * 1e-9);
    double sf = kMaxSample / planck(peakWl);
    sampleSum = 0;
    for (int i = 0; i < kSamples; ++i) {
        samples[i] = toSample(sf * planck((kMinWl + i * kWlStep) * 1e-9), dither);
        sampleSum += samples[i];
    }
    flags = SpecDefined | SpecSet;
    return true;
}

void MgfColor::convert(unsigned want, MgfDither* dither) {
    want &= ~unsigned(flags);
    if (!want) return;
    if (!(flags & (XySet | SpecSet))) {
        *this = MgfColor();
        return;
    }
    if (want & XySet) {
        double cx = 0, cy = 0, cz = 0;
        for (int i = 0; i < kSamples; ++i) {
            cx += kX31[i] * samples[i];
            cy += kY31[i] * samples[i];
            cz += kZ31[i] * samples[i];
        }
        cx /= double(kX31Sum);
        cy /= double(kY31Sum);
        cz = cz / double(kZ31Sum) + cx + cy;
        x = cz > 1e-6 ? float(cx / cz) : 1.f / 3;
        y = cz > 1e-6 ? float(cy / cz) : 1.f / 3;
        flags |= XySet;
    }
    if (want & SpecSet) {
        double cx = x, cy = y, cz = 1 - cx - cy;
        sampleSum = 0;
        for (int i = 0; i < kSamples; ++i) {
            int16_t v = toSample(cx * kXPrim[i] + cy * kYPrim[i] + cz * kZPrim[i], *dither);
            samples[i] = v < 0 ? 0 : v;  // out of gamut
            sampleSum += samples[i];
        }
        flags |= SpecSet;
    }
    if (want & EffSet) {
        if (flags & SpecSet) {
            double sum = 0;
            for (int i = 0; i < kSamples; ++i) sum += kY31[i] * samples[i];
            efficacy = float(kLumensPerSample * sum / (sampleSum + 0.0001));
        } else {
            efficacy = float(x * kX31Eff + y * kY31Eff + (1. - x - y) * kZ31Eff);
        }
        flags |= EffSet;
    }
}

bool MgfColor::isGrey() {
    if (!(flags & (XySet | SpecSet))) return true;
    convert(XySet);
    return x >= .323 && x <= .343 && y >= .323 && y <= .343;
}

MgfColor mixColors(double w1, MgfColor c1, double w2, MgfColor c2, MgfDither& dither) {
    if (w1 == 0) return c2;
    if (w2 == 0) return c1;
    MgfColor out;
    if ((c1.flags | c2.flags) & MgfColor::SpecDefined) {
        c1.convert(MgfColor::SpecSet | MgfColor::EffSet, &dither);
        c2.convert(MgfColor::SpecSet | MgfColor::EffSet, &dither);
        if (c1.sampleSum * c2.sampleSum == 0) return out;
        // Weights are luminous: divide by each colour's lumens per unit sample sum.
        w1 /= c1.efficacy * double(c1.sampleSum);
        w2 /= c2.efficacy * double(c2.sampleSum);
        std::array<float, MgfColor::kSamples> mix{};
        double peak = 0;
        for (int i = 0; i < MgfColor::kSamples; ++i) {
            mix[i] = float(w1 * c1.samples[i] + w2 * c2.samples[i]);
            peak = std::max(peak, double(std::fabs(mix[i])));
        }
        double scale = MgfColor::kMaxSample / peak;
        out.sampleSum = 0;
        for (int i = 0; i < MgfColor::kSamples; ++i) {
            out.samples[i] = toSample(scale * mix[i], dither);
            out.sampleSum += out.samples[i];
        }
        out.flags = MgfColor::SpecDefined | MgfColor::SpecSet;
        return out;
    }
    c1.convert(MgfColor::XySet);
    c2.convert(MgfColor::XySet);
    // Luminous weights become XYZ-sum weights through 1/y.
    w1 *= c2.y;
    w2 *= c1.y;
    if (w1 + w2 == 0) return out;
    double s = 1 / (w1 + w2);
    out.x = float((w1 * c1.x + w2 * c2.x) * s);
    out.y = float((w1 * c1.y + w2 * c2.y) * s);
    out.flags = MgfColor::XyDefined | MgfColor::XySet;
    return out;
}

namespace {

// RADIANCE's xyz2rgbmat for its default primaries (r 0.640 0.330, g 0.290 0.600,
// b 0.150 0.060, white 1/3 1/3), held in floats as RADIANCE's COLORMAT.
struct XyzToRgb {
    float m[3][3];
    XyzToRgb() {
        const double xr = .640, yr = .330, xg = .290, yg = .600, xb = .150, yb = .060;
        const double xw = 1. / 3, yw = 1. / 3;
        double cr = (1. / yw) * (xw * (yg - yb) - yw * (xg - xb) + xg * yb - xb * yg);
        double cg = (1. / yw) * (xw * (yb - yr) - yw * (xb - xr) - xr * yb + xb * yr);
        double cb = (1. / yw) * (xw * (yr - yg) - yw * (xr - xg) + xr * yg - xg * yr);
        double rows[3][3] = {{(yg - yb - xb * yg + yb * xg) / cr,
                              (xb - xg - xb * yg + xg * yb) / cr, (xg * yb - xb * yg) / cr},
                             {(yb - yr - yb * xr + yr * xb) / cg,
                              (xr - xb - xr * yb + xb * yr) / cg, (xb * yr - xr * yb) / cg},
                             {(yr - yg - yr * xg + yg * xr) / cb,
                              (xg - xr - xg * yr + xr * yg) / cb, (xr * yg - xg * yr) / cb}};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = float(rows[i][j]);
    }
};

}  // namespace

std::array<float, 3> mgfColorToRgb(MgfColor c, double intensity) {
    static const XyzToRgb kMat;
    c.convert(MgfColor::XySet);
    // In floats, as RADIANCE's COLOR, so that printed digits agree.
    float xyz[3];
    xyz[1] = float(intensity);
    xyz[0] = c.x / c.y * xyz[1];
    xyz[2] = float(xyz[1] * (1. / c.y - 1.) - xyz[0]);
    std::array<float, 3> rgb;
    for (int i = 0; i < 3; ++i)
        rgb[i] = kMat.m[i][0] * xyz[0] + kMat.m[i][1] * xyz[1] + kMat.m[i][2] * xyz[2];
    // RADIANCE clipgamut with the lower limit only: black below zero luminance, else
    // negative primaries pulled toward the grey of the same luminance.
    double brt = xyz[1];
    if (brt < 0) return {0, 0, 0};
    double keep = 1;
    for (float v : rgb)
        if (v < 0) keep = std::min(keep, (0 - brt) / (v - brt));
    if (keep < 1)
        for (float& v : rgb) v = float(keep * v + (1 - keep) * brt);
    return rgb;
}

}  // namespace rp::gen
