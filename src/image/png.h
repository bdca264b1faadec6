// PNG writer for 8-bit RGB previews (ra_png, falsecolour plans), through libpng. No PNG
// reading here, no other pixel types: RADIANCE pictures are the real output format; PNG
// is for looking at them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rp {

// Encodes width*height RGB triples (top row first) as a complete, deflate-compressed PNG
// file image. gamma: if set, a gAMA chunk for a plain power-law encoding (value
// 1/gamma); otherwise an sRGB chunk declares the sRGB transfer curve.
std::string encodePng(int width, int height, const std::vector<uint8_t>& rgb,
                      std::optional<double> gamma);

}  // namespace rp
