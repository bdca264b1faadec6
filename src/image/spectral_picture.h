// RADIANCE 6 hyperspectral pictures (".hsr"): FORMAT=Radiance_spectra, NCOMP=n samples
// per pixel over WAVELENGTH_SPLITS= (longest wavelength first), each pixel n mantissa
// bytes and one shared exponent byte (RADIANCE's SCOLR). Reading, writing, and turning
// them into RGB pictures the way RADIANCE 6's picture tools do. RGB/XYZ pictures stay in
// picture.h.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "image/picture.h"
#include "util/header.h"
#include "util/spectrum.h"

namespace rp {

constexpr const char* kSpectralFormat = "Radiance_spectra";

struct SpectralPicture {
    int width = 0;
    int height = 0;
    // n is NCOMP= (3..24; 3 when the header has none, as RADIANCE assumes), wl is
    // WAVELENGTH_SPLITS= (RADIANCE's 780 588 480 380 when absent), as RADIANCE reads them
    // (float). rgb[] is what RADIANCE's setspectrsamp picks for n and wl's extremes.
    spectral::Sampling sampling;
    // Header lines other than FORMAT=. NCOMP= and WAVELENGTH_SPLITS= stay where they
    // were; writeSpectralPicture brings them in line with `sampling`.
    Header header;
    // width*height pixels, row-major, top row first; each sampling.n values, longest
    // wavelength first.
    std::vector<float> samples;
    // The resolution string as RADIANCE's fputsresolu writes it, "-Y        6 +X        8"
    // (rtrace, rcomb), rather than as fprtresolu, "-Y 6 +X 8" (rpict); kept from the file.
    bool paddedResolution = false;

    SpectralPicture() = default;
    SpectralPicture(int w, int h, const spectral::Sampling& s)
        : width(w), height(h), sampling(s), samples(static_cast<size_t>(w) * h * s.n) {}

    // x from the left, y from the top.
    std::span<float> at(int x, int y) {
        return {samples.data() + (static_cast<size_t>(y) * width + x) * sampling.n,
                static_cast<size_t>(sampling.n)};
    }
    std::span<const float> at(int x, int y) const {
        return {samples.data() + (static_cast<size_t>(y) * width + x) * sampling.n,
                static_cast<size_t>(sampling.n)};
    }

    // As Picture's: product of EXPOSURE= values, of PIXASPECT= values (1 if none).
    double exposure() const;
    double pixelAspect() const;
};

// Whether a header's FORMAT= names a spectral picture.
bool isSpectralFormat(const Header& h);

// One pixel packed (RADIANCE's scolor2scolr): n mantissas and an exponent byte, the
// largest mantissa in [128, 255]; all 0 for a maximum <= 1e-32. Beyond RADIANCE, NaN
// counts as 0 and values past the exponent byte saturate to 255s. out.size() == n + 1.
void packSpectrum(std::span<const float> in, std::span<uint8_t> out);
// And back (scolr2scolor): (mantissa + 0.5) * 2^(exponent - 136); exponent 0 is black.
void unpackSpectrum(std::span<const uint8_t> in, std::span<float> out);

// Reads a spectral picture; `what` names the source in errors. Throws InputError for
// anything else (other FORMAT, bad NCOMP= or WAVELENGTH_SPLITS=, bad resolution line,
// truncated or corrupt scanlines). Any of the 8 resolution orientations.
SpectralPicture readSpectralPicture(std::istream& in, const std::string& what);
SpectralPicture readSpectralPicture(const std::string& path);

// Writes header (NCOMP=, WAVELENGTH_SPLITS= as in SpectralPicture::header, FORMAT= last),
// the standard resolution string (padded or not) and the scanlines as RADIANCE's
// fwritescolrs: flat n+1 byte pixels, or run-length encoded RGBE when n == 3. A picture
// read from a file RADIANCE wrote in standard orientation is written back byte for byte.
void writeSpectralPicture(std::ostream& out, const SpectralPicture& pic);
// Atomically, as writePicture(path, ...).
void writeSpectralPicture(const std::string& path, const SpectralPicture& pic);

// How RADIANCE 6's tools see a spectral picture as RGB. Both use band averages (its
// scolor2color: each channel the mean of the samples whose band centres fall between the
// channel's WAVELENGTH_SPLITS), not the CIE observer.
enum class SpectralToRgb {
    kBandAverages,      // fread2scan, as pvalue reads pixels: float averages
    kBandAveragesRgbe,  // fread2colrs, as ra_rgbe/ra_tiff/ra_bmp/pcond read them: the
                        // averages stored as RGBE (scolr2colr)
};

// The picture as RGB: pixels converted as `how` says; header without NCOMP= and
// WAVELENGTH_SPLITS= (as ra_rgbe writes it), format RGBE.
Picture toRgbPicture(const SpectralPicture& pic, SpectralToRgb how);

// Reads an RGB/XYZ picture, or a spectral one converted as `how` says: for tools that
// work on RGB and take RADIANCE 6's spectral pictures too. Errors as readPicture's.
Picture readPictureAsRgb(std::istream& in, const std::string& what, SpectralToRgb how);
Picture readPictureAsRgb(const std::string& path, SpectralToRgb how);

}  // namespace rp
