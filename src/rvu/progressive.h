// rvu's picture, refined coarse to fine (RADIANCE rview.c rview/refine/rsample): the
// first level traces one pixel per large block and paints the block with it; each
// following level halves the blocks. While blocks are larger than -ps every block is
// traced ("refining"); below that only blocks whose value differs by more than -pt from
// a neighbour's ("sampling"), as rvu does. Every pixel is traced at most once, through
// the ray rpict traces for it (render/rpict.h tracePixel), so a picture refined with
// -ps 1 has exactly rpict -ps 1's pixels. Refinement can stop between chunks of work
// and resume where it stopped.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "image/rgbe.h"
#include "image/view.h"
#include "render/rpict.h"

namespace rp::rvu {

// A rectangle of pixels: columns [x0, x1), rows [row0, row1) (row 0 at the top).
struct PixelRect {
    int x0 = 0, row0 = 0, x1 = 0, row1 = 0;
    bool empty() const { return x1 <= x0 || row1 <= row0; }
};

class ProgressiveImage {
public:
    // An untraced (black) picture of the view; `sampleSpacing` (-ps) and
    // `sampleThreshold` (-pt) as rvu's. Throws InputError for an invalid view.
    ProgressiveImage(const View& view, int width, int height, const render::PixelRayParams& rays,
                     int sampleSpacing, double sampleThreshold);
    ~ProgressiveImage();
    ProgressiveImage(const ProgressiveImage&) = delete;
    ProgressiveImage& operator=(const ProgressiveImage&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    const View& view() const { return rays_.view(); }
    // Display values, top row first: each traced pixel's value, every other pixel the
    // value of the traced pixel whose block covers it (black before the first level).
    const std::vector<Pixel>& pixels() const { return pixels_; }
    // Whether pixel (x, row) has been traced.
    bool traced(int x, int row) const { return traced_[index(x, row)] != 0; }
    long tracedCount() const { return tracedCount_; }

    // Side of the blocks the current level paints (1: the last level); 0 when done.
    int blockSize() const { return done() ? 0 : step_; }
    bool done() const { return step_ == 0; }
    // Whether the current level traces every block (rvu's "refining") or only those that
    // differ from a neighbour ("sampling").
    bool sampling() const;

    // rvu's frame: later refinement stays inside `frame` (clipped to the picture) and
    // starts again from the coarsest level there; pixels traced stay traced.
    void setFrame(const PixelRect& frame);
    const PixelRect& frame() const { return frame_; }
    // The pixel-sampling options changed (rvu's set ps / pt): refinement restarts from the
    // coarsest level, keeping what is traced.
    void setSampling(int sampleSpacing, double sampleThreshold);

    // Traces the current level's remaining blocks, a chunk of block rows at a time, with
    // up to `threads` threads and one tracer per thread from `tracers` (made as needed,
    // kept for later calls). Between chunks, returns early when `interrupted()` is true
    // and calls `progress()`. Moves to the next level when this one is finished. Returns
    // whether the level was finished.
    bool refineLevel(int threads, const render::PixelTracerFactory& tracers,
                     const std::function<bool()>& interrupted,
                     const std::function<void()>& progress);
    // Forgets the tracers made so far (their renderer is about to change).
    void dropTracers();

private:
    size_t index(int x, int row) const { return size_t(row) * size_t(width_) + size_t(x); }
    void startLevel();
    void markDifferences();
    void traceBlock(render::PixelTracer& tracer, int bx, int by);

    ViewRays rays_;
    int width_, height_;
    render::PixelRayParams rayParams_;
    int spacing_;
    double threshold_;
    std::vector<Pixel> pixels_;
    std::vector<uint8_t> traced_;
    long tracedCount_ = 0;
    PixelRect frame_;
    int coarsest_;                 // the first level's block side (a power of 2)
    int step_;                     // the current level's block side; 0 when done
    int nextRow_ = 0;              // the next block row of the current level to trace
    std::vector<uint8_t> marked_;  // sampling levels: blocks to trace, by block index
    struct Tracers;
    std::unique_ptr<Tracers> tracers_;
};

}  // namespace rp::rvu
