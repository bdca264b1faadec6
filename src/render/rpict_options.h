// rpict's command line: its own options (-x -y -p* -t -o -z, view options) on top of the
// shared render options (render_options.h), rpict's defaults (which differ from
// rtrace's), -defaults text, and the picture size rule (RADIANCE's normaspect). The
// picture loop itself lives in rpict.h.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "image/view.h"
#include "render/render_options.h"

namespace rp::render {

// RADIANCE 5.4 rpict.c's defaults for the shared options, where they differ from
// rtrace's: -dt .05 -ds .25 -dr 1 -lr 7 -lw 1e-3 -aa .2 -ar 64 -ad 512 -as 128.
RenderOptions rpictRenderDefaults();

struct RpictOptions {
    RenderOptions render = rpictRenderDefaults();
    View view;                      // -vt -vp ... -vf (rpict's STDVIEW defaults)
    int xres = 512;                 // -x: maximum picture width
    int yres = 512;                 // -y: maximum picture height
    double pixelAspect = 1;         // -pa: pixel height over width; 0 keeps -x and -y
    double pixelJitter = 0.67;      // -pj: 0 samples pixel centres, 1 anywhere in the pixel
    int sampleSpacing = 4;          // -ps: adaptive sampling spacing in pixels (1 = every pixel)
    double sampleThreshold = 0.05;  // -pt: relative difference above which pixels are traced
    double motionBlur = 0;          // -pm: blur between the previous and this frame (-S)
    double apertureBlur = 0;        // -pd: depth-of-field aperture diameter (world units)
    int reportInterval = 0;         // -t: seconds between progress reports (0 = none)
    int sequenceStart = 0;          // -S: > 0 renders one frame per view line on input
    std::string outputFile;         // -o: picture file; with -S may hold a printf %d field
    std::string zFile;              // -z: depth file (raw floats, one per pixel; %d as -o)
    std::string recoverFile;        // -r / -ro: partial picture to continue; with -S a frame number
};

// A parsed rpict command: options, then the scene files.
struct RpictCommand {
    RpictOptions options;
    std::vector<std::string> sceneFiles;
    bool printDefaults = false;  // -defaults / -help: print and exit
    bool printVersion = false;   // -version
};

// Parses rpict's arguments (without the program name); @file and $EVAR words at option
// positions are expanded (command_args.h). As
// RADIANCE's rpmain, options come first (shared render options, then view options, then
// rpict's own) and the first word not starting with '-' starts the scene files. Throws
// InputError for an unknown option ("unknown option '-q'"), a missing or bad value, an
// option after the scene files, and RADIANCE features not supported yet (-P, -PP).
// -ro file is -r file -o file, as RADIANCE's. A missing scene is not an error here (the
// tool decides).
// `defaults`: the options before parsing (another program's defaults, e.g. rvu's);
// `toolOption` (may be empty): tried before rpict's own options, for a program that
// shares rpict's command line (rvu): consumes args[i] and its values, advancing i past
// them, and returns true, or returns false to leave args[i] to rpict.
using ToolOptionParser = std::function<bool(const std::vector<std::string>& args, size_t& i)>;
RpictCommand parseRpictCommand(std::vector<std::string> args,
                               const RpictOptions& defaults = RpictOptions{},
                               const ToolOptionParser& toolOption = {});

// The lines RADIANCE's `rpict -defaults` prints (view, picture, then the render options
// of formatRenderDefaults), reflecting `opt`.
std::string formatRpictDefaults(const RpictOptions& opt);

// Height over width of the view's image plane (RADIANCE's viewaspect: the square root of
// vn2/hn2 from setview). The view must be valid (ViewRays accepts it).
double viewAspect(const View& view);

struct PictureSize {
    int xres = 0;
    int yres = 0;
    double pixelAspect = 1;  // what goes into PIXASPECT= when it is not about 1
};

// RADIANCE's normaspect: with -pa > 0 the larger side is kept and the other reduced so
// that pixels have that aspect for this view; with -pa 0 the resolution stays and the
// pixel aspect follows from it. Never returns a side below 1.
PictureSize pictureSize(const RpictOptions& opt);

}  // namespace rp::render
