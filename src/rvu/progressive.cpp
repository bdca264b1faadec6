// rvu's progressive refinement (see progressive.h).
//
// RADIANCE compat (rview.c): rvu keeps a quadtree whose leaves are painted with one
// sample each, taken at a random place inside the leaf. We keep the blocks of each
// level on a grid instead (the block of side s at (bx, by) is sampled at its top-left
// pixel) and trace that pixel through rpict's own jittered ray: a refined picture is then
// rpict's picture, which is what makes rvu a trustworthy preview of a long rpict run.
#include "rvu/progressive.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <mutex>

#include "util/error.h"

namespace rp::rvu {

struct ProgressiveImage::Tracers {
    tbb::enumerable_thread_specific<render::PixelTracer> perThread;
    std::mutex factoryMutex;
};

namespace {

// The first level's block side: the largest power of two that leaves at least 8 blocks
// across the larger side, so that the first picture comes after a few dozen rays.
int coarsestStep(int width, int height) {
    int s = 1;
    while (s * 2 * 8 <= std::max(width, height)) s *= 2;
    return s;
}

int blocks(int size, int step) { return (size + step - 1) / step; }

}  // namespace

ProgressiveImage::ProgressiveImage(const View& view, int width, int height,
                                   const render::PixelRayParams& rays, int sampleSpacing,
                                   double sampleThreshold)
    : rays_(view),
      width_(width),
      height_(height),
      rayParams_(rays),
      spacing_(std::max(1, sampleSpacing)),
      threshold_(sampleThreshold),
      pixels_(size_t(width) * size_t(height), Pixel{0, 0, 0}),
      traced_(pixels_.size(), 0),
      frame_{0, 0, width, height},
      coarsest_(coarsestStep(width, height)),
      step_(coarsest_),
      tracers_(std::make_unique<Tracers>()) {
    RP_CHECK(width > 0 && height > 0);
    startLevel();
}

ProgressiveImage::~ProgressiveImage() = default;

bool ProgressiveImage::sampling() const {
    // RADIANCE compat (rview.c rview): blocks are refined everywhere while their parents
    // are larger than -ps, and only where neighbours differ after that.
    return step_ > 0 && step_ < coarsest_ && 2 * step_ <= spacing_;
}

void ProgressiveImage::setFrame(const PixelRect& frame) {
    frame_.x0 = std::clamp(frame.x0, 0, width_);
    frame_.x1 = std::clamp(frame.x1, frame_.x0, width_);
    frame_.row0 = std::clamp(frame.row0, 0, height_);
    frame_.row1 = std::clamp(frame.row1, frame_.row0, height_);
    step_ = coarsest_;
    startLevel();
}

void ProgressiveImage::setSampling(int sampleSpacing, double sampleThreshold) {
    spacing_ = std::max(1, sampleSpacing);
    threshold_ = sampleThreshold;
    step_ = coarsest_;
    startLevel();
}

void ProgressiveImage::dropTracers() { tracers_->perThread.clear(); }

void ProgressiveImage::startLevel() {
    nextRow_ = 0;
    marked_.clear();
    if (step_ > 0 && sampling()) markDifferences();
}

void ProgressiveImage::markDifferences() {
    // RADIANCE compat (rview.c rsample): each block is compared with the blocks to its
    // right and below, by the values they show now; both of a differing pair are traced.
    const int s = step_, nx = blocks(width_, s), ny = blocks(height_, s);
    marked_.assign(size_t(nx) * size_t(ny), 0);
    for (int by = 0; by < ny; ++by)
        for (int bx = 0; bx < nx; ++bx) {
            const Pixel& v = pixels_[index(bx * s, by * s)];
            auto compare = [&](int ox, int oy) {
                if (ox >= nx || oy >= ny) return;
                if (!render::bigDiff(v, pixels_[index(ox * s, oy * s)], threshold_)) return;
                marked_[size_t(by) * size_t(nx) + size_t(bx)] = 1;
                marked_[size_t(oy) * size_t(nx) + size_t(ox)] = 1;
            };
            compare(bx + 1, by);
            compare(bx, by + 1);
        }
}

void ProgressiveImage::traceBlock(render::PixelTracer& tracer, int bx, int by) {
    const int s = step_, x = bx * s, row = by * s;
    const size_t i = index(x, row);
    if (traced_[i]) return;  // traced at a coarser level: its block shows it already
    float depth = 0;         // rvu shows no depths
    render::tracePixel(tracer, rays_, nullptr, rayParams_, x, row, width_, height_, pixels_[i],
                       depth);
    traced_[i] = 1;
    // Paint the block's untraced pixels; the traced ones inside it are only its corner.
    const int x1 = std::min(width_, x + s), row1 = std::min(height_, row + s);
    for (int r = row; r < row1; ++r)
        for (int c = x; c < x1; ++c) {
            const size_t j = index(c, r);
            if (!traced_[j]) pixels_[j] = pixels_[i];
        }
}

bool ProgressiveImage::refineLevel(int threads, const render::PixelTracerFactory& factory,
                                   const std::function<bool()>& interrupted,
                                   const std::function<void()>& progress) {
    if (done()) return true;
    const int s = step_, nx = blocks(width_, s);
    // The blocks inside the frame.
    const int bx0 = frame_.x0 / s, bx1 = blocks(frame_.x1, s);
    const int by0 = frame_.row0 / s, by1 = blocks(frame_.row1, s);
    // Chunks of about a tenth of a second: short enough to answer a command quickly,
    // long enough that threads seldom wait for each other at a chunk's end.
    const int across = std::max(1, bx1 - bx0);
    int chunkRows = std::max(1, (64 * std::max(1, threads)) / across);
    auto tracerHere = [&]() -> render::PixelTracer& {
        render::PixelTracer& t = tracers_->perThread.local();
        if (!t) {
            std::lock_guard<std::mutex> lock(tracers_->factoryMutex);
            t = factory();
            RP_CHECK(bool(t));
        }
        return t;
    };
    tbb::task_arena arena(std::max(1, threads));
    auto traceRange = [&](const tbb::blocked_range<long>& range) {
        render::PixelTracer& tracer = tracerHere();
        for (long k = range.begin(); k < range.end(); ++k) {
            const int by = int(k / across), bx = bx0 + int(k % across);
            if (!marked_.empty() && !marked_[size_t(by) * size_t(nx) + size_t(bx)]) continue;
            traceBlock(tracer, bx, by);
        }
    };
    nextRow_ = std::max(nextRow_, by0);
    while (nextRow_ < by1) {
        if (interrupted && interrupted()) return false;
        const int r0 = nextRow_, r1 = std::min(by1, r0 + chunkRows);
        const auto start = std::chrono::steady_clock::now();
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<long>(long(r0) * across, long(r1) * across),
                              traceRange);
        });
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (seconds < 0.05)
            chunkRows *= 2;
        else if (seconds > 0.2 && chunkRows > 1)
            chunkRows /= 2;
        nextRow_ = r1;
        if (progress) progress();
    }
    tracedCount_ = long(std::count(traced_.begin(), traced_.end(), uint8_t(1)));
    step_ = s > 1 ? s / 2 : 0;
    startLevel();
    return true;
}

}  // namespace rp::rvu
