// Lossy compression of a precomputed photon's binned contributions (precomp_contrib.h),
// as the photon-map development branch does it (tech report rev 1.13: Daubechies-4
// wavelets, the largest coefficients kept): a modifier's RGB bins are padded by mirroring
// to a multiple of 8, transformed with the orthonormal D4 wavelet (periodic, while the
// length halves evenly), and the `kept` coefficients of largest RGB
// magnitude are stored with their index. Records have a fixed size so that a file of
// them is addressed by photon index alone (and read out of core through the page cache).
// Our choices where the branch is silent: 1-D over the bins in their own order (a
// Reinhart or Klems numbering runs along rows of neighbouring patches; the branch's
// Shirley-Chiu square is 2-D), a coefficient as its index (1 byte up to 256 coefficients)
// and three signed 8-bit mantissas with a shared exponent (5 bytes), the coarsest
// approximation always kept (the totals
// stay unbiased), and the reconstruction not clamped at zero (clamping the ringing around
// a sun bin biased totals by +13 % at comp 0.9). With comp 0 the bins are stored as
// floats, untransformed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rp::pmap {

using Rgb = std::array<double, 3>;

// Daubechies-4 transform in place over x, with periodic boundaries, level after level
// while the length is even and at least 4; the approximation coefficients end first.
// Orthonormal: the inverse is the transpose, and the sum of squares is kept.
void d4Forward(std::span<double> x, std::vector<double>& scratch);
void d4Inverse(std::span<double> x, std::vector<double>& scratch);

class CoeffCodec {
public:
    // `comp` in [0, 1]: 0 stores the bins as they are; otherwise the coarsest
    // approximation (19 of 152 coefficients for 146 bins) and (1 - comp) of the others.
    CoeffCodec(int bins, double comp);

    int bins() const { return bins_; }
    int length() const { return length_; }  // padded length (a multiple of 8)
    int kept() const { return kept_; }      // coefficients per record; 0 when raw
    bool raw() const { return kept_ == 0; }
    int approximation() const { return approx_; }  // always among the kept
    size_t recordBytes() const {
        return raw() ? size_t(bins_) * 12 : size_t(kept_) * coefficientBytes();
    }

    // Per-thread buffers.
    struct Scratch {
        std::array<std::vector<double>, 3> channels;
        std::vector<double> tmp;
        std::vector<uint32_t> order;
        std::vector<double> magnitude;  // by coefficient, for choosing the kept ones
    };
    // Writes recordBytes() bytes for `bins` values.
    void encode(std::span<const Rgb> values, uint8_t* out, Scratch& s) const;
    // Reads a record into `values` (bins() entries).
    void decode(const uint8_t* in, std::span<Rgb> values, Scratch& s) const;

private:
    // A kept coefficient: its index (one byte up to 256 coefficients, else two), then
    // its RGB values in 4 bytes.
    size_t indexBytes() const { return length_ <= 256 ? 1 : 2; }
    size_t coefficientBytes() const { return indexBytes() + 4; }
    void putIndex(uint8_t* at, uint32_t i) const;
    uint32_t getIndex(const uint8_t* at) const;

    int bins_ = 0, length_ = 0, kept_ = 0;
    int approx_ = 0;  // coefficients of the coarsest approximation, always kept
};

}  // namespace rp::pmap
