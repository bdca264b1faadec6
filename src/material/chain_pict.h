// Pictures as 2-D interpolation tables for colorpict and mixpict (RADIANCE data.c getpict
// and datavalue), and spectral pictures for specpict (getspec): three channels, or a
// spectrum's samples, on a grid whose shorter side spans 0..1 in (u,v), u to the right
// and v up. Reading scene records and calling .cal functions is not here.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "util/color.h"
#include "util/spectrum.h"

namespace rp::material {

class PictTable {
public:
    // Reads a RADIANCE picture (any orientation; PIXASPECT honoured). Throws InputError
    // for unreadable or malformed files.
    static PictTable load(const std::string& path);
    // Reads a RADIANCE 6 spectral picture (FORMAT=Radiance_spectra, more than 3 samples).
    static PictTable loadSpectral(const std::string& path);
    // From pixels in memory, top row first (for tests and callers that already hold one).
    static PictTable fromPixels(int width, int height, const std::vector<Color>& topFirst,
                                double pixelAspect = 1);

    int width() const { return width_; }
    int height() const { return height_; }
    double uSize() const { return uSize_; }  // the picture spans u in [0, uSize]
    double vSize() const { return vSize_; }

    // Bilinear value at (u, v). RADIANCE compat (data.c datavalue): pixels are grid
    // nodes, the first and last at the picture's edges; outside the picture values are
    // extrapolated linearly for one more pixel, then taper off harmonically to zero.
    Color value(double u, double v) const;
    // The same for every channel: out.size() == channels().
    void values(double u, double v, std::span<double> out) const;
    int channels() const { return channels_; }
    // A spectral picture's bands (sampling.n == channels()).
    const spectral::Sampling& sampling() const { return sampling_; }

private:
    void setSize(int width, int height, double pixelAspect);
    int width_ = 0, height_ = 0, channels_ = 3;
    double uSize_ = 1, vSize_ = 1;
    spectral::Sampling sampling_;
    std::vector<double> bottomFirst_;  // channels_ values per pixel; row 0 is the bottom row
};

}  // namespace rp::material
