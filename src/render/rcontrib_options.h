// rcontrib's command line (RADIANCE rcmain.c, rcontrib.1): modifiers to track with the
// output, bin expression, bin count and parameters in effect where each -m/-M stands,
// the .cal definitions (-e, -f) in order, and the rtrace-like options. The common render
// options are parsed by render_options.h with rcontrib's defaults and overrides.
#pragma once

#include <string>
#include <vector>

#include "pmap/contrib_bins.h"
#include "render/render_options.h"

namespace rp::render {

using pmap::CalcDefinition;
using pmap::ContribModifier;
using pmap::isConstantBin;

struct RcontribOptions {
    RenderOptions render;  // rcontrib's defaults; see rcontribDefaults()
    std::vector<ContribModifier> modifiers;
    std::vector<CalcDefinition> definitions;
    bool contributions = false;  // -V: contributions (+) or coefficients (-)
    int accumulate = 1;          // -c: input rays per record; 0 = one record at the end
    int xres = 0, yres = 0;      // -x -y
    bool force = false;          // -fo: overwrite existing outputs
    bool recover = false;        // -r: continue existing outputs
    bool header = true;          // -h
    char inputFormat = 'a';      // -f[io]
    char outputFormat = 'a';
    bool immediateIrradiance = false;  // -I
    bool limitDistance = false;        // -ld
    int reportSeconds = 0;             // -t
    bool printDefaults = false;        // -defaults / -help
    bool printVersion = false;         // -version
    std::string sceneFile;
    std::vector<std::string> args;  // after @file/$EVAR expansion, argv[0] first
    size_t optionCount = 0;         // args[0..optionCount) are program and options
    // The command line as given (@file unexpanded), for output headers: RADIANCE prints
    // it without its last word, the octree.
    std::vector<std::string> commandWords;
};

// RADIANCE compat (rcontrib.c globals, rcmain.c override_options): -ab 1, -ad 350,
// -dt 0, -dc .75, -dj .9, -dr 3, -st .02, -u+, and neither irradiance cache (-aa 0) nor
// ambient super-samples (-as 0), which contribution coefficients cannot pass through.
RcontribOptions rcontribDefaults();

// Parses argv (argv[0] the program), expanding @file and $EVAR at option positions.
// -bn takes a number or a name defined by an earlier -e/-f (`evalCount` evaluates it with
// the definitions given so far; null: numbers only). Throws InputError with RADIANCE's
// messages: "missing required modifier argument", "duplicate modifier 'x'", "cannot
// track 'void' modifier", "unspecified or illegal bin count for modifier 'x'", "illegal
// non-zero constant for bin (e)", "cannot find modifier file 'f'", unknown options,
// "missing octree argument". -aa, -as and -dt are overridden after parsing, as RADIANCE's.
using pmap::BinCountEval;
RcontribOptions parseRcontribArgs(std::vector<std::string> args, BinCountEval evalCount = nullptr);

// What `rcontrib -defaults` prints (rcmain.c printdefaults, then the common options).
std::string formatRcontribDefaults(const RcontribOptions& opt);

}  // namespace rp::render
