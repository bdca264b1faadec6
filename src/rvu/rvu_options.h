// rvu's command line (RADIANCE rvu.1, rvmain.c): rpict's view and rendering options with
// rvu's defaults, plus -o dev (the display: "web", optionally "web:PORT"), -b (grey),
// -pe exposure, -n threads, -devices and -defaults. rpict's output options (-o file, -z,
// -r, -S, -t, -pd, -pm, -P) have no meaning for an interactive viewer and are refused, as
// RADIANCE's rvu refuses them. -x and -y give the largest picture (RADIANCE: the
// window), 512 by default; the view's aspect decides the other side.
#pragma once

#include <string>
#include <vector>

#include "render/rpict_options.h"

namespace rp::rvu {

struct RvuOptions {
    render::RpictOptions picture;  // view, -x/-y, -pj/-ps/-pt, rendering options
    double exposure = 1;           // -pe (a multiplier, or f-stops with a sign)
    bool greyscale = false;        // -b
    std::string device = "web";    // -o
    int port = 0;                  // -o web:PORT (0: any free port)
    std::string radFile;           // -R: the rad file of the L and V commands (rad -o)
};

// RADIANCE 5.4 rvmain.c's defaults: -ps 8 -pt .15, and for rendering -dt .1 -dc .25
// -dr 0 -dp 128 -ds 0 -st .3 -ss 1 -lr 6 -lw .01 -aa .3 -ar 32 -ad 256 -as 64.
RvuOptions rvuDefaults();

struct RvuCommand {
    RvuOptions options;
    std::vector<std::string> sceneFiles;
    bool printDefaults = false;
    bool printDevices = false;
    bool printVersion = false;
};

// Parses rvu's arguments (without the program name); @file and $EVAR words are expanded
// as rpict's. Throws InputError for an unknown or refused option, a bad value, or an
// unknown device.
RvuCommand parseRvuCommand(std::vector<std::string> args);

// `rvu -defaults`: the view, picture and rendering options in rpict's layout, with rvu's
// own (-pe, -b, -o) first.
std::string formatRvuDefaults(const RvuOptions& options);
// `rvu -devices`.
std::string formatRvuDevices();

}  // namespace rp::rvu
