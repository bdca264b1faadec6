// RADIANCE's 4-byte shared-exponent pixels (COLR: RGBE or XYZE) and the scanline
// codecs of picture files: new-style run-length encoding, old-style runs and flat data.
// Headers, resolution strings and whole pictures live in picture.h.
#pragma once

#include <array>
#include <cstdint>
#include <streambuf>
#include <string>

namespace rp {

// A float pixel: red, green, blue (or X, Y, Z in an XYZE picture), as RADIANCE's COLOR.
using Pixel = std::array<float, 3>;

// A packed pixel: three 8-bit mantissas and a shared exponent biased by 128 (COLR).
using Colr = std::array<uint8_t, 4>;

// RADIANCE compat: setcolr() in color.c. The largest component d is split with frexp
// (d = m * 2^e, m in [0.5,1)); each component is scaled by m*256/d and truncated, so the
// largest mantissa is in [128,255]; the exponent byte is e+128. Components <= 1e-32 in the
// maximum give (0,0,0,0); negative components become 0. Beyond RADIANCE, NaN counts as 0
// and values too large for the exponent byte saturate to (255,255,255,255).
Colr toColr(double r, double g, double b);
inline Colr toColr(const Pixel& p) { return toColr(p[0], p[1], p[2]); }

// RADIANCE compat: colr_color() in color.c: (mantissa + 0.5) * 2^(exp - 136), i.e. the
// centre of the truncation interval; exponent byte 0 means black.
Pixel toPixel(const Colr& c);

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
