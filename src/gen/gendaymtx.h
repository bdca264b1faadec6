// gendaymtx(1): a Perez sky matrix (one row per Reinhart patch, ground first; one column
// per weather tape time step, or their average) and the -D sun descriptions, as RADIANCE
// 5.4's gendaymtx writes them. Options and the time loop; the tape is read by wea.h, the
// per-step sky is gendaymtx_sky.h's, the patches gendaymtx_patches.h's. Tool main:
// tools/gendaymtx.cpp.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "gen/gendaymtx_sky.h"
#include "gen/wea.h"

namespace rp::gen {

// What goes out as a matrix: a column per time step, one averaged column (-A), or
// nothing (-n, and "-D -").
enum class DaymtxMatrix { PerStep, Average, None };

struct GendaymtxOptions {
    bool verbose = false;  // -v
    bool header = true;    // -h: none
    char format = 'a';     // -oa, -of, -od
    DaymtxMatrix matrix = DaymtxMatrix::PerStep;
    bool sunHoursOnly = false;  // -u
    int subdivisions = 1;       // -m
    double rotationDeg = 0;     // -r, -rz: counter-clockwise about the zenith
    std::string sunFile;        // -D: empty for none, "-" for the standard output
    std::string modifierFile;   // -M
    DaymtxSkyOptions sky;       // -c, -g, -s, -d, -O, -5
    std::string input;          // the weather tape; empty for the standard input
};

// RADIANCE compat (gendaymtx.c main): options apply in order, so "-d -c 1 1 1" has a sky
// again, "-n" (and "-D -") resets -m to 1 and blackens sky and ground, and a later -A
// brings the matrix back. Throws InputError for unknown options, missing or non-numeric
// values, -m below 1, a -5 disk size not above 0 and more than one input file.
GendaymtxOptions parseGendaymtxArgs(const std::vector<std::string>& args);

struct GendaymtxOutputs {
    std::ostream* matrix = nullptr;     // the matrix (header and values)
    std::ostream* suns = nullptr;       // -D
    std::ostream* modifiers = nullptr;  // -M: one "solar<minute>" line per sun
    // Verbose reports and warnings, one line each without the program name.
    std::function<void(const std::string&)> note;
};

// Runs the tape through the sky model and writes the outputs. `args` is the command line
// for the header (args[0] the program name), `tapeName` names the tape in messages.
// Throws InputError naming the tape's line for a negative direct or diffuse value at a
// step with light (RADIANCE reads out of its tables there), and for a tape without time
// steps (left).
void runGendaymtx(const GendaymtxOptions& opt, const WeaTape& tape, const std::string& tapeName,
                  const std::vector<std::string>& args, GendaymtxOutputs& out);

}  // namespace rp::gen
