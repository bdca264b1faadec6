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

// RADIANCE's bright(): the luminance-weighted sum of an RGB colour.
inline double brightness(const Pixel& p) { return 0.265 * p[0] + 0.670 * p[1] + 0.065 * p[2]; }

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
