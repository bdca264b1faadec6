// mkillum's variables (RADIANCE mkillum.1, VARIABLES): what the `#@mkillum` comment
// lines of its input set, the parser of one such line and their -defaults text. What
// the variables do to surfaces lives in illum_sample.h and illum_output.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "util/error.h"

namespace rp::illum {

// Which surfaces become secondary sources: a, n, i=mod, e=mod.
enum class Selection { kAll, kNone, kOnly, kAllBut };

// c=n, c=a, c=d: no colour, the average colour, a colour distribution.
enum class ColourMode { kNone, kAverage, kDistribution };

struct IllumSettings {
    std::string material = "illum_mat";  // m=: the new modifier, its distribution's name
    std::string dataFile = "illum";      // f= (or m=): data file name before number/.dat
    int dataFileNumber = 0;              // the number after it (0: none)
    bool clobber = false;                // f= given: overwrite data files
    bool light = false;                  // l+: light instead of illum
    ColourMode colour = ColourMode::kNone;
    int density = 48;          // d=: directions per projected steradian (0: diffuse)
    int samples = 32;          // s=: rays per direction
    double minBrightness = 0;  // b=: surfaces darker on average stay as they are
    Selection selection = Selection::kAll;
    std::string selectModifier;  // the modifier of i= or e=

    // Whether a surface with modifier `modifier` is to be converted (surfaces only).
    bool selects(const std::string& modifier) const;
};

// What one `#@mkillum` line asks for besides settings.
struct OptionLine {
    bool processed = false;                 // "!": the input is mkillum output already
    std::optional<std::string> outputFile;  // o=file: what follows goes there
};

// Whether `line` (a whole comment line, '#' first) is addressed to mkillum: "#@mkillum"
// followed by white space or nothing.
bool isOptionLine(std::string_view line);

// Applies the words after "#@mkillum" to `settings` in order. RADIANCE compat
// (mkillum.c xoptions): m= also names the data file unless f= named one; "f=" alone goes
// back to the material's name; "d=" alone changes nothing; a negative b= is 0; "!"
// stops the line. A word that is not one of the variables, or a bad value, is an
// InputError at `loc` naming the word (RADIANCE only warned and skipped it, which left
// the surfaces that followed converted with settings nobody asked for).
OptionLine applyOptionLine(std::string_view line, IllumSettings& settings, const SourceLoc& loc);

// The variables' lines of `mkillum -defaults` (RADIANCE mkillum.c printopts).
std::string formatSettings(const IllumSettings& settings);

}  // namespace rp::illum
