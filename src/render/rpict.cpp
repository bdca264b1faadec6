// rpict's picture loop and header (see rpict.h).
//
// RADIANCE compat (rpict.c render/fillscanline/fillscanbar/fillsample): samples are laid
// out in RADIANCE's quincunx pattern (every hstep = 1.41*ps pixels along scanlines that
// are ystep = ps/1.41 apart, alternate scanlines offset by half a step). Between two
// samples along a scanline, and then between two sampled scanlines in each column, the
// middle pixel is traced when the ends differ by more than -pt (relative, per colour
// component; also in depth when a z-file is written) and the halves are treated the same
// way; otherwise the pixels between are interpolated linearly.
//
// Not RADIANCE: rpict also remembers where the previous scanline needed subdivision and
// forces sampling there (its "sample density" array), which makes each scanline depend
// on the one before. We leave that out so that scanlines, and then the bands between
// them, can be filled in parallel with results that never depend on the thread count.
#include "render/rpict.h"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <ostream>

#include "image/view.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/version.h"
#include "util/warnings.h"

namespace rp::render {

std::string formatProgress(long rays, double percentDone, double seconds) {
    return fmt::format("{} rays, {:4.2f}% after {:.4f} hours", rays, percentDone, seconds / 3600.0);
}

namespace {

using Clock = std::chrono::steady_clock;

// Serialised, rate-limited progress reports (RADIANCE's -t alarm).
class Progress {
public:
    Progress(const ProgressCallback& cb, int interval, int rows, int done,
             const std::atomic<long>& rays)
        : cb_(cb),
          interval_(interval),
          rows_(rows),
          rays_(rays),
          done_(done),
          start_(Clock::now()),
          last_(start_) {}

    void start() { report(true); }
    void advance(int rows) {
        done_ += rows;
        report(false);
    }
    void finish() { report(true); }

private:
    void report(bool always) {
        if (!cb_ || interval_ <= 0) return;
        std::lock_guard<std::mutex> lock(mutex_);
        auto now = Clock::now();
        if (!always && now - last_ < std::chrono::seconds(interval_)) return;
        last_ = now;
        RenderProgress p;
        p.percentDone = 100.0 * std::min(done_.load(), rows_) / rows_;
        p.primaryRays = rays_.load();
        p.seconds = std::chrono::duration<double>(now - start_).count();
        cb_(p);
    }

    const ProgressCallback& cb_;
    int interval_;
    int rows_;
    const std::atomic<long>& rays_;
    std::atomic<int> done_;
    std::mutex mutex_;
    Clock::time_point start_, last_;
};

struct Sampler {
    ViewRays rays;
    std::optional<ViewRays> previous;  // -pm: the previous frame's view
    int xres, yres;
    PixelRayParams params;
    double threshold;
    bool useDepth;
    std::vector<Pixel>& pixels;
    std::vector<float>& z;
    std::atomic<long>& traced;

    size_t at(int x, int row) const { return size_t(row) * size_t(xres) + size_t(x); }

    void trace(PixelTracer& tracer, int x, int row) {
        const size_t i = at(x, row);
        if (tracePixel(tracer, rays, previous ? &*previous : nullptr, params, x, row, xres, yres,
                       pixels[i], z[i]))
            traced.fetch_add(1, std::memory_order_relaxed);
    }

    bool differ(size_t a, size_t b) const {
        if (useDepth && 2.0 * std::fabs(double(z[a]) - z[b]) > threshold * (double(z[a]) + z[b]))
            return true;
        return bigDiff(pixels[a], pixels[b], threshold);
    }

    // Fills the pixels strictly between positions k0 and k1 of a line whose ends are
    // known; `pos(k)` gives the pixel index and `trace(k)` traces position k.
    template <class Pos, class Trace>
    void fill(int k0, int k1, const Pos& pos, const Trace& traceAt) {
        if (k1 - k0 <= 1) return;
        const size_t a = pos(k0), b = pos(k1);
        if (differ(a, b)) {
            const int m = k0 + (k1 - k0) / 2;
            traceAt(m);
            fill(k0, m, pos, traceAt);
            fill(m, k1, pos, traceAt);
            return;
        }
        const int len = k1 - k0;
        for (int k = k0 + 1; k < k1; ++k) {
            // (b - a) * k / len keeps values that are linear in position exact.
            const size_t i = pos(k);
            for (int c = 0; c < 3; ++c)
                pixels[i][c] =
                    float(pixels[a][c] + (double(pixels[b][c]) - pixels[a][c]) * (k - k0) / len);
            z[i] = float(z[a] + (double(z[b]) - z[a]) * (k - k0) / len);
        }
    }

    // A sampled scanline: pixel 0, then every hstep, the first step halved on odd
    // sampled scanlines (counted from the top), and the last pixel.
    void sampledRow(PixelTracer& tracer, int row, int count, int hstep) {
        std::vector<int> xs{0};
        const int first = std::max(1, count % 2 == 0 ? hstep : hstep / 2);
        for (int x = first;; x += hstep) {
            if (x >= xres - 1) {
                if (xs.back() != xres - 1) xs.push_back(xres - 1);
                break;
            }
            xs.push_back(x);
        }
        auto pos = [&](int x) { return at(x, row); };
        auto traceAt = [&](int x) { trace(tracer, x, row); };
        trace(tracer, 0, row);
        for (size_t j = 1; j < xs.size(); ++j) {
            traceAt(xs[j]);
            fill(xs[j - 1], xs[j], pos, traceAt);
        }
    }

    // The scanlines strictly between two sampled ones, column by column.
    void band(PixelTracer& tracer, int row0, int row1) {
        for (int x = 0; x < xres; ++x) {
            auto pos = [&](int row) { return at(x, row); };
            auto traceAt = [&](int row) { trace(tracer, x, row); };
            fill(row0, row1, pos, traceAt);
        }
    }
};

// The sampled scanlines (from the top: 0, ystep, 2*ystep, ... and always the last) and
// the step between samples along them, for -ps `spacing` (RADIANCE's quincunx steps).
struct SampleGrid {
    int hstep = 1;
    std::vector<int> rows;
};
SampleGrid sampleGrid(int spacing, int yres) {
    int ps = spacing;
    if (ps < 1) {
        ps = 1;
    } else if (ps > kMaxSampleSpacing) {
        warn(fmt::format("pixel sampling reduced from {} to {}", ps, kMaxSampleSpacing));
        ps = kMaxSampleSpacing;
    }
    // RADIANCE compat (rpict.c render).
    SampleGrid g;
    g.hstep = (ps * 140 + 49) / 99;
    const int ystep = std::max(1, (ps * 99 + 70) / 140);
    for (int r = 0; r < yres - 1; r += ystep) g.rows.push_back(r);
    g.rows.push_back(yres - 1);
    if (g.rows.size() > 1 && g.rows[g.rows.size() - 2] == g.rows.back()) g.rows.pop_back();
    return g;
}

// The rows of the band above sampled row k that are not recovered (progress counts).
int bandRowsAfter(const std::vector<int>& rows, size_t k, int firstRow) {
    return std::max(0, rows[k] - std::max(rows[k - 1] + 1, firstRow));
}

// Rows [r0, r1) of items [k0, k1) (rowsOf(k, r0, r1)) from the rank that traced each
// (k % ranks) to every rank, or with `toRoot` to the root only: pixels and depths.
template <class RowsOf>
void shareRows(Cluster& cluster, Picture& pic, std::vector<float>& z, size_t k0, size_t k1,
               size_t ranks, const RowsOf& rowsOf, bool toRoot) {
    const size_t width = size_t(pic.width);
    auto span = [&](size_t k) {
        int r0 = 0, r1 = 0;
        rowsOf(k, r0, r1);
        return std::make_pair(size_t(r0) * width, size_t(std::max(r0, r1)) * width);
    };
    ByteWriter w;
    for (size_t k = k0; k < k1; ++k) {
        if (k % ranks != size_t(cluster.rank())) continue;
        const auto [i0, i1] = span(k);
        w.putVector(
            std::vector<Pixel>(pic.pixels.begin() + long(i0), pic.pixels.begin() + long(i1)));
        w.putVector(std::vector<float>(z.begin() + long(i0), z.begin() + long(i1)));
    }
    std::vector<size_t> sizes;
    const Bytes all =
        toRoot ? cluster.gather(w.bytes(), sizes) : cluster.allGather(w.bytes(), sizes);
    if (toRoot && !cluster.isRoot()) return;
    size_t at = 0;
    std::vector<Pixel> px;
    std::vector<float> depth;
    for (size_t r = 0; r < ranks; ++r) {
        ByteReader rd(std::span<const std::byte>(all).subspan(at, sizes[r]));
        at += sizes[r];
        for (size_t k = k0; k < k1; ++k) {
            if (k % ranks != r) continue;
            rd.getVector(px);
            rd.getVector(depth);
            if (r == size_t(cluster.rank())) continue;
            const auto [i0, i1] = span(k);
            RP_CHECK(px.size() == i1 - i0 && depth.size() == i1 - i0);
            std::copy(px.begin(), px.end(), pic.pixels.begin() + long(i0));
            std::copy(depth.begin(), depth.end(), z.begin() + long(i0));
        }
        RP_CHECK(rd.done());
    }
}

}  // namespace

bool bigDiff(const Pixel& a, const Pixel& b, double md) {
    for (int i = 0; i < 3; ++i)
        if (a[i] - b[i] > md * b[i] || b[i] - a[i] > md * a[i]) return true;
    return false;
}

std::optional<ViewRays::Ray> pixelRay(const ViewRays& rays, const ViewRays* previous,
                                      const PixelRayParams& params, int x, int row, int xres,
                                      int yres) {
    const uint64_t index = uint64_t(row) * uint64_t(xres) + uint64_t(x);
    // RADIANCE compat (pixjitter): .5 + pj*(.5 - random) in each direction.
    Rng rng(0, RngDomain::Pixel, index);
    const double jx = 0.5 + params.jitter * (0.5 - rng.uniform());
    const double jy = 0.5 + params.jitter * (0.5 - rng.uniform());
    // Image y runs from the bottom; picture rows from the top.
    const double hpos = (x + jx) / xres, vpos = (yres - 1 - row + jy) / yres;
    auto ray = rays.ray(hpos, vpos);
    if (!ray) return ray;  // outside a fisheye's circle
    // RADIANCE compat (rpict.c pixvalue): motion blur moves origin, direction and aft
    // distance linearly towards the previous view's ray by d in [-pm/2, pm/2).
    const double dm = params.motionBlur * (0.5 - rng.uniform());
    if (previous && params.motionBlur > 1e-6) {
        if (auto last = previous->ray(hpos, vpos)) {
            ray->origin = (1 - dm) * ray->origin + dm * last->origin;
            ray->maxDistance = (1 - dm) * ray->maxDistance + dm * last->maxDistance;
            const Vec3 d = (1 - dm) * ray->direction + dm * last->direction;
            if (length(d) == 0) return std::nullopt;
            ray->direction = normalize(d);
        }
    }
    const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
    if (!rays.jitterAperture(*ray, params.aperture, u1, u2, u3)) return std::nullopt;
    return ray;
}

bool tracePixel(PixelTracer& tracer, const ViewRays& rays, const ViewRays* previous,
                const PixelRayParams& params, int x, int row, int xres, int yres, Pixel& value,
                float& depth) {
    auto ray = pixelRay(rays, previous, params, x, row, xres, yres);
    if (!ray) {  // black, as RADIANCE
        value = Pixel{0, 0, 0};
        depth = 0;
        return false;
    }
    const uint64_t index = uint64_t(row) * uint64_t(xres) + uint64_t(x);
    double distance = 0;
    const double maxDistance = ray->maxDistance > 0 ? ray->maxDistance : HUGE_VAL;
    const Color c = tracer(ray->origin, ray->direction, index, maxDistance, &distance);
    value = Pixel{float(c.r), float(c.g), float(c.b)};
    depth = float(distance);
    return true;
}

std::vector<std::string> viewHeaderLines(const RpictOptions& options) {
    std::vector<std::string> lines{viewHeaderLine(options.view)};
    // RADIANCE compat (rpict.c): PIXASPECT only when the pixels are not about square.
    const double pa = pictureSize(options).pixelAspect;
    if (pa < .99 || pa > 1.01) lines.push_back(fmt::format("PIXASPECT={:f}", pa));
    return lines;
}

Picture renderPicture(const RpictOptions& options, const PixelTracerFactory& factory,
                      const ProgressCallback& progress, std::vector<float>* depth,
                      const RenderRows& rowsIn) {
    ViewRays rays(options.view);
    std::optional<ViewRays> previous;
    if (rowsIn.previousView) previous.emplace(*rowsIn.previousView);
    const PictureSize size = pictureSize(options);
    const SampleGrid grid = sampleGrid(options.sampleSpacing, size.yres);
    const int hstep = grid.hstep;
    const std::vector<int>& rows = grid.rows;

    Picture pic(size.xres, size.yres);
    std::vector<float> z(pic.pixels.size(), 0.0f);
    const int firstRow = std::clamp(rowsIn.firstRow, 0, size.yres);
    std::atomic<long> traced{0};
    const PixelRayParams params{options.pixelJitter, options.motionBlur, options.apertureBlur};
    Sampler s{rays,
              previous,
              size.xres,
              size.yres,
              params,
              options.sampleThreshold,
              depth != nullptr,
              pic.pixels,
              z,
              traced};

    Progress report(progress, options.reportInterval, size.yres, firstRow, traced);
    report.start();
    std::mutex factoryMutex;
    tbb::enumerable_thread_specific<PixelTracer> tracers;
    auto tracerHere = [&]() -> PixelTracer& {
        PixelTracer& t = tracers.local();
        if (!t) {
            std::lock_guard<std::mutex> lock(factoryMutex);
            t = factory();
            RP_CHECK(bool(t));
        }
        return t;
    };
    // The picture is made in chunks of sampled scanlines, top to bottom, so that finished
    // rows can be written while the rest is rendered. A recovered picture restarts at the
    // last sampled scanline at or above its first missing row: that scanline and the band
    // below it are traced again (the rows above firstRow are not handed over), so the
    // rows after firstRow come out as the uninterrupted run made them.
    size_t start = 0;
    while (start + 1 < rows.size() && rows[start + 1] <= firstRow) ++start;
    const int threads = std::max(1, options.render.threads);
    Cluster* cluster = rowsIn.cluster;
    const bool spread = distributed(cluster);
    const size_t ranks = spread ? size_t(cluster->size()) : 1;
    const size_t rank = spread ? size_t(cluster->rank()) : 0;
    auto mine = [&](size_t k) { return k % ranks == rank; };
    // Eight sampled rows a thread: the threads wait for each other once a chunk, and rows
    // differ in cost (a window, a new irradiance cache region), so smaller chunks leave a
    // thread idle more often (bench/README_speed.md); larger ones write rows less often.
    const size_t chunk = size_t(std::max(8, 8 * threads)) * ranks;
    // Sampled row k and the band above it are traced by rank k % ranks; every rank needs
    // all sampled rows (a band reads the rows at both its ends), only the root needs the
    // bands.
    auto sampledRows = [&](size_t k, int& r0, int& r1) { r0 = rows[k], r1 = rows[k] + 1; };
    auto bandRows = [&](size_t k, int& r0, int& r1) { r0 = rows[k - 1] + 1, r1 = rows[k]; };
    // Pipelined: each step samples the rows of one chunk and fills the bands of the chunk
    // before it, all in one parallel loop, so that the threads wait for each other once a
    // chunk (the bands of a chunk need its sampled rows and the last one before it).
    struct Chunk {
        size_t k0 = 0, k1 = 0, b0 = 0;  // sampled rows[k0..k1), bands below rows[b0..k1)
    };
    auto chunkAt = [&](size_t k0) {
        const size_t k1 = std::min(rows.size(), k0 + chunk);
        return Chunk{k0, k1, std::max(k0, start + 1)};
    };
    int handed = firstRow;
    tbb::task_arena arena(threads);
    std::optional<Chunk> pending;  // sampled, bands not yet filled
    for (size_t k0 = start; firstRow < size.yres && (k0 < rows.size() || pending); k0 += chunk) {
        std::optional<Chunk> now;
        if (k0 < rows.size()) now = chunkAt(k0);
        const size_t nSampled = now ? now->k1 - now->k0 : 0;
        const size_t nBands = pending ? pending->k1 - pending->b0 : 0;
        arena.execute([&] {
            tbb::parallel_for(size_t(0), nSampled + nBands, [&](size_t i) {
                if (i < nSampled) {
                    const size_t k = now->k0 + i;
                    if (!mine(k)) return;
                    s.sampledRow(tracerHere(), rows[k], int(k), hstep);
                    if (rows[k] >= firstRow) report.advance(1);
                } else {
                    const size_t k = pending->b0 + (i - nSampled);
                    if (!mine(k)) return;
                    s.band(tracerHere(), rows[k - 1], rows[k]);
                    report.advance(bandRowsAfter(rows, k, firstRow));
                }
            });
        });
        if (spread && now) shareRows(*cluster, pic, z, now->k0, now->k1, ranks, sampledRows, false);
        if (spread && pending)
            shareRows(*cluster, pic, z, pending->b0, pending->k1, ranks, bandRows, true);
        if (spread && cluster->isRoot()) {  // the others' rows, for the root's progress
            if (now)
                for (size_t k = now->k0; k < now->k1; ++k)
                    if (!mine(k) && rows[k] >= firstRow) report.advance(1);
            if (pending)
                for (size_t k = pending->b0; k < pending->k1; ++k)
                    if (!mine(k)) report.advance(bandRowsAfter(rows, k, firstRow));
        }
        if (pending) {
            // The last sampled row is the top of the next band: kept until that is filled.
            const int end = pending->k1 < rows.size() ? rows[pending->k1 - 1] : size.yres;
            if (end > handed) {
                if (rowsIn.finish && (!spread || cluster->isRoot()))
                    rowsIn.finish(pic, depth ? &z : nullptr, handed, end);
                if (rowsIn.done) rowsIn.done(pic, z, handed, end);
            }
            handed = std::max(handed, end);
        }
        pending = now;
    }
    report.finish();

    for (auto& line : viewHeaderLines(options)) pic.header.lines.push_back(std::move(line));
    if (depth) *depth = std::move(z);
    return pic;
}

void addRpictHeader(Picture& picture, const std::string& commandLine, std::time_t now) {
    auto& lines = picture.header.lines;
    lines.insert(lines.begin(), {commandLine, "SOFTWARE= " + softwareName()});
    // RADIANCE compat (header.c fputnow): local capture time, then the same in GMT.
    std::tm local{}, gmt{};
    localtime_r(&now, &local);
    gmtime_r(&now, &gmt);
    auto stamp = [](const char* key, const std::tm& t) {
        return fmt::format("{} {:04d}:{:02d}:{:02d} {:02d}:{:02d}:{:02d}", key, t.tm_year + 1900,
                           t.tm_mon + 1, t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec);
    };
    lines.push_back(stamp("CAPDATE=", local));
    lines.push_back(stamp("GMT=", gmt));
    // RADIANCE 5.4a's rpict names its (standard) primaries; radcompare compares headers'
    // settings, so a picture without the line differs from RADIANCE's.
    lines.push_back("PRIMARIES= 0.6400 0.3300 0.2900 0.6000 0.1500 0.0600 0.3333 0.3333");
}

}  // namespace rp::render
