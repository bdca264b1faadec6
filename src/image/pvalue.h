// RADIANCE's pvalue: a picture's pixels as text or binary values (one pixel per line,
// optionally with coordinates, or brightness only), and with -r the reverse, values to a
// RADIANCE picture, so that e.g. an rtrace sensor grid can go through falsecolor.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "image/picture.h"
#include "util/options.h"

namespace rp {

enum class ValueFormat { kAscii, kFloat, kDouble };  // -da, -df, -dd

struct PvalueOptions {
    std::string input = "-";  // the picture (or, with -r, the values); "-" is stdin
    bool reverse = false;     // -r: values -> picture
    bool header = true;       // -h turns off the header (written or read)
    bool resolution = true;   // -H turns off the resolution string (written or read)
    bool original = false;    // -o: values before EXPOSURE (and COLORCORR)
    bool brightness = false;  // -b: one value per pixel
    bool coordinates = true;  // -d..: pixel data only; +d.. keeps coordinates
    ValueFormat format = ValueFormat::kAscii;
    double exposure = 1;             // -e: multiplier, or +/-stops when signed
    std::optional<Resolution> size;  // -y N +x M (any of +-x +-y, first is major)
};

// The picture size options (-y N +x M) as they are read, before both are checked.
struct PvalueSize {
    int x = 0, y = 0;
    Resolution res;
    bool first = true;  // no size given yet
};

// pvalue's options (util/options.h), reading into `opt` and `size`; its -defaults lists
// opt's values.
OptionTable pvalueTable(PvalueOptions& opt, PvalueSize& size);

// Parses pvalue's arguments (without the program name): options, then at most one input
// file. Throws InputError naming the option for unknown options, missing or bad values.
PvalueOptions parsePvalueArgs(const std::vector<std::string>& args);

namespace pvalue_detail {
// RADIANCE compat: CIE_rf, CIE_gf, CIE_bf as color.h computes them from its standard
// primaries and equal-energy white, in the same order: 0.26510583, 0.67010583,
// 0.06478836 (the ".265074126" etc. in its comment are not what it compiles to;
// RADIANCE 6.1a's pvalue -b output fits these to 1e-8).
constexpr double xr = 0.640, yr = 0.330, xg = 0.290, yg = 0.600, xb = 0.150, yb = 0.060;
constexpr double xw = 1. / 3., yw = 1. / 3.;
constexpr double kD = xr * (yg - yb) + xg * (yb - yr) + xb * (yr - yg);
constexpr double kCr = (1. / yw) * (xw * (yg - yb) - yw * (xg - xb) + xg * yb - xb * yg);
constexpr double kCg = (1. / yw) * (xw * (yb - yr) - yw * (xb - xr) - xr * yb + xb * yr);
constexpr double kCb = (1. / yw) * (xw * (yr - yg) - yw * (xr - xg) + xr * yg - xg * yr);
constexpr double kRf = yr * kCr / kD, kGf = yg * kCg / kD, kBf = yb * kCb / kD;
}  // namespace pvalue_detail

// RADIANCE's bright(): the luminance-weighted sum of an RGB colour.
inline double brightness(const Pixel& p) {
    using namespace pvalue_detail;
    return kRf * p[0] + kGf * p[1] + kBf * p[2];
}

// Picture -> values. `commandLine` is appended to the picture's header lines.
void writeValues(std::ostream& out, const Picture& pic, const PvalueOptions& opt,
                 const std::string& commandLine);

// Values -> picture; `what` names the input in errors, which are InputErrors with the
// line (ASCII input) of a bad number, a line with the wrong number of values, or a count
// of pixels that does not fill the resolution.
Picture readValues(std::istream& in, const std::string& what, const PvalueOptions& opt,
                   const std::string& commandLine);

// The tool: reads opt.input (or `in` for "-"), writes values or a picture to `out`.
void runPvalue(const PvalueOptions& opt, const std::string& commandLine, std::istream& in,
               std::ostream& out);

}  // namespace rp
