// RADIANCE's falsecolor: a picture's luminance mapped to a colour scale (linear or over
// log decades), optionally as contour lines, contour bands or posterized steps, with the
// legend (colour bar, division values, unit label) left of the image and the extrema
// marked. Palettes live in falsecolor_palette.h, the legend font in legend_font.h.
#pragma once

#include <array>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "image/falsecolor_palette.h"
#include "image/picture.h"
#include "util/options.h"

namespace rp {

enum class ContourMode { kNone, kLines, kBands, kPosterize };  // -cl, -cb, -cp

// Option defaults are RADIANCE 5.4 falsecolor.pl's.
struct FalseColorOptions {
    std::string input = "-";      // -i (or -ip): the picture whose luminance is mapped
    std::string background;       // -p (or -ip): shown where contours leave gaps
    double scale = 1000;          // -s: top of the scale, in multiplier units
    bool autoScale = false;       // -s a: top from the picture's brightest values
    int ndivs = 8;                // -n
    std::string label = "cd/m2";  // -l
    double multiplier = 179;      // -m: W/sr/m2 to cd/m2 (luminous efficacy)
    int decimals = 3;             // -d: decimals kept in legend numbers
    double decades = 0;           // -log: 0 means linear
    FalseColorPalette palette = FalseColorPalette::kDef;  // -pal
    std::array<std::string, 3> channelExpr;  // -r -g -b: .cal expressions of v ("" = palette)
    ContourMode contour = ContourMode::kNone;
    bool extrema = false;       // -e
    bool showPalettes = false;  // -palettes
    int legendWidth = 100;      // -lw
    int legendHeight = 200;     // -lh
};

// falsecolor's options (util/options.h), reading into `o`; its -defaults lists o's values.
OptionTable falseColorTable(FalseColorOptions& o);

// Parses falsecolor's arguments (without the program name). Throws InputError naming the
// option for unknown options, missing or bad values.
FalseColorOptions parseFalseColorArgs(const std::vector<std::string>& args);

// Value to colour, as falsecolor.pl's pc0.cal/pc1.cal: luminance -> scale position v
// (map) -> colour. Custom -r/-g/-b expressions are compiled once through src/calc.
class FalseColorMap {
public:
    explicit FalseColorMap(const FalseColorOptions& opt);
    ~FalseColorMap();

    // map(x): x is luminance over the scale top; linear, or log10(x)/decades + 1 (0 below
    // the lowest decade).
    double position(double x) const;
    // Colour drawn for position v in the options' contour mode (lines and bands draw the
    // palette stretched so the first division's colour is its bottom; -cp draws the
    // palette at the middle of v's division, likewise stretched). Clipped to [0,1].
    std::array<double, 3> color(double v);
    // The colour at palette coordinate w in [0,1] (palette or -r/-g/-b), clipped.
    std::array<double, 3> paletteAt(double w);
    // Contour tests (falsecolor.pl's iscontb and isconta): band pixels lie in the outer
    // tenths of a division; line pixels have horizontal or vertical neighbours in another
    // division. Both only within half a division of the scale's ends.
    bool inBand(double v) const;
    bool onLine(double v, double left, double right, double above, double below) const;

private:
    const FalseColorOptions& opt_;
    struct Custom;
    std::unique_ptr<Custom> custom_;
};

// A number as falsecolor.pl writes it in the legend: Perl's default formatting (%.15g)
// with the digits after the point cut (not rounded) to `decimals`.
std::string legendNumber(double value, int decimals);
// The division values, top first: scale * (n-i)/n (or its log-decade equivalent) for
// i = 0..n-1, and 0 at the bottom unless contours or posterizing are on.
std::vector<std::string> legendValues(const FalseColorOptions& opt);

// Scale top for -s a: 10^(log10 luminance) of the second-highest bin in a 777-bin histogram of
// the picture's log luminances (RADIANCE's phisto on a 128 x 128 reduction), times
// multiplier/179.
double autoScaleTop(const Picture& pic, double multiplier);

// The whole falsecolor picture: legend left of the (mapped) image, sized and placed as
// RADIANCE's pcompos composes them. `background` may be null. `commandLine` goes into
// the header after the input's lines.
Picture falseColorPicture(const Picture& input, const Picture* background, FalseColorOptions opt,
                          const std::string& commandLine);
// -palettes: every palette as a 256 x 30 strip with its name above, bottom to top.
Picture paletteChart(const std::string& commandLine);

// The tool: reads the pictures named in `opt`, writes the result to `out`.
void runFalseColor(const FalseColorOptions& opt, const std::string& commandLine, std::istream& in,
                   std::ostream& out);

}  // namespace rp
