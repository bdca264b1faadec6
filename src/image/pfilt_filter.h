// pfilt's second-pass filters over a whole exposed picture in memory: the box filter,
// the Gaussian (-r) and the threshold Gaussian (-m), plus the star points (-n) added to
// the input before them. See pfilt.h for the options.
#pragma once

#include <vector>

#include "image/picture.h"

namespace rp {

// Input and output sizes, their ratios and the filter parameters of one run.
struct PfiltFrame {
    int xres = 0, yres = 0;         // input
    int ncols = 0, nrows = 0;       // output
    double xRatio = 1, yRatio = 1;  // output over input
    double radius = 0;              // Gaussian radius in output pixels (0: box)
    double threshold = 0;           // threshold filter limit (0: none)
    bool xyz = false;               // XYZE picture: brightness is Y
    bool wrap = false;              // 360-degree cylindrical view: filters wrap around the sides

    // RADIANCE 5.4's bright(): luminance weights of its standard primaries under its
    // equal-energy white (not tonemap.h's older weights), so the exposure agrees.
    double brightness(const Pixel& p) const {
        return xyz ? p[1] : 0.265105820 * p[0] + 0.670105820 * p[1] + 0.064788360 * p[2];
    }
};

// A pixel at or above the hot level, with the slope of its star line.
struct HotPixel {
    Pixel value;
    int x = 0, y = 0;  // from the left, from the top
    float slope = 0;
};

// Adds each hot pixel's star line (pixels along its slope, within half a pixel) to `pic`,
// falling off as spreadFactor / distance^2 beyond sqrt(spreadFactor).
void addStarPoints(Picture& pic, const std::vector<HotPixel>& hot, double spreadFactor);

// The output picture (pixels only) of the box, Gaussian or threshold filter.
Picture filterPicture(const Picture& in, const PfiltFrame& frame);

}  // namespace rp
