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
#include "util/options.h"

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

// Adds rpict's options to `t` bound to `opt` (util/options.h): the shared render options,
// the view options, rpict's own, with @file and $EVAR expanded at option positions
// (util/command_args.h) and -defaults in rpict's layout. `toolOptions` (may be empty) adds
// the options of a program that shares rpict's command line (rvu) first, so that they
// replace rpict's of the same name and lead the -defaults text. Errors: "unknown option
// '-q'", missing or bad values, RADIANCE features not supported yet (-P, -PP). -ro file is
// -r file -o file, as RADIANCE's.
void addRpictOptions(OptionTable& t, RpictOptions& opt,
                     const std::function<void(OptionTable&)>& toolOptions = {});

// Parses rpict's arguments (without the program name) with rpict's table: as RADIANCE's
// rpmain, options come first and the first word not starting with '-' starts the scene
// files; an option after them is an InputError. A missing scene is not an error here (the
// tool decides). `defaults`: the options before parsing.
RpictCommand parseRpictCommand(std::vector<std::string> args,
                               const RpictOptions& defaults = RpictOptions{});
// The parsing of parseRpictCommand with a table built by addRpictOptions (bound to the
// options it fills): sets cmd's scene files and -defaults/-version flags.
void finishRpictCommand(const OptionTable& t, std::vector<std::string> args, RpictCommand& cmd);

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
