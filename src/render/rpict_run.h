// What rpict does once the scene is loaded (RADIANCE rpict.c rpict()): one picture, or
// with -S one frame per view line on the input; -o files (with a frame-number field)
// that are never clobbered; -r/-ro recovery of an interrupted picture; and the picture
// written scanline by scanline as it is finished, so that an interrupted run leaves a
// picture that -r can finish. The picture loop itself is rpict.h's.
#pragma once

#include <ctime>
#include <functional>
#include <iosfwd>
#include <string>

#include "image/view.h"
#include "render/rpict.h"
#include "render/rpict_options.h"

namespace rp::render {

struct RpictIo {
    std::istream* views = nullptr;  // -S: view lines (RADIANCE reads standard input)
    std::ostream* out = nullptr;    // pictures without -o (standard output)
    std::string commandLine;        // the header's first line
    std::function<std::time_t()> clock = [] { return std::time(nullptr); };
    // Called before each frame of a sequence (rpict -t prints "FRAME n: <view>").
    std::function<void(int frame, const View& view)> frameStarted;
    // The ranks of an MPI run (null: this process alone): one picture (no -S, no -r),
    // traced by all, written by the root.
    Cluster* cluster = nullptr;
    // What each frame (its options, view and size as rendered) does to its finished rows
    // before they are written (RenderRows::finish; rpict's bitty sources). Empty: nothing.
    std::function<RowsPass(const RpictOptions& frame)> finishRows;
};

// Renders as RADIANCE's rpict does with these options:
//  - Each picture's header: commandLine, SOFTWARE=, FRAME= (sequences), VIEW=,
//    PIXASPECT= (not square), CAPDATE=, GMT=, FORMAT=; then the resolution line and the
//    scanlines, written and flushed as they are finished. The z-file (-z) likewise.
//  - -S n (n > 0): frames n, n+1, ... one per line of `views` that carries a view
//    (isViewLine), each applied on top of the previous view; -pm blurs each frame towards
//    the previous view (the first towards the command line's). Without -o the frames
//    follow each other on `out`; -o and -z may hold one printf integer field ("%03d")
//    for the frame number.
//  - -o: the file is created exclusively. An existing file is an error for a single
//    picture; in a sequence that frame is skipped (several processes can share one).
//  - -r file: the view and size come from the file's header (a warning when they cannot,
//    then the command line's), its complete scanlines are copied and rendering goes on
//    from the first missing one; the file is removed afterwards. When it is the -o file
//    (-ro) it is first renamed to a temporary name beside it. With -S and an integer
//    -r n, view lines up to frame n are skipped and frame n is recovered from its -o file.
// Returns the number of pictures written ("no output produced" is warned at 0). Throws
// InputError for RADIANCE's user errors (messages as rpict.c's) and write errors.
int runRpict(const RpictOptions& options, const PixelTracerFactory& factory,
             const ProgressCallback& progress, RpictIo& io);

// The file name for `frame` from an -o/-z pattern: one printf integer field
// (%d, %5d, %05d, %-5d; %% is a percent sign) or none (the pattern itself). Throws
// InputError for any other conversion or more than one field.
std::string frameFileName(const std::string& pattern, int frame);

}  // namespace rp::render
