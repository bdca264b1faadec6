// pcomb: RADIANCE's picture combiner. Each output pixel is ro, go, bo (or lo, a grey
// value) of .cal definitions given with -e and -f, evaluated by our calc module with the
// inputs' pixels as ri(n) gi(n) bi(n) li(n) (n counts from 1; 0 gives the number of
// inputs; optional x and y offsets reach neighbouring pixels, y up), the constant
// functions re ge be le (exposures) and pa (pixel aspect), the constants nfiles, xmax,
// ymax, xres, yres, WE and the variables x and y (the output pixel, y from the bottom).
// Without definitions each channel is the sum of the inputs. Inputs are scaled as read by
// their -s and -c factors; -o divides out their EXPOSURE and COLORCORR. Negative results
// are written as zero. Missing next to RADIANCE: '!command' inputs and the view
// functions Ox Oy Oz Dx Dy Dz T S.
//   pcomb [-h][-w][-x xres][-y yres][-e expr][-f file] [ [-o][-s f][-c r g b] input .. ]
#pragma once

#include <array>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "image/picture.h"
#include "util/options.h"

namespace rp {

struct PcombInput {
    std::string name;                     // a file, or "-" for the standard input
    std::array<double, 3> coef{1, 1, 1};  // -s and -c factors
    bool original = false;                // -o: undo EXPOSURE and COLORCORR
};

struct PcombOptions {
    bool echoHeader = true;  // -h toggles: the inputs' header lines go into ours
    bool warnings = true;    // -w toggles
    // -e text, -f file, -x and -y expressions in command-line order ('e', 'f', 'x', 'y').
    std::vector<std::pair<char, std::string>> sources;
    std::vector<PcombInput> inputs;
};

// The options before the inputs (-h -w -x -y -e -f).
OptionTable pcombTable(PcombOptions& o);
// All arguments (without the program name). Throws InputError for bad options.
PcombOptions parsePcombArgs(const std::vector<std::string>& args);

// One input as read: its picture and what the command line said about it.
struct PcombPicture {
    std::string name;  // for the header and errors ("<stdin>" for -)
    PcombInput input;
    Picture picture;
};

// Combines `inputs` (all of one size; none needs -x and -y) into the output picture,
// whose header is CAPDATE/GMT (from `now`), each input's name and indented header lines
// (unless -h), `commandLine` and the first input's view. `searchPath` finds -f files.
// Throws InputError (a size mismatch, a bad resolution, an unknown file or a .cal error).
Picture runPcomb(std::vector<PcombPicture>& inputs, const PcombOptions& o,
                 const std::string& commandLine, std::time_t now,
                 const std::vector<std::string>& searchPath);

}  // namespace rp
