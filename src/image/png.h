// Minimal PNG writer for 8-bit RGB previews (ra_png). No PNG reading, no other pixel
// types: RADIANCE pictures are the real output format; PNG is only for looking at them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rp {

// Encodes width*height RGB triples (top row first) as a complete PNG file image.
// gamma: if set, a gAMA chunk for a plain power-law encoding (value 1/gamma);
// otherwise an sRGB chunk declares the sRGB transfer curve.
//
// The image data is zlib-wrapped deflate with *stored* (uncompressed) blocks, so we need
// no zlib dependency; files are about 3 bytes per pixel, fine for previews. Swapping in
// zlib's compress2() would only change deflateStored() in png.cpp.
std::string encodePng(int width, int height, const std::vector<uint8_t>& rgb,
                      std::optional<double> gamma);

// CRC-32 as PNG chunks use it (ISO 3309 / ITU-T V.42 polynomial), exposed for tests.
uint32_t pngCrc32(const uint8_t* data, size_t len, uint32_t crc = 0);
// Adler-32 of the zlib stream trailer, exposed for tests.
uint32_t adler32(const uint8_t* data, size_t len);

}  // namespace rp
