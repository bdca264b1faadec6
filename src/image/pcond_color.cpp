// pcond's colour output (RADIANCE's spec_rgb.c matrices and pcond2.c): input RGB or XYZ
// to the output device's primaries with a von Kries white balance in the "sharp" cone
// space, desaturation into the displayable cube, and macbethcal(1) calibrations (-f).
// Matrices are single precision as RADIANCE's COLORMAT, so results round alike.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <string>

#include "image/pcond_internal.h"
#include "image/white_balance.h"
#include "util/error.h"

namespace rp::pcond_detail {
namespace {

using Prims = std::array<double, 8>;  // rx ry gx gy bx by wx wy
enum { kRx, kRy, kGx, kGy, kBx, kBy, kWx, kWy };

// RADIANCE's standard primaries (nominal CRT) with an equal-energy white.
constexpr Prims kStandard{0.640, 0.330, 0.290, 0.600, 0.150, 0.060, 1. / 3., 1. / 3.};
constexpr float kNeutral = static_cast<float>(1. / 3.);

// The "sharp" cone-like primaries of the von Kries transform and their inverse.
constexpr ColorMatrix kSharp{
    {{1.2694f, -0.0988f, -0.1706f}, {-0.8364f, 1.8006f, 0.0357f}, {0.0297f, -0.0315f, 1.0018f}}};
constexpr ColorMatrix kSharpInverse{
    {{0.8156f, 0.0472f, 0.1372f}, {0.3791f, 0.5769f, 0.0440f}, {-0.0123f, 0.0167f, 0.9955f}}};

constexpr double kColorEps = 1e-4;
bool colorEqual(double a, double b) { return a <= b + kColorEps && b <= a + kColorEps; }

Prims widen(const std::optional<Primaries>& p) {
    if (!p) return kStandard;
    Prims d;
    for (int i = 0; i < 8; ++i) d[i] = (*p)[i];
    return d;
}

// The white chromaticity as RADIANCE holds it (float).
std::array<float, 2> whiteOf(const std::optional<Primaries>& p) {
    if (!p) return {kNeutral, kNeutral};
    return {(*p)[kWx], (*p)[kWy]};
}

bool whiteIsNeutral(const std::array<float, 2>& w) {
    return colorEqual(w[0], kNeutral) && colorEqual(w[1], kNeutral);
}

ColorMatrix identity() { return {{{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}}}; }

// a applied after b (RADIANCE's multcolormat(m, b, a)), in single precision.
ColorMatrix compose(const ColorMatrix& a, const ColorMatrix& b) {
    ColorMatrix m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return m;
}

Pixel colorTransform(const ColorMatrix& m, const Pixel& c) {
    Pixel out;
    for (int i = 0; i < 3; ++i) out[i] = m[i][0] * c[0] + m[i][1] * c[1] + m[i][2] * c[2];
    return out;
}

// The chromaticity-weighted determinants of RADIANCE's primary formulas (C_rD etc.).
std::array<double, 3> whiteTerms(const Prims& p) {
    const double iy = 1. / p[kWy];
    return {iy * (p[kWx] * (p[kGy] - p[kBy]) - p[kWy] * (p[kGx] - p[kBx]) + p[kGx] * p[kBy] -
                  p[kBx] * p[kGy]),
            iy * (p[kWx] * (p[kBy] - p[kRy]) - p[kWy] * (p[kBx] - p[kRx]) - p[kRx] * p[kBy] +
                  p[kBx] * p[kRy]),
            iy * (p[kWx] * (p[kRy] - p[kGy]) - p[kWy] * (p[kRx] - p[kGx]) + p[kRx] * p[kGy] -
                  p[kGx] * p[kRy])};
}

ColorMatrix rgbToXyz(const Prims& p) {
    const std::array<double, 3> c = whiteTerms(p);
    const double d =
        p[kRx] * (p[kGy] - p[kBy]) + p[kGx] * (p[kBy] - p[kRy]) + p[kBx] * (p[kRy] - p[kGy]);
    if (colorEqual(p[kWx], 0.) || colorEqual(p[kWy], 0.) || colorEqual(d, 0.))
        throw InputError("bad color primaries");
    ColorMatrix m;
    for (int j = 0; j < 3; ++j) {
        const double x = p[2 * j], y = p[2 * j + 1];
        m[0][j] = static_cast<float>(x * c[j] / d);
        m[1][j] = static_cast<float>(y * c[j] / d);
        m[2][j] = static_cast<float>((1. - x - y) * c[j] / d);
    }
    return m;
}

ColorMatrix xyzToRgb(const Prims& p) {
    const std::array<double, 3> c = whiteTerms(p);
    if (colorEqual(p[kWx], 0.) || colorEqual(p[kWy], 0.) || colorEqual(c[0], 0.) ||
        colorEqual(c[1], 0.) || colorEqual(c[2], 0.))
        throw InputError("bad color primaries");
    ColorMatrix m;
    // Row i from the other two primaries j, k (cyclic), as the inverse's cofactors.
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const double xj = p[2 * j], yj = p[2 * j + 1], xk = p[2 * k], yk = p[2 * k + 1];
        m[i][0] = static_cast<float>((yj - yk - xk * yj + yk * xj) / c[i]);
        m[i][1] = static_cast<float>((xk - xj - xk * yj + xj * yk) / c[i]);
        m[i][2] = static_cast<float>((xj * yk - xk * yj) / c[i]);
    }
    return m;
}

// von Kries adaptation from white w1 to white w2 (compxyzWBmat).
ColorMatrix whiteBalance(const std::array<float, 2>& w1, const std::array<float, 2>& w2) {
    if (colorEqual(w1[0], w2[0]) && colorEqual(w1[1], w2[1])) return identity();
    auto cone = [](const std::array<float, 2>& w) {
        if (colorEqual(w[0], 0.) || colorEqual(w[1], 0.)) throw InputError("bad white point");
        const Pixel xyz{static_cast<float>(w[0] / w[1]), 1.f,
                        static_cast<float>((1. - w[0] - w[1]) / w[1])};
        return colorTransform(kSharp, xyz);
    };
    const Pixel c1 = cone(w1), c2 = cone(w2);
    if (colorEqual(c1[0], 0.) || colorEqual(c1[1], 0.) || colorEqual(c1[2], 0.))
        throw InputError("bad white point");
    ColorMatrix scale{};
    for (int i = 0; i < 3; ++i) scale[i][i] = c2[i] / c1[i];
    return compose(kSharpInverse, compose(scale, kSharp));
}

// RADIANCE's bright(): luminance weights of the standard primaries.
double standardBrightness(const Pixel& c) {
    static const std::array<double, 3> w = [] {
        const std::array<double, 3> t = whiteTerms(kStandard);
        const Prims& p = kStandard;
        const double d =
            p[kRx] * (p[kGy] - p[kBy]) + p[kGx] * (p[kBy] - p[kRy]) + p[kBx] * (p[kRy] - p[kGy]);
        return std::array<double, 3>{p[kRy] * t[0] / d, p[kGy] * t[1] / d, p[kBy] * t[2] / d};
    }();
    return w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
}

// Brightness of the colour clipped to the unit cube: the grey the gamut clip aims at.
double greyPoint(const Pixel& c) {
    Pixel g = c;
    for (float& v : g) v = v > 1 ? 1.f : (v < 0 ? 0.f : v);
    return standardBrightness(g);
}

// Desaturates `col` toward the grey of brightness `brt` until it lies in [lower, upper]
// (RADIANCE's clipgamut with both limits).
void clipGamut(Pixel& col, double brt, const Pixel& lower, const Pixel& upper) {
    const double brtmin = 1. / 3. * (lower[0] + lower[1] + lower[2]);
    if (brt < brtmin) {
        col = lower;
        return;
    }
    const double brtmax = 1. / 3. * (upper[0] + upper[1] + upper[2]);
    if (brt > brtmax) {
        col = upper;
        return;
    }
    const double v = (brt - brtmin) / (brtmax - brtmin);
    Pixel grey;
    for (int i = 0; i < 3; ++i) grey[i] = static_cast<float>(v * upper[i] + (1. - v) * lower[i]);
    double vv = 1.;
    bool clipped = false;
    for (int i = 0; i < 3; ++i) {
        const float limit = col[i] < lower[i] ? lower[i] : (col[i] > upper[i] ? upper[i] : col[i]);
        if (limit == col[i]) continue;
        const double t = (limit - grey[i]) / (col[i] - grey[i]);
        if (t < vv) vv = t;
        clipped = true;
    }
    if (!clipped) return;
    for (int i = 0; i < 3; ++i) col[i] = static_cast<float>(vv * col[i] + (1. - vv) * grey[i]);
}

// sscanf(line, format, ...) for formats of literal text, white space and %f: the number
// of values read before the first mismatch.
int scanFloats(const std::string& line, const char* format, float* out) {
    const char* s = line.c_str();
    int n = 0;
    for (const char* f = format; *f; ++f) {
        if (std::isspace(static_cast<unsigned char>(*f))) {
            while (std::isspace(static_cast<unsigned char>(*s))) ++s;
        } else if (f[0] == '%' && f[1] == 'f') {
            char* end = nullptr;
            const float v = std::strtof(s, &end);
            if (end == s) return n;
            out[n++] = v;
            s = end;
            ++f;
        } else if (*s++ != *f) {
            return n;
        }
    }
    return n;
}

}  // namespace

ColorMatrix rgbToXyzBalanced(const std::optional<Primaries>& p) {
    const ColorMatrix m = rgbToXyz(widen(p));
    const std::array<float, 2> w = whiteOf(p);
    if (whiteIsNeutral(w)) return m;
    return compose(whiteBalance(w, {kNeutral, kNeutral}), m);
}

ColorMatrix rgbToRgbBalanced(const std::optional<Primaries>& from,
                             const std::optional<Primaries>& to) {
    if (!from && !to) return identity();
    const ColorMatrix toXyz = rgbToXyz(widen(from));
    const ColorMatrix balance = whiteBalance(whiteOf(from), whiteOf(to));
    const ColorMatrix toRgb = xyzToRgb(widen(to));
    return compose(toRgb, compose(balance, toXyz));
}

ColorMatrix xyzToRgbBalanced(const std::optional<Primaries>& to) {
    const ColorMatrix m = xyzToRgb(widen(to));
    const std::array<float, 2> w = whiteOf(to);
    if (whiteIsNeutral(w)) return m;
    return compose(m, whiteBalance({kNeutral, kNeutral}, w));
}

void matrixScan(const ColorMatrix& m, Pixel* scan, int n) {
    static const Pixel black{0, 0, 0}, white{1, 1, 1};
    for (int i = 0; i < n; ++i) {
        scan[i] = colorTransform(m, scan[i]);
        clipGamut(scan[i], greyPoint(scan[i]), black, white);
    }
}

Macbeth readMacbeth(std::istream& in, const std::string& what) {
    // The lines pcond takes from a macbethcal .cal file: six-point curves per channel
    // (input "xa", output "ya") and the colour matrix.
    static const char* const kFormats[9] = {"rxa(i) : select(i,%f,%f,%f,%f,%f,%f)",
                                            "rya(i) : select(i,%f,%f,%f,%f,%f,%f)",
                                            "gxa(i) : select(i,%f,%f,%f,%f,%f,%f)",
                                            "gya(i) : select(i,%f,%f,%f,%f,%f,%f)",
                                            "bxa(i) : select(i,%f,%f,%f,%f,%f,%f)",
                                            "bya(i) : select(i,%f,%f,%f,%f,%f,%f)",
                                            "ro = %f*rn + %f*gn + %f*bn",
                                            "go = %f*rn + %f*gn + %f*bn",
                                            "bo = %f*rn + %f*gn + %f*bn"};
    Macbeth mb;
    int found = 0;
    std::string line;
    while (std::getline(in, line)) {
        for (int k = 0; k < 9; ++k) {
            if (found & (1 << k)) continue;
            float v[6];
            const int want = k < 6 ? 6 : 3;
            if (scanFloats(line, kFormats[k], v) != want) continue;
            for (int i = 0; i < want; ++i) {
                if (k < 6)
                    (k % 2 ? mb.ya : mb.xa)[k / 2][i] = v[i];
                else
                    mb.matrix[k - 6][i] = v[i];
            }
            found |= 1 << k;
            break;
        }
    }
    if (found != 0777) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "0%o", found);
        throw InputError(SourceLoc{what, 0},
                         std::string("cannot grok macbethcal file (inpflags==") + buf + ")");
    }
    for (int i = 0; i < 3; ++i) {  // the gamut: the curves extended to output 0 and 1
        const auto& x = mb.xa[i];
        const auto& y = mb.ya[i];
        mb.cmin[i] = x[0] - y[0] * (x[1] - x[0]) / (y[1] - y[0]);
        mb.cmax[i] = static_cast<float>(x[4] + (1. - y[4]) * (x[5] - x[4]) / (y[5] - y[4]));
    }
    return mb;
}

void macbethScan(const Macbeth& mb, Pixel* scan, int n) {
    for (int k = 0; k < n; ++k) {
        Pixel& c = scan[k];
        c = colorTransform(mb.matrix, c);
        clipGamut(c, greyPoint(c), mb.cmin, mb.cmax);
        for (int i = 0; i < 3; ++i) {
            const double d = c[i];
            const auto& x = mb.xa[i];
            const auto& y = mb.ya[i];
            int j = 0;
            while (j < 4 && x[j + 1] <= d) ++j;
            c[i] = static_cast<float>(((x[j + 1] - d) * y[j] + (d - x[j]) * y[j + 1]) /
                                      (x[j + 1] - x[j]));
        }
    }
}

}  // namespace rp::pcond_detail

namespace rp {

std::array<float, 9> xyzToRgbWhiteBalanced(const std::array<float, 8>& primaries) {
    const pcond_detail::ColorMatrix m = pcond_detail::xyzToRgbBalanced(primaries);
    std::array<float, 9> out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[size_t(3 * i + j)] = m[size_t(i)][size_t(j)];
    return out;
}

}  // namespace rp
