// mkillum, "compute illum sources for a RADIANCE scene" (RADIANCE mkillum.1): its command
// line ([-n N] [render options] octree [< file ..]), -defaults, and the run that loads
// the octree's scene into our renderer and passes the inputs through IllumFilter
// (illum_filter.h). The tool's main (tools/mkillum.cpp) only reports errors.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "illum/illum_settings.h"
#include "render/render_options.h"

namespace rp::illum {

struct MkillumOptions {
    render::RenderOptions render;     // with mkillum's defaults (mkillumDefaults)
    std::string octree;               // the scene the rays are traced in
    std::vector<std::string> inputs;  // the files after "<"; none: standard input
    std::vector<std::string> args;    // after @file/$EVAR expansion, program first
    size_t headerWords = 0;           // args[0..headerWords): program, options, octree
    bool printDefaults = false;       // -defaults: print and exit
    bool printVersion = false;        // -version
};

// RADIANCE compat (mkillum.c main): rtrace's render options with -dj .5, -dr 3, -ab 2
// and uncorrelated sampling.
MkillumOptions mkillumDefaults();

// Parses argv (program first). The options are the renderers' common ones
// (render_options.h: -n and -w included, not rtrace's ray input/output options, nor -e);
// then the octree; then either nothing or "<" and one or more files. Throws InputError:
// unknown options and bad values as the option table words them, "missing octree
// argument", and "use '< file1 file2 ..' for multiple inputs".
MkillumOptions parseMkillumArgs(std::vector<std::string> args);

// What `mkillum -defaults` prints: the variables' defaults, then the render options.
std::string formatMkillumDefaults(const MkillumOptions& o);

// The run: loads the octree, builds the renderer (irradiance mode -i is always off, as
// in RADIANCE), and converts each input, or `in` without inputs, writing to `out` (or
// where o= sends it) and the data files into the current folder. Throws InputError for
// missing files and bad input (with file and line).
void runMkillum(const MkillumOptions& o, std::istream& in, std::ostream& out);

}  // namespace rp::illum
