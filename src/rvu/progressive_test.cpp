// rvu's progressive picture: refined with -ps 1 it is rpict -ps 1's picture, pixel for
// pixel, with every pixel traced exactly once however the work was interrupted; the
// first level is a few dozen rays that cover the whole picture; -ps > 1 traces fully
// only where neighbours differ; a frame keeps refinement inside it.
#include "rvu/progressive.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "render/rpict.h"
#include "render/rpict_options.h"

namespace rp::rvu {
namespace {

// A smooth, direction-dependent "scene" that counts its rays; `edge` adds a step where
// the ray's x direction crosses it.
struct FakeScene {
    std::atomic<long> rays{0};
    double edge = HUGE_VAL;
    render::PixelTracerFactory factory() {
        return [this]() -> render::PixelTracer {
            return [this](const Vec3& org, const Vec3& dir, uint64_t, double, double* distance) {
                rays.fetch_add(1);
                *distance = 1 + org.x;
                const double step = dir.x > edge ? 10 : 0;
                return Color(0.5 + 0.5 * dir.x + step, 0.5 + 0.5 * dir.z, 1 + step);
            };
        };
    }
};

View frontView(ViewType type = ViewType::kPerspective) {
    View v;
    v.type = type;
    v.horizontal = v.vertical = type == ViewType::kPerspective ? 60 : 180;
    return v;
}

render::PixelRayParams jittered() { return render::PixelRayParams{0.67, 0, 0}; }

void refineAll(ProgressiveImage& image, FakeScene& scene, int threads = 2) {
    for (int guard = 0; !image.done() && guard < 64; ++guard)
        image.refineLevel(threads, scene.factory(), {}, {});
    ASSERT_TRUE(image.done());
}

TEST(ProgressiveImage, RefinedWithPs1IsRpictsPicture) {
    for (ViewType type : {ViewType::kPerspective, ViewType::kHemispherical}) {
        const View view = frontView(type);
        FakeScene ours, theirs;
        ProgressiveImage image(view, 67, 45, jittered(), 1, 0.05);
        refineAll(image, ours);
        render::RpictOptions o;
        o.view = view;
        o.xres = 67;
        o.yres = 45;
        o.pixelAspect = 0;  // keep the size
        o.sampleSpacing = 1;
        o.pixelJitter = 0.67;
        o.render.threads = 3;
        Picture pic = render::renderPicture(o, theirs.factory());
        ASSERT_EQ(pic.pixels.size(), image.pixels().size());
        for (size_t i = 0; i < pic.pixels.size(); ++i)
            ASSERT_EQ(pic.pixels[i], image.pixels()[i]) << i;
        // Each pixel once: rpict traces the same rays (none outside the fisheye circle).
        EXPECT_EQ(ours.rays.load(), theirs.rays.load());
        EXPECT_EQ(image.tracedCount(), 67L * 45L);
    }
}

TEST(ProgressiveImage, FirstLevelCoversThePictureWithFewRays) {
    FakeScene scene;
    ProgressiveImage image(frontView(), 512, 512, jittered(), 1, 0.05);
    EXPECT_EQ(image.blockSize(), 64);
    EXPECT_FALSE(image.sampling());
    image.refineLevel(1, scene.factory(), {}, {});
    EXPECT_EQ(scene.rays.load(), 64);  // 8 x 8 blocks
    EXPECT_EQ(image.blockSize(), 32);
    for (const Pixel& p : image.pixels()) ASSERT_GT(p[2], 0.5f);  // nothing left black
    // Each block shows its own traced pixel.
    EXPECT_EQ(image.pixels()[size_t(100) * 512 + 70], image.pixels()[size_t(64) * 512 + 64]);
}

TEST(ProgressiveImage, InterruptedAndResumedGivesTheSamePicture) {
    FakeScene whole, pieces;
    ProgressiveImage a(frontView(), 96, 80, jittered(), 1, 0.05);
    refineAll(a, whole, 1);
    ProgressiveImage b(frontView(), 96, 80, jittered(), 1, 0.05);
    int interruptions = 0, calls = 0;
    while (!b.done() && calls < 1000) {
        ++calls;
        // Stop after every chunk.
        bool stop = false;
        if (!b.refineLevel(
                1, pieces.factory(), [&] { return stop; }, [&] { stop = true; }))
            ++interruptions;
    }
    EXPECT_TRUE(b.done());
    EXPECT_GT(interruptions, 3);
    EXPECT_EQ(a.pixels(), b.pixels());
    EXPECT_EQ(whole.rays.load(), pieces.rays.load());
}

TEST(ProgressiveImage, SamplingTracesOnlyWhereNeighboursDiffer) {
    FakeScene flat;
    // A picture that is nearly flat (within -pt): -ps 8 stops at 8-pixel blocks.
    ProgressiveImage image(frontView(), 128, 128, jittered(), 8, 10.0);
    refineAll(image, flat);
    EXPECT_EQ(flat.rays.load(), 16L * 16L);
    // With a sharp edge and a tight threshold, the blocks along it are traced to single
    // pixels, and the picture is exact there.
    FakeScene edged;
    edged.edge = 0.1;
    ProgressiveImage sharp(frontView(), 128, 128, jittered(), 8, 0.05);
    EXPECT_EQ(sharp.blockSize(), 16);
    refineAll(sharp, edged);
    EXPECT_LT(edged.rays.load(), 128L * 128L / 2);
    EXPECT_GT(edged.rays.load(), 16L * 16L);
    int exactAcross = 0;
    for (int x = 0; x < 128; ++x) exactAcross += sharp.traced(x, 64);
    EXPECT_GT(exactAcross, 16);  // more than the 8-pixel grid: the edge was refined
}

TEST(ProgressiveImage, FrameKeepsRefinementInside) {
    FakeScene scene;
    ProgressiveImage image(frontView(), 64, 64, jittered(), 1, 0.05);
    image.refineLevel(1, scene.factory(), {}, {});  // the first 8 x 8 blocks
    const long first = scene.rays.load();
    image.setFrame(PixelRect{0, 0, 32, 64});  // the left half
    refineAll(image, scene);
    EXPECT_EQ(scene.rays.load(), first + 32 * 64 - first / 2);
    for (int row = 0; row < 64; ++row) {
        EXPECT_TRUE(image.traced(31, row));
        EXPECT_FALSE(image.traced(33, row));
    }
}

}  // namespace
}  // namespace rp::rvu
