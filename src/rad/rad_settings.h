// What rad derives from a RIF's variables, as RADIANCE 5.4's rad.c derives it: the options
// of oconv, mkillum and mkpmap, the rendering options from QUALITY, DETAIL, VARIABILITY,
// INDIRECT, PENUMBRAS, ZONE, EXPOSURE, AMBFILE and the photon maps, pfilt's options, and
// the views (named, numbered, or RADIANCE's standard views "X", "xZl", ... around ZONE).
// Option strings are built as RADIANCE builds them: each word group starts with a space,
// numbers use RADIANCE's printf formats, so `rad -n` prints the same commands.
#pragma once

#include <optional>
#include <string>

#include "rad/rif.h"

namespace rp::rad {

// The programs rad runs. A tool variable (oconv, mkillum, mkpmap, rvu, rpict, pfilt) whose
// value starts with a word that is not an option names the program to run instead.
struct Programs {
    std::string oconv = "oconv";
    std::string mkillum = "mkillum";
    std::string mkpmap = "mkpmap";
    std::string rvu = "rvu";
    std::string rpict = "rpict";
    std::string pfilt = "pfilt";
};

// The options of a tool variable (leading space, "" if unset); a leading program name
// goes to `program`.
std::string toolOptions(const RifVars& vars, Var var, std::string& program);
// mkillum's and mkpmap's options: " -n N" with more than one process first.
std::string parallelToolOptions(const RifVars& vars, Var var, int nprocs, std::string& program);

struct RenderSettings {
    std::string render;     // rpict's / rvu's rendering options (leading space)
    std::string picture;    // -ps and -pt, then the rpict (or rvu) variable's options
    bool overture = false;  // an ambient-file overture run is worth making
};
// `cubeSize`: the octree's bounding cube (RADIANCE scales -ar by it). `forRvu`: the
// picture options of the rvu variable instead of rpict's. Throws InputError for a bad
// ZONE or EXPOSURE.
RenderSettings renderSettings(const RifVars& vars, double cubeSize, bool forRvu,
                              Programs& programs);

// RADIANCE's ambval(): the -av value, from EXPOSURE, else from the zone type.
double ambientValue(const RifVars& vars);

// pfilt's options (leading space): exposure (-1 -e), -r .6 (medium) or -m .25 (high),
// then the pfilt variable's.
std::string pfiltOptions(const RifVars& vars, Programs& programs);

// The view options of a view value: a standard view ("X", "xYZ", "Zl", "Xh ..."), or a
// name followed by options ("def -vf inside.vf"), or options alone. nullopt where
// RADIANCE's specview gives none (a bare name).
std::optional<std::string> viewOptions(const RifVars& vars, const std::string& spec);

// RADIANCE's getview(): view n of the RIF (or, with `select` from rad -v, the selected one
// by number, name or options, else a standard view). `name` receives the view's name
// used in picture names ("def", "2", ...). nullopt: no such view.
std::optional<std::string> selectView(const RifVars& vars, const std::string* select, int n,
                                      std::string* name);

// The six zone numbers "xmin xmax ymin ymax zmin zmax" after the zone type; throws
// InputError ("bad value for variable 'ZONE'") unless six numbers follow.
struct Zone {
    char type = 'I';
    double min[3] = {0, 0, 0};
    double max[3] = {0, 0, 0};
};
Zone zoneOf(const RifVars& vars);

}  // namespace rp::rad
