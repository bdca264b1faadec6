// rpict's picture loop with fake tracers: exact interpolation of linear images, tracing
// at edges, thread-count independence, fisheye masks, depth, header and files.
#include "render/rpict.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

#include "image/picture.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"
#include "util/version.h"

namespace rp::render {
namespace {

// Records which pixels were traced (thread-safe) and counts factory calls.
struct TraceLog {
    explicit TraceLog(size_t n) : traced(n) {}
    std::vector<std::atomic<int>> traced;
    std::atomic<int> factoryCalls{0};
    int count(size_t i) const { return traced[i].load(); }
    int total() const {
        int t = 0;
        for (const auto& c : traced) t += c.load();
        return t;
    }
};

// A factory whose tracers return value(x, row) for pixel index = row * xres + x.
template <class F>
PixelTracerFactory fakeFactory(int xres, TraceLog* log, F value, double distance = 1.0) {
    return [=]() -> PixelTracer {
        if (log) log->factoryCalls++;
        return [=](const Vec3&, const Vec3&, uint64_t index, double, double* d) {
            if (log) log->traced[index]++;
            *d = distance;
            return value(int(index % uint64_t(xres)), int(index / uint64_t(xres)));
        };
    };
}

RpictOptions smallOptions(int x, int y, int ps) {
    RpictOptions o;
    o.xres = x;
    o.yres = y;
    o.sampleSpacing = ps;
    return o;
}

TEST(RpictRender, LinearImagesAreExactWithAndWithoutInterpolation) {
    for (int ps : {1, 2, 4, 8}) {
        RpictOptions o = smallOptions(37, 37, ps);
        auto f = [](int x, int row) { return Color(x, 2.0 * row + 1, x + row + 3.0); };
        TraceLog log(37 * 37);
        Picture pic = renderPicture(o, fakeFactory(37, &log, f));
        ASSERT_EQ(pic.width, 37);
        ASSERT_EQ(pic.height, 37);
        for (int row = 0; row < 37; ++row)
            for (int x = 0; x < 37; ++x) {
                Color c = f(x, row);
                ASSERT_EQ(pic.at(x, row)[0], float(c.r))
                    << "ps " << ps << " at " << x << "," << row;
                ASSERT_EQ(pic.at(x, row)[1], float(c.g)) << "ps " << ps;
                ASSERT_EQ(pic.at(x, row)[2], float(c.b)) << "ps " << ps;
            }
        // No pixel is traced twice.
        for (size_t i = 0; i < log.traced.size(); ++i) ASSERT_LE(log.count(i), 1) << i;
        if (ps == 1) {
            EXPECT_EQ(log.total(), 37 * 37);
        }
    }
}

TEST(RpictRender, DegeneratePictureSizes) {
    for (auto [x, y] : {std::pair{1, 1}, std::pair{1, 7}, std::pair{7, 1}, std::pair{2, 2}}) {
        RpictOptions o = smallOptions(x, y, 4);
        o.pixelAspect = 0;  // keep the requested size
        TraceLog log(size_t(x) * y);
        Picture pic = renderPicture(
            o, fakeFactory(x, &log, [](int px, int row) { return Color(px, row, 1); }));
        ASSERT_EQ(pic.width, x);
        ASSERT_EQ(pic.height, y);
        for (int row = 0; row < y; ++row)
            for (int px = 0; px < x; ++px)
                ASSERT_EQ(pic.at(px, row), (Pixel{float(px), float(row), 1}));
    }
}

TEST(RpictRender, SmoothImagesAreMostlyInterpolated) {
    RpictOptions o = smallOptions(64, 64, 4);
    TraceLog log(64 * 64);
    Picture pic = renderPicture(o, fakeFactory(64, &log, [](int, int) { return Color(1, 1, 1); }));
    // A constant image needs only the quincunx samples: about 1 in 6 * 3 pixels.
    EXPECT_LT(log.total(), 64 * 64 / 8);
    for (const Pixel& p : pic.pixels) ASSERT_EQ(p[0], 1.0f);
}

TEST(RpictRender, EdgesAreTracedNotInterpolated) {
    const int n = 48;
    auto f = [](int x, int row) {
        return (x >= 21) != (row >= 30) ? Color(1, 1, 1) : Color(0.1, 0.1, 0.1);
    };
    RpictOptions o = smallOptions(n, n, 4);
    o.sampleThreshold = 0.01;
    TraceLog log(n * n);
    Picture pic = renderPicture(o, fakeFactory(n, &log, f));
    int sampledRows = 0;
    for (int row = 0; row < n; ++row) {
        // Both sides of the vertical edge are traced on every sampled scanline (those
        // that trace their first pixel); between them columns agree and are interpolated.
        if (log.count(size_t(row) * n) == 1) {
            ++sampledRows;
            EXPECT_EQ(log.count(size_t(row) * n + 20), 1) << row;
            EXPECT_EQ(log.count(size_t(row) * n + 21), 1) << row;
        }
        for (int x = 0; x < n; ++x)
            ASSERT_EQ(pic.at(x, row)[0], float(f(x, row).r)) << x << "," << row;
    }
    // ...and the scanline above the horizontal one (row 30 is sampled) in every column.
    for (int x = 0; x < n; ++x) EXPECT_EQ(log.count(size_t(29) * n + x), 1) << x;
    EXPECT_GE(sampledRows, n / 3);
    EXPECT_LT(log.total(), n * n / 2);
}

TEST(RpictRender, ResultsDoNotDependOnThreads) {
    // A value that depends on the (jittered) direction and, in places, on the pixel.
    auto factory = [](std::atomic<int>* calls) -> PixelTracerFactory {
        return [calls]() -> PixelTracer {
            ++*calls;
            return [](const Vec3& org, const Vec3& dir, uint64_t index, double, double* d) {
                *d = 2 + dir.x;
                double v = 1 + dir.x + 0.5 * dir.z + (index % 97 == 0 ? 3.0 : 0.0);
                return Color(v, v * v, org.z + 1);
            };
        };
    };
    RpictOptions o = smallOptions(80, 60, 4);
    o.pixelAspect = 0;
    std::vector<float> z1, z4;
    std::atomic<int> calls1{0}, calls4{0};
    o.render.threads = 1;
    Picture a = renderPicture(o, factory(&calls1), {}, &z1);
    o.render.threads = 4;
    Picture b = renderPicture(o, factory(&calls4), {}, &z4);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_TRUE(a.pixels == b.pixels);
    EXPECT_TRUE(z1 == z4);
    EXPECT_EQ(calls1.load(), 1);
    EXPECT_GE(calls4.load(), 1);
    EXPECT_LE(calls4.load(), 4);
}

TEST(RpictRender, FisheyeCornersAreBlackAndNotTraced) {
    RpictOptions o = smallOptions(32, 32, 1);
    o.view.type = ViewType::kHemispherical;
    o.view.horizontal = o.view.vertical = 180;
    TraceLog log(32 * 32);
    std::vector<float> z;
    Picture pic = renderPicture(o,
                                fakeFactory(
                                    32, &log, [](int, int) { return Color(1, 2, 3); }, 5.0),
                                {}, &z);
    EXPECT_EQ(log.count(0), 0);
    EXPECT_EQ(pic.at(0, 0), (Pixel{0, 0, 0}));
    EXPECT_EQ(z[0], 0.0f);
    EXPECT_EQ(log.count(16 * 32 + 16), 1);
    EXPECT_EQ(pic.at(16, 16), (Pixel{1, 2, 3}));
    EXPECT_EQ(z[16 * 32 + 16], 5.0f);
}

TEST(RpictRender, RaysFollowTheView) {
    // Pixel centres (-pj 0) of a perspective view looking along +y: the centre column's
    // rays have x ~ 0 and the top row's rays point up.
    RpictOptions o = smallOptions(33, 33, 1);
    o.pixelJitter = 0;
    o.view.point = Vec3(1, 2, 3);
    PixelTracerFactory factory = []() -> PixelTracer {
        return [](const Vec3& org, const Vec3& dir, uint64_t, double, double* d) {
            *d = 1;
            EXPECT_NEAR(length(dir), 1.0, 1e-12);
            EXPECT_EQ(org, Vec3(1, 2, 3));
            return Color(dir.x, dir.y, dir.z);
        };
    };
    Picture pic = renderPicture(o, factory);
    EXPECT_NEAR(pic.at(16, 16)[0], 0.0, 1e-6);
    EXPECT_NEAR(pic.at(16, 16)[1], 1.0, 1e-6);
    EXPECT_GT(pic.at(16, 0)[2], 0.3);    // top row looks up
    EXPECT_LT(pic.at(16, 32)[2], -0.3);  // bottom row looks down
    EXPECT_LT(pic.at(0, 16)[0], -0.3);   // left column looks left
}

TEST(RpictRender, AftClippingReachesTheTracerAndBadViewsFail) {
    RpictOptions o = smallOptions(8, 8, 1);
    // The tracer sees the aft distance along each ray: -va 10 minus -vo 2 on the axis,
    // longer off it (the aft plane is a plane); without -va, no limit.
    std::atomic<int> limited{0}, unlimited{0};
    PixelTracerFactory f = [&]() -> PixelTracer {
        return [&](const Vec3&, const Vec3&, uint64_t, double maxDistance, double* d) {
            *d = 1;
            if (maxDistance < HUGE_VAL) {
                EXPECT_GE(maxDistance, 8 - 1e-9);
                EXPECT_LT(maxDistance, 8 * 1.5);
                ++limited;
            } else {
                ++unlimited;
            }
            return Color();
        };
    };
    o.view.fore = 2;
    o.view.aft = 10;
    renderPicture(o, f);
    EXPECT_GT(limited.load(), 0);
    EXPECT_EQ(unlimited.load(), 0);
    o.view.fore = 0;
    o.view.aft = 0;
    limited = 0;
    renderPicture(o, f);
    EXPECT_EQ(limited.load(), 0);
    EXPECT_GT(unlimited.load(), 0);
    o.view.direction = Vec3(0, 0, 0);
    EXPECT_THROW(renderPicture(o, f), InputError);
}

TEST(RpictRender, ProgressReportsStartAndEnd) {
    RpictOptions o = smallOptions(16, 16, 4);
    o.reportInterval = 3600;  // only the first and last reports fall due
    std::vector<RenderProgress> reports;
    renderPicture(o, fakeFactory(16, nullptr, [](int x, int) { return Color(x, x, x); }),
                  [&](const RenderProgress& p) { reports.push_back(p); });
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_EQ(reports[0].percentDone, 0);
    EXPECT_EQ(reports[1].percentDone, 100);
    EXPECT_GT(reports[1].primaryRays, 0);
    o.reportInterval = 0;
    reports.clear();
    renderPicture(o, fakeFactory(16, nullptr, [](int, int) { return Color(); }),
                  [&](const RenderProgress& p) { reports.push_back(p); });
    EXPECT_TRUE(reports.empty());
    EXPECT_EQ(formatProgress(1234, 45.0, 36.0), "1234 rays, 45.00% after 0.0100 hours");
}

TEST(RpictRender, HeaderAndRoundTrip) {
    RpictOptions o = smallOptions(40, 40, 4);
    o.view.point = Vec3(2.75, 0.05, 2.75);
    auto f = [](int x, int row) { return Color(0.01 * x, 0.5, 0.02 * row + 0.001); };
    Picture pic = renderPicture(o, fakeFactory(40, nullptr, f));
    addRpictHeader(pic, "rpict -x 40 -y 40 scene.rad", std::time_t(0));
    std::stringstream file;
    writePicture(file, pic);
    Picture back = readPicture(file, "rpict output");
    ASSERT_EQ(back.width, 40);
    ASSERT_EQ(back.height, 40);
    const auto& lines = back.header.lines;
    ASSERT_GE(lines.size(), 5u);
    EXPECT_EQ(lines[0], "rpict -x 40 -y 40 scene.rad");
    EXPECT_EQ(lines[1], "SOFTWARE= " + softwareName());
    EXPECT_EQ(lines[2], viewHeaderLine(o.view));
    EXPECT_EQ(lines[2].rfind("VIEW= -vtv -vp 2.75 0.05 2.75", 0), 0u);
    EXPECT_EQ(lines[3].rfind("CAPDATE= ", 0), 0u);
    EXPECT_EQ(lines[4], "GMT= 1970:01:01 00:00:00");
    EXPECT_EQ(back.format, PictureFormat::kRgbe);
    EXPECT_DOUBLE_EQ(back.pixelAspect(), 1);
    for (int row = 0; row < 40; ++row)
        for (int x = 0; x < 40; ++x)
            for (int c = 0; c < 3; ++c)  // RGBE: 8-bit mantissas under a shared exponent
                ASSERT_NEAR(back.at(x, row)[c], f(x, row)[c], 0.01 * f(x, row).max());
}

TEST(RpictRender, PixelAspectLineWhenPixelsAreNotSquare) {
    RpictOptions o = smallOptions(20, 20, 1);
    o.view.horizontal = 60;
    o.pixelAspect = 0;  // keep 20 x 20: pixels become flatter than square
    Picture pic = renderPicture(o, fakeFactory(20, nullptr, [](int, int) { return Color(); }));
    ASSERT_EQ(pic.width, 20);
    ASSERT_EQ(pic.height, 20);
    ASSERT_EQ(pic.header.lines.size(), 2u);
    EXPECT_EQ(pic.header.lines[1].rfind("PIXASPECT=0.71", 0), 0u) << pic.header.lines[1];
    EXPECT_NEAR(pic.pixelAspect(), std::tan(22.5 * kPi / 180) / std::tan(30 * kPi / 180), 1e-6);
}

TEST(RpictRender, DepthOfFieldBlursOnlyAwayFromTheFocus) {
    // A wall at y = 5, white where x > 0, seen along +y through pixel centres: the focus
    // at the wall (-vd 0 5 0) keeps every pixel as the pinhole's; a focus at 2.5 spreads
    // each pixel over the aperture's diameter on the wall (|1 - 5/2.5| * 0.5), so pixels
    // whose pinhole ray lands within 0.25 of the edge may change and no others do.
    auto pictureWith = [](Vec3 direction, double pd, ViewType type, std::vector<Vec3>* origins) {
        RpictOptions o = smallOptions(40, 40, 1);
        o.pixelJitter = 0;
        o.apertureBlur = pd;
        o.view.type = type;
        o.view.direction = direction;
        o.view.horizontal = o.view.vertical = type == ViewType::kParallel ? 4 : 40;
        auto m = std::make_shared<std::mutex>();
        PixelTracerFactory f = [=]() -> PixelTracer {
            return [=](const Vec3& org, const Vec3& dir, uint64_t, double, double* d) {
                const double t = (5 - org.y) / dir.y;
                *d = t;
                if (origins) {
                    std::lock_guard<std::mutex> lock(*m);
                    origins->push_back(org);
                }
                return (org + t * dir).x > 0 ? Color(1, 1, 1) : Color(0, 0, 0);
            };
        };
        return renderPicture(o, f);
    };
    const Picture pinhole = pictureWith(Vec3(0, 5, 0), 0, ViewType::kPerspective, nullptr);
    std::vector<Vec3> origins;
    const Picture focused = pictureWith(Vec3(0, 5, 0), 0.5, ViewType::kPerspective, &origins);
    const Picture blurred = pictureWith(Vec3(0, 2.5, 0), 0.5, ViewType::kPerspective, nullptr);
    EXPECT_EQ(focused.pixels, pinhole.pixels);
    const double planeHalf = std::tan(20 * kPi / 180) * 5;  // wall x at the picture's edge
    int near = 0, changed = 0;
    for (int row = 0; row < 40; ++row)
        for (int x = 0; x < 40; ++x) {
            const double wallX = ((x + 0.5) / 40 - 0.5) * 2 * planeHalf;
            const bool differs = blurred.at(x, row) != pinhole.at(x, row);
            if (std::fabs(wallX) > 0.25) {
                ASSERT_FALSE(differs) << x << "," << row;
            } else {
                ++near;
                changed += differs;
            }
        }
    // A pixel at s from the edge changes with the chance that a uniform point of the
    // radius-0.25 disk lies beyond s: averaged over s in [0, 0.25] that is 2/(3 pi) =
    // 0.21. Bounds at about 4 binomial sigmas for the 240 pixels of the band.
    EXPECT_GT(changed, near * 12 / 100) << changed << " of " << near;
    EXPECT_LT(changed, near * 31 / 100) << changed << " of " << near;
    // The origins fill the aperture: a disk of radius 0.25 across the view direction.
    double rmax = 0;
    for (const Vec3& org : origins) {
        EXPECT_EQ(org.y, 0);
        rmax = std::max(rmax, std::hypot(org.x, org.z));
    }
    EXPECT_LE(rmax, 0.25 + 1e-12);
    EXPECT_GT(rmax, 0.24);
    // Parallel views focus each ray on its own point (not RADIANCE's single point).
    EXPECT_EQ(pictureWith(Vec3(0, 5, 0), 0.5, ViewType::kParallel, nullptr).pixels,
              pictureWith(Vec3(0, 5, 0), 0, ViewType::kParallel, nullptr).pixels);
    EXPECT_NE(pictureWith(Vec3(0, 1, 0), 0.5, ViewType::kParallel, nullptr).pixels,
              pictureWith(Vec3(0, 1, 0), 0, ViewType::kParallel, nullptr).pixels);
}

}  // namespace
}  // namespace rp::render
