// pfilt: RADIANCE's picture filter (exposure, anti-aliasing, resizing, star patterns).
// Two passes by default: the first finds the picture's average brightness (pixels below
// the "hot" level -h) so the exposure puts it at 0.5, and records the hot pixels; the
// second adds star points (-n) to the hot pixels' neighbours, applies the exposure and
// filters down (or up) to the output size with a box (default), a Gaussian of radius -r
// output pixels, or a Gaussian whose radius grows with a pixel's contrast to its
// surroundings (-m, RADIANCE's threshold filter). -1 skips the first pass: -e is then
// the whole exposure.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "image/picture.h"
#include "util/options.h"

namespace rp {

struct PfiltOptions {
    int xres = 0;                             // -x N (0: from xRatio)
    double xRatio = 1;                        // -x /f gives xRatio 1/f
    int yres = 0;                             // -y N
    double yRatio = 1;                        // -y /f
    double pixelAspect = 0;                   // -p: output pixel aspect (0: any)
    bool correctAspect = false;               // -c: aspect is being corrected, no PIXASPECT= line
    std::array<double, 3> exposure{1, 1, 1};  // -e, -er, -eg, -eb (products)
    bool singlePass = false;                  // -1
    int starPoints = 0;                       // -n N: N/2 star lines through each hot pixel
    double spread = 1e-4;                     // -s
    bool averageHot = false;                  // -a: hot pixels count in the average
    double hotLevel = 100;                    // -h (times the input's EXPOSURE)
    double radius = 0;                        // -r (output pixels); 0: box filter
    double threshold = 0;                     // -m; 0: no threshold filter
    std::string inputFile;                    // "" : standard input
};

// pfilt's option table over `opt`; the -defaults text is RADIANCE's usage in lines.
OptionTable pfiltTable(PfiltOptions& opt);
// Options then at most one file; throws InputError (unknown option, two files, ...).
// `optionWords` receives the number of words that were options (for the header line).
PfiltOptions parsePfiltArgs(std::vector<std::string>& args, size_t& optionWords);

// The output size RADIANCE's pfilt gives a picture of `in` pixels with `aspect`
// (PIXASPECT= product of the input).
struct PfiltSize {
    int ncols = 0;
    int nrows = 0;
};
PfiltSize pfiltOutputSize(int xres, int yres, double aspect, const PfiltOptions& opt);

// Filters `in`; `history` is the command line added to the header (RADIANCE writes the
// program and its options, not the file). Throws InputError naming `what` (the input)
// for a picture too dark or too bright to set an exposure.
// `in` holds the picture in its file's scanline order (rows are scanlines, which run
// along Y when !yMajor: -x and -y then size the scanlines, as RADIANCE's).
Picture runPfilt(const Picture& in, const PfiltOptions& opt, const std::string& history,
                 const std::string& what, bool yMajor = true);
// Reads a picture from `in`, filters it and writes it to `out` in the input's scanline
// order.
void runPfilt(std::istream& in, const std::string& what, const PfiltOptions& opt,
              const std::string& history, std::ostream& out);

// glibc's lrand48() before any srand48 (48-bit linear congruential
// generator, 31 bits out), which gives RADIANCE's star points their directions.
class Rand48 {
public:
    long next();

private:
    uint64_t state_ = 0;  // glibc before any srand48 (not POSIX's 0x1234ABCD330E)
};

}  // namespace rp
