// RADIANCE's 4-byte shared-exponent pixels (COLR: RGBE or XYZE) and the scanline
// codecs of picture files: new-style run-length encoding, old-style runs and flat data.
// Headers, resolution strings and whole pictures live in picture.h.
#pragma once

#include <array>
#include <cstdint>
#include <streambuf>
#include <string>

#include "util/colr.h"

namespace rp {

// A float pixel: red, green, blue (or X, Y, Z in an XYZE picture), as RADIANCE's COLOR.
using Pixel = std::array<float, 3>;

// Packed pixels (Colr) and their float conversion are util/colr.h's, shared with photons.
inline Colr toColr(const Pixel& p) { return toColr(p[0], p[1], p[2]); }
inline Pixel toPixel(const Colr& c) { return colrToRgb(c); }

// Scanline lengths RADIANCE run-length encodes (MINELEN..MAXELEN in color.c); shorter or
// longer scanlines are written flat.
constexpr int kMinRleLength = 8;
constexpr int kMaxRleLength = 0x7fff;

// Appends one scanline to `out` as RADIANCE's fwritecolrs writes it: for lengths in
// [kMinRleLength, kMaxRleLength] the bytes 2,2,len>>8,len&255 followed by the four
// components each encoded separately (a count byte > 128 is a run of count-128 copies of
// the next byte, a count <= 128 is that many literal bytes; runs shorter than 4 are left
// literal unless they start the stretch); otherwise the pixels flat, 4 bytes each.
void encodeScanline(const Colr* scan, int len, std::string& out);

// Reads one scanline of `len` pixels in any of the three encodings, as RADIANCE's
// freadcolrs. Returns "" on success or a short reason ("truncated scanline",
// "scanline length mismatch", "bad run length") on failure; never reads past a
// failure point that would overflow `scan`.
std::string decodeScanline(std::streambuf& in, Colr* scan, int len);

}  // namespace rp
