// Display mapping for ra_png (see tonemap.h).
#include "image/tonemap.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "image/png.h"
#include "image/spectral_picture.h"
#include "util/error.h"
#include "util/file_write.h"
#include "util/spectrum.h"

namespace rp {

namespace {

// sRGB (ITU-R BT.709) chromaticities with RADIANCE's equal-energy white: a RADIANCE
// XYZ white (1,1,1) stays neutral on screen, as RADIANCE's own displays treat it.
constexpr std::array<double, 8> kDisplayPrimaries = {0.640, 0.330, 0.300,   0.600,
                                                     0.150, 0.060, 1.0 / 3, 1.0 / 3};

using Mat3 = std::array<double, 9>;

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

std::vector<uint8_t> toDisplayRgb8(const Picture& pic, double exposure,
                                   std::optional<double> gamma) {
    const bool xyz = pic.format == PictureFormat::kXyze;
    const Mat3 m = spectral::rgbFromXyz(kDisplayPrimaries);
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
    // RADIANCE compat: its 8-bit converters (ra_tiff, ra_bmp) read a spectral picture
    // with fread2colrs(), band averages as RGBE.
    constexpr auto how = SpectralToRgb::kBandAveragesRgbe;
    Picture pic = input == "-" ? readPictureAsRgb(std::cin, "standard input", how)
                               : readPictureAsRgb(input, how);
    if (opt.gamma && !(*opt.gamma > 0)) throw InputError("-g: gamma must be positive");
    double e = opt.exposure ? *opt.exposure : autoExposure(pic);
    writeFileAtomically(
        output, encodePng(pic.width, pic.height, toDisplayRgb8(pic, e, opt.gamma), opt.gamma));
}

}  // namespace rp
