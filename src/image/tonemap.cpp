// Display mapping for ra_png (see tonemap.h).
#include "image/tonemap.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "image/png.h"
#include "util/error.h"
#include "util/file_write.h"

namespace rp {

namespace {

// sRGB (ITU-R BT.709) chromaticities with RADIANCE's equal-energy white: a RADIANCE
// XYZ white (1,1,1) stays neutral on screen, as RADIANCE's own displays treat it.
constexpr std::array<double, 8> kDisplayPrimaries = {0.640, 0.330, 0.300,   0.600,
                                                     0.150, 0.060, 1.0 / 3, 1.0 / 3};

using Mat3 = std::array<double, 9>;

Mat3 inverse(const Mat3& m) {
    double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7], i = m[8];
    double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    RP_CHECK(det != 0);
    double k = 1 / det;
    return {(e * i - f * h) * k, (c * h - b * i) * k, (b * f - c * e) * k,
            (f * g - d * i) * k, (a * i - c * g) * k, (c * d - a * f) * k,
            (d * h - e * g) * k, (b * g - a * h) * k, (a * e - b * d) * k};
}

uint8_t encode(double v, std::optional<double> gamma) {
    if (!(v > 0)) return 0;  // also NaN
    if (v >= 1) return 255;
    double e = gamma ? std::pow(v, 1 / *gamma)
                     : (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055);
    return static_cast<uint8_t>(std::lround(e * 255));
}

}  // namespace

double parseExposureArg(const std::string& arg) {
    char* end;
    double v = std::strtod(arg.c_str(), &end);
    if (arg.empty() || *end != '\0' || !std::isfinite(v))
        throw InputError("-e: bad exposure '" + arg + "'");
    // RADIANCE compat: ra_tiff etc. read a signed value as f-stops.
    if (arg[0] == '+' || arg[0] == '-') return std::pow(2.0, v);
    if (v <= 0) throw InputError("-e: exposure must be positive");
    return v;
}

double pixelBrightness(const Pixel& c) {
    return 0.265074126 * c[0] + 0.670114631 * c[1] + 0.064811243 * c[2];
}

double autoExposure(const Picture& pic) {
    double sumLog = 0;
    size_t n = 0;
    for (const auto& p : pic.pixels) {
        double y = pic.format == PictureFormat::kXyze ? p[1] : pixelBrightness(p);
        if (y > 1e-9 && std::isfinite(y)) {
            sumLog += std::log(y);
            ++n;
        }
    }
    if (n == 0) return 1;
    return 0.18 / std::exp(sumLog / static_cast<double>(n));
}

std::array<double, 9> rgbFromXyz(const std::array<double, 8>& p) {
    // Columns: XYZ of each primary at Y=1, scaled so that they sum to the white point.
    auto xyz = [](double x, double y) { return std::array<double, 3>{x / y, 1, (1 - x - y) / y}; };
    auto r = xyz(p[0], p[1]), g = xyz(p[2], p[3]), b = xyz(p[4], p[5]), w = xyz(p[6], p[7]);
    Mat3 m = {r[0], g[0], b[0], r[1], g[1], b[1], r[2], g[2], b[2]};
    Mat3 mi = inverse(m);
    double s[3];
    for (int i = 0; i < 3; ++i)
        s[i] = mi[3 * i] * w[0] + mi[3 * i + 1] * w[1] + mi[3 * i + 2] * w[2];
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) m[3 * row + col] *= s[col];
    return inverse(m);
}

std::vector<uint8_t> toDisplayRgb8(const Picture& pic, double exposure,
                                   std::optional<double> gamma) {
    const bool xyz = pic.format == PictureFormat::kXyze;
    const Mat3 m = rgbFromXyz(kDisplayPrimaries);
    std::vector<uint8_t> out(pic.pixels.size() * 3);
    for (size_t i = 0; i < pic.pixels.size(); ++i) {
        const Pixel& p = pic.pixels[i];
        double c[3] = {p[0], p[1], p[2]};
        if (xyz)
            for (int k = 0; k < 3; ++k)
                c[k] = m[3 * k] * p[0] + m[3 * k + 1] * p[1] + m[3 * k + 2] * p[2];
        for (int k = 0; k < 3; ++k) out[3 * i + k] = encode(c[k] * exposure, gamma);
    }
    return out;
}

void convertPictureToPng(const std::string& input, const std::string& output,
                         const DisplayOptions& opt) {
    Picture pic = input == "-" ? readPicture(std::cin, "standard input") : readPicture(input);
    if (opt.gamma && !(*opt.gamma > 0)) throw InputError("-g: gamma must be positive");
    double e = opt.exposure ? *opt.exposure : autoExposure(pic);
    writeFileAtomically(
        output, encodePng(pic.width, pic.height, toDisplayRgb8(pic, e, opt.gamma), opt.gamma));
}

}  // namespace rp
