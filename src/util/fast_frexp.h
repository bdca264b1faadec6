// std::frexp for normal doubles by moving the exponent field: exact, the same bits, and
// inline. Why: std::frexp is a library call, and mkpmap makes four per stored photon
// (its RGBE flux, then three coordinates in the file).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace rp {

// As std::frexp(x, &e): x = frac x 2^e with 0.5 <= |frac| < 1, or frac = x and e = 0
// for zero, infinities and NaN. Subnormals go to std::frexp.
inline double frexpFast(double x, int& e) {
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = int((bits >> 52) & 0x7ff);
    if (biased == 0 || biased == 0x7ff) return std::frexp(x, &e);
    e = biased - 1022;
    bits = (bits & ~(uint64_t{0x7ff} << 52)) | (uint64_t{1022} << 52);
    double frac;
    std::memcpy(&frac, &bits, sizeof frac);
    return frac;
}

}  // namespace rp
