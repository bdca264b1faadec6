// rpict's picture loop: view rays through jittered pixel positions, RADIANCE's adaptive
// image sampling (trace a sparse grid, interpolate where neighbours agree, trace where
// they do not), in parallel, and the picture's header. The ray tracing itself is
// injected (a PixelTracer per worker thread) so the loop is tested without a scene;
// options live in rpict_options.h.
#pragma once

#include <cstdint>
#include <ctime>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "image/picture.h"
#include "image/view.h"
#include "render/rpict_options.h"
#include "util/cluster.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::render {

// Traces one primary ray (unit `dir`) and returns its radiance; stores the distance to
// the first hit in *distance (the tracer's "miss" distance when nothing is hit).
// `index` = row * xres + column (row 0 at the top), so results never depend on threads.
// `maxDistance`: the view's aft clipping distance along this ray (-va; HUGE_VAL if none).
using PixelTracer = std::function<Color(const Vec3& org, const Vec3& dir, uint64_t index,
                                        double maxDistance, double* distance)>;
// Called once per worker thread (serialised); each tracer is used by one thread only.
using PixelTracerFactory = std::function<PixelTracer()>;

struct RenderProgress {
    double percentDone = 0;  // scanlines finished over all scanlines
    long primaryRays = 0;    // tracer calls so far
    double seconds = 0;      // wall time since the start
};
// Called (serialised, from any thread) at the start, every -t seconds and at the end
// when options.reportInterval > 0; never otherwise.
using ProgressCallback = std::function<void(const RenderProgress&)>;

// "1234 rays, 45.00% after 0.0123 hours" (RADIANCE's report() without host and CPU
// times); the tool prefixes "rpict: ".
std::string formatProgress(long rays, double percentDone, double seconds);

// How rpict aims the primary ray of a pixel: -pj jitter, -pm motion blur towards the
// previous frame's view, -pd aperture (rpict's pixvalue; rvu traces pixels the same way).
struct PixelRayParams {
    double jitter = 0;      // -pj
    double motionBlur = 0;  // -pm (used only with a previous view)
    double aperture = 0;    // -pd
};

// The primary ray of pixel (x, row) (row 0 at the top) of an xres by yres picture of
// `rays`' view, jittered by the pixel's own random stream so that it never depends on
// the order pixels are traced in; `previous` (may be null): the previous frame's view
// for -pm. nullopt where nothing is traced: outside a fisheye's circle, or a degenerate
// blurred direction.
std::optional<ViewRays::Ray> pixelRay(const ViewRays& rays, const ViewRays* previous,
                                      const PixelRayParams& params, int x, int row, int xres,
                                      int yres);

// Traces pixel (x, row) as rpict does: its value and the distance to the first hit in
// *depth; black with depth 0 where pixelRay gives no ray. Returns whether a ray was traced.
bool tracePixel(PixelTracer& tracer, const ViewRays& rays, const ViewRays* previous,
                const PixelRayParams& params, int x, int row, int xres, int yres, Pixel& value,
                float& depth);

// RADIANCE's bigdiff: some colour component of a and b differs by more than
// `threshold` times the other's value (-pt; rpict and rvu sample where it is true).
bool bigDiff(const Pixel& a, const Pixel& b, double threshold);

// The largest -ps RADIANCE allows (MAXDIV); larger values are reduced with a warning.
constexpr int kMaxSampleSpacing = 16;

// Work done on rows [begin, end) of the picture once their pixels are final and before
// they are handed over: rpict's bitty sources (source_draw.h). `depth`: null without -z.
using RowsPass =
    std::function<void(Picture& picture, std::vector<float>* depth, int begin, int end)>;

// Where renderPicture starts, what it hands over while it works, the previous view, and
// the ranks that share the work.
struct RenderRows {
    // Rows [0, firstRow) (from the top) were recovered from an interrupted picture
    // (rpict -r): they are not passed to `done`, and in the result they hold only what
    // the restart traced again (black elsewhere).
    int firstRow = 0;
    // Called on the calling thread, top to bottom, each time rows [begin, end) are final
    // (pixels and depths), so that they can be written while the rest is rendered; every
    // row from firstRow on is passed exactly once.
    std::function<void(const Picture&, const std::vector<float>& depth, int begin, int end)> done;
    // Called with each range of rows `done` gets, just before it (on the root only,
    // under MPI), whether or not there is a `done`. A sampled scanline is handed over
    // only when the band below it is filled, so that what `finish` changes never feeds
    // the sampling of other rows.
    RowsPass finish;
    // -pm: the previous frame's view; each pixel's ray is moved towards the one this
    // view would trace by a random part of -pm (RADIANCE's motion blur). Null: none.
    const View* previousView = nullptr;
    // The ranks of an MPI run (null: this process alone). Every rank renders the same
    // picture; each traces every ranks-th sampled scanline and the band above it, all
    // ranks share the sampled scanlines, and the root gets the bands: its picture (the
    // only one complete, and the only one `done` is called with in full) is the same as
    // one process's.
    Cluster* cluster = nullptr;
};

// Renders the picture: size from pictureSize(options), header lines viewHeaderLines().
// Pixels outside a fisheye's circle are black with depth 0 and are not traced. With
// `depth` non-null it receives one distance per pixel (top row first) and, as RADIANCE
// does with -z, depth differences also stop interpolation. Rays go through a disk of
// diameter -pd when it is positive (ViewRays::jitterAperture). Uses
// options.render.threads worker threads; pixels never depend on their number, nor on
// `rows.firstRow` (a recovered picture is finished exactly as the uninterrupted run
// would have done it, given a deterministic tracer). Throws InputError for an invalid
// view (ViewRays' messages).
Picture renderPicture(const RpictOptions& options, const PixelTracerFactory& factory,
                      const ProgressCallback& progress = {}, std::vector<float>* depth = nullptr,
                      const RenderRows& rows = {});

// The header lines the picture's view adds: VIEW= and, when the pixel aspect is not
// within 1 % of square, PIXASPECT= (RADIANCE's rpict).
std::vector<std::string> viewHeaderLines(const RpictOptions& options);

// Completes an rpict header as RADIANCE's rpict writes it: `commandLine` and
// "SOFTWARE= radphoton ..." before the lines renderPicture added, "CAPDATE=" (local time)
// and "GMT=" of `now` after them. writePicture then adds FORMAT=.
void addRpictHeader(Picture& picture, const std::string& commandLine, std::time_t now);

}  // namespace rp::render
