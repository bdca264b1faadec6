// vwrays, RADIANCE's view-to-rays program (vwrays(1)): the origin and direction of the
// ray through each pixel of a view or of a picture, as rpict traces them (the same
// mapping, jitter and aperture: render::pixelRay), for rtrace or rcontrib to trace.
// Option parsing lives in tools/vwrays.cpp; reading the picture's header here.
#pragma once

#include <iosfwd>
#include <string>

#include "image/picture.h"
#include "image/view.h"
#include "render/rpict.h"

namespace rp::rays {

struct VwraysOptions {
    View view;                // -v* (rpict's defaults)
    int xres = 512;           // -x
    int yres = 512;           // -y
    double pixelAspect = 1;   // -pa
    double jitter = 0;        // -pj
    double aperture = 0;      // -pd
    int repeat = 1;           // -c: rays per pixel (none when below 1)
    char format = 'a';        // -fa, -ff, -fd
    bool fromInput = false;   // -i: pixel positions "x y" from the input
    bool unbuffered = false;  // -u: flush after each input position
    std::string picture;      // view and resolution from this picture's header
    std::string depthFile;    // with `picture`: its depth buffer (floats, picture order)
};

// What the rays are made from: the view (command line, then the picture's VIEW= lines
// applied on top, as RADIANCE's viewfile) and the resolution (the picture's, or -x -y
// fitted to the view's aspect as rpict's normaspect does).
class Vwrays {
public:
    // Throws InputError: a picture without a view ("no view in picture"), an unreadable
    // picture, or an invalid view (ViewRays' messages).
    explicit Vwrays(const VwraysOptions& options);

    const Resolution& resolution() const { return res_; }
    // "-x 512 -y 512 -ld-" (vwrays -d), without the newline.
    std::string dimensionsLine() const;

    // Every pixel's rays, scanline by scanline in the picture's order (or top to bottom
    // for a view). Throws InputError when the depth buffer is short.
    void writeAll(std::ostream& out) const;
    // The rays of each "x y" pixel position read from `in` (-i): x from the left, y from
    // the bottom, pixel centres at whole numbers. Throws InputError for input that is not
    // pairs of numbers ("expected px py on input") and, with a depth buffer, a position
    // outside the picture.
    void writeFromInput(std::istream& in, std::ostream& out) const;

private:
    // One ray of image location (x, y) in [0,1)^2 (y up) from the stream (seed, index).
    std::optional<ViewRays::Ray> jittered(double x, double y, uint64_t seed, uint64_t index) const;
    // Writes ray `r` (zeros for none) made at depth `z` (< 0: no depth buffer).
    void put(std::ostream& out, const std::optional<ViewRays::Ray>& r, double z,
             bool depthScalesDirection) const;

    VwraysOptions opt_;
    Resolution res_;
    ViewRays rays_;
    render::PixelRayParams params_;
};

}  // namespace rp::rays
