// Turning a RADIANCE picture into 8-bit display values for ra_png: exposure (given or
// automatic), XYZ to RGB for XYZE pictures, sRGB or power-law gamma encoding. No
// perceptual operators (pcond's job in RADIANCE); this is a viewing aid.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/picture.h"

namespace rp {

struct DisplayOptions {
    std::optional<double> exposure;  // multiplier on file values; automatic if unset
    std::optional<double> gamma;     // power-law gamma; the sRGB curve if unset
};

// Parses ra_*'s -e argument: "+2" or "-1.5" are f-stops (multiplier 2^stops), a plain
// positive number is the multiplier itself. Throws InputError otherwise.
double parseExposureArg(const std::string& arg);

// RADIANCE's luminance weights for its standard primaries (bright() in color.h).
double pixelBrightness(const Pixel& rgb);

// Automatic exposure: the multiplier that maps the log-average brightness of the
// non-black pixels (Reinhard et al. 2002, "Photographic Tone Reproduction", eq. 1) to
// 0.18, photographic mid grey (about 118 of 255 after sRGB encoding). Bright light
// sources clip; the room reads well. 1 for an all-black picture.
double autoExposure(const Picture& pic);

// width*height*3 bytes, top row first: (XYZ converted to sRGB primaries with
// RADIANCE's equal-energy white) * exposure, clipped to [0,1], encoded with the sRGB
// curve or v^(1/gamma), rounded.
std::vector<uint8_t> toDisplayRgb8(const Picture& pic, double exposure,
                                   std::optional<double> gamma);

// ra_png: reads `input` ("-" for standard input), writes `output` atomically.
void convertPictureToPng(const std::string& input, const std::string& output,
                         const DisplayOptions& opt);

}  // namespace rp
