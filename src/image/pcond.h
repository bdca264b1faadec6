// pcond: RADIANCE's "condition a picture for display" (Ward Larson, Rushmeier and Piatko
// 1997, "A Visibility Matching Tone Reproduction Operator for High Dynamic Range Scenes").
// A histogram of the picture's world luminances, sampled over 1-degree foveal areas,
// gives a brightness map that compresses the scene's range into the display's (-u, -d)
// without exaggerating contrast (-s: human contrast sensitivity); optionally the
// simulated loss of acuity (-a) and colour (-c) in the dark and veiling glare (-v).
// Pictures whose range fits the display, and -l / -e, are scaled linearly instead.
// Options and the whole run live here; the histogram and brightness map are in
// pcond_histogram.cpp, the human-vision effects in pcond_vision.cpp, the colour
// output (primaries, macbethcal files) in pcond_color.cpp.
#pragma once

#include <array>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "util/options.h"

namespace rp {

struct PcondOptions {
    bool acuity = false;        // -a: defocus dark regions
    bool veil = false;          // -v: veiling glare from bright regions
    bool sensitivity = false;   // -s: human contrast sensitivity sets the mapping
    bool color = false;         // -c: mesopic/scotopic colour loss
    bool centerWeight = false;  // -w: centre-weighted histogram
    bool linear = false;        // -l (and -e): linear response
    bool preHistogram = false;  // -I: histogram from standard input
    double fixationShare = 0;   // -i: share of the histogram from fixations on stdin
    double exposure = 0;        // -e: scale factor (0: automatic)
    double displayMax = 100;    // -u Ldmax: display luminance of (1,1,1), cd/m^2
    double displayRange = 100;  // -d Lddyn: display max / min luminance
    std::optional<std::array<float, 8>> primaries;  // -p: output device chromaticities
    std::string macbethFile;                        // -f: macbethcal output
    std::string colorWarpFile;                      // -m: colour warp map (not supported)
    std::string mapFile;                            // -x: the final mapping, as text
    std::string inputFile;
    std::string outputFile;  // "": standard output

    bool fixations() const { return fixationShare > 1e-6; }
};

// pcond's option table over `opt`; its -defaults text lists RADIANCE's defaults.
OptionTable pcondTable(PcondOptions& opt);
// Options, then the input picture and an optional output picture. Throws InputError
// with RADIANCE's usage line for anything else (unknown option, no input, -i with -I,
// more than one of -p, -f and -m).
PcondOptions parsePcondArgs(std::vector<std::string>& args);

// Conditions the picture read from `in` (named `what` in errors) and writes it to `out`
// in the input's scanline order. `history` is the header's command line (RADIANCE
// writes every argument, files too). `side` is read for -I (histogram) and -i
// (fixation points); `mapOut`, if given, receives the -x mapping. Throws InputError.
void runPcond(std::istream& in, const std::string& what, const PcondOptions& opt,
              const std::string& history, std::ostream& out, std::istream* side = nullptr,
              std::ostream* mapOut = nullptr);

}  // namespace rp
