// rpict's bitty sources: the image-polygon geometry, which sources are drawn, and a
// 0.5-degree sun that the pixel rays miss, drawn back with its radiance times its solid
// angle (the energy the picture must hold), through the whole picture pipeline.
#include "render/source_draw.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "calc/search_path.h"
#include "geometry/scene_geometry.h"
#include "render/renderer.h"
#include "render/rpict_tracer.h"
#include "scene/reader.h"
#include "util/paths.h"

namespace rp::render {
namespace {

ImagePolygon rectangle(double x0, double x1, double y0, double y1) {
    ImagePolygon p;
    p.add(x0, y0);
    p.add(x1, y0);
    p.add(x1, y1);
    p.add(x0, y1);
    return p;
}

TEST(ImagePolygon, ClipAreaCentreWidth) {
    const ImagePolygon r = rectangle(0.2, 0.6, 0.2, 0.6);
    EXPECT_NEAR(r.area(), 0.16, 1e-15);
    const ImagePolygon half = r.clip(0.5, 1, 0, 1);
    ASSERT_EQ(half.n, 4);
    EXPECT_NEAR(half.area(), 0.04, 1e-15);
    EXPECT_NEAR(half.centre()[0], 0.55, 1e-15);
    EXPECT_NEAR(half.centre()[1], 0.4, 1e-15);
    EXPECT_LT(r.clip(0.7, 1, 0, 1).n, 3);  // nothing left
    // A triangle cut by a corner of the box gains vertices.
    ImagePolygon t;
    t.add(0, 0);
    t.add(1, 0);
    t.add(0, 1);
    EXPECT_NEAR(t.clip(0.25, 1, 0.25, 1).area(), 0.125, 1e-15);
    // Widths: 0.4 by 0.1; with y distances doubled, 0.4 by 0.2.
    const ImagePolygon thin = rectangle(0.1, 0.5, 0.3, 0.4);
    EXPECT_NEAR(thin.minWidth2(1), 0.01, 1e-15);
    EXPECT_NEAR(thin.minWidth2(4), 0.04, 1e-15);
}

TEST(ImagePolygon, ConvexHullDropsInnerPoints) {
    const std::array<double, 2> pts[] = {{0.5, 0.5}, {0, 0}, {1, 0},   {0.2, 0.7},
                                         {1, 1},     {0, 1}, {0.5, 0}, {0.9, 0.1}};
    const ImagePolygon h = convexHull(pts, 8);
    EXPECT_EQ(h.n, 4);
    EXPECT_NEAR(h.area(), 1, 1e-15);
}

// A 0.5-degree sun of radiance 1000 on a black background, seen by a 20-degree camera of
// 32 by 32 pixels (0.625 degrees each) whose centre is a pixel corner.
constexpr double kSunRadiance = 1000;
std::string sunScene(const std::string& dir, double degrees = 0.5) {
    return "void light sunlight 0 0 3 1000 1000 1000\n"
           "sunlight source sun 0 0 4 " +
           dir + " " + std::to_string(degrees) + "\n";
}

RpictOptions camera(int res = 32) {
    RpictOptions o;
    applyViewString(o.view, "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 20 -vv 20");
    o.xres = o.yres = res;
    o.sampleSpacing = 1;
    o.pixelJitter = 0;
    o.render.threads = 1;
    return o;
}

struct Rendered {
    Picture picture;
    std::vector<float> depth;
};

// The picture rpict makes (bitty sources drawn unless `draw` is false).
Rendered render(const std::string& text, const RpictOptions& o, bool draw = true) {
    const Scene scene = parseScene(text, "t.rad");
    SceneGeometry geometry(scene);
    Renderer renderer(scene, geometry, o.render, calc::defaultSearchPath(projectLibDir()));
    RenderRows rows;
    if (draw) rows.finish = bittySourcePass(renderer, o);
    Rendered r;
    r.picture = renderPicture(o, rendererPixelTracers(renderer), {}, &r.depth, rows);
    return r;
}

// Solid angle of the image-plane rectangle [u0,u1] x [v0,v1] at distance 1.
double rectangleSolidAngle(double u0, double u1, double v0, double v1) {
    auto f = [](double u, double v) { return std::atan(u * v / std::sqrt(1 + u * u + v * v)); };
    return f(u1, v1) - f(u0, v1) - f(u1, v0) + f(u0, v0);
}

// The solid angle of pixel (x, row) of a camera() picture.
double pixelSolidAngle(const Picture& pic, int x, int row) {
    const double t = std::tan(10 * kPi / 180), du = 2 * t / pic.width, dv = 2 * t / pic.height;
    const double u0 = -t + x * du, v0 = t - (row + 1) * dv;
    return rectangleSolidAngle(u0, u0 + du, v0, v0 + dv);
}

// Sum over the pixels of radiance (green) times solid angle: the picture's
// irradiance-like total for a camera built by camera().
double energy(const Picture& pic) {
    double sum = 0;
    for (int row = 0; row < pic.height; ++row)
        for (int x = 0; x < pic.width; ++x) sum += pic.at(x, row)[1] * pixelSolidAngle(pic, x, row);
    return sum;
}

double sunSolidAngle(double degrees = 0.5) {
    return 2 * kPi * (1 - std::cos(degrees / 2 * kPi / 180));
}

TEST(BittySources, MissedSunIsDrawnWithItsEnergy) {
    const std::string scene = sunScene("0 1 0");
    const double truth = kSunRadiance * sunSolidAngle();
    // The sun's image (radius 0.4 pixel) lies between the four central pixel centres.
    EXPECT_EQ(energy(render(scene, camera(), false).picture), 0);
    const Rendered r = render(scene, camera());
    // 1 %: the image square (RADIANCE's, of the sun's solid angle) seen in perspective.
    EXPECT_NEAR(energy(r.picture), truth, 0.01 * truth);
    for (int row : {15, 16})
        for (int x : {15, 16}) EXPECT_GT(r.picture.at(x, row)[1], 0) << x << "," << row;
    // -dv-: sources are not visible, and not drawn either.
    RpictOptions off = camera();
    off.render.direct.visibility = false;
    EXPECT_EQ(energy(render(scene, off).picture), 0);
}

TEST(BittySources, SunSeenByAPixelRayIsScaledToItsShare) {
    // Centred on pixel (16, 15): its ray sees the sun, whose image covers a part of it.
    const double t = std::tan(10 * kPi / 180);
    const std::string dir = std::to_string(t / 32) + " 1 " + std::to_string(t / 32);
    const double truth = kSunRadiance * sunSolidAngle();
    const Rendered plain = render(sunScene(dir), camera(), false);
    EXPECT_NEAR(plain.picture.at(16, 15)[1], kSunRadiance, 1e-3);
    const Rendered r = render(sunScene(dir), camera());
    EXPECT_NEAR(energy(r.picture), truth, 0.01 * truth);
    // The image lies in the pixel: the pixel keeps the sun's share of it (about half).
    const double share = sunSolidAngle() / pixelSolidAngle(r.picture, 16, 15);
    EXPECT_NEAR(r.picture.at(16, 15)[1], kSunRadiance * share, 0.01 * kSunRadiance * share);
}

TEST(BittySources, SamplingSpacingThreadsAndBigSources) {
    const std::string scene = sunScene("0.05 1 -0.03");
    const double truth = kSunRadiance * sunSolidAngle();
    RpictOptions o = camera();
    o.sampleSpacing = 4;
    const Rendered one = render(scene, o);
    EXPECT_NEAR(energy(one.picture), truth, 0.01 * truth);
    o.render.threads = 3;
    const Rendered three = render(scene, o);
    EXPECT_EQ(one.picture.pixels, three.picture.pixels);
    // A 3-degree sun (almost 5 pixels across) is left to the pixel rays.
    const Rendered big = render(sunScene("0 1 0", 3), camera());
    EXPECT_NEAR(energy(big.picture), kSunRadiance * sunSolidAngle(3),
                0.1 * kSunRadiance * sunSolidAngle(3));
}

TEST(BittySources, WhichSourcesAreDrawn) {
    const Scene scene = parseScene(sunScene("0 1 0") + sunScene("0 1 0.1", 6) + sunScene("0 -1 0") +
                                       "void illum window 0 0 3 5 5 5\n"
                                       "window sphere pane 0 0 4 0 10 0 0.01\n"
                                       "sunlight sphere bulb 0 0 4 0.1 10 0 0.01\n",
                                   "t.rad");
    SceneGeometry geometry(scene);
    const RpictOptions o = camera();
    Renderer renderer(scene, geometry, o.render, calc::defaultSearchPath(projectLibDir()));
    const SourceList& list = renderer.directSources();
    auto found = [&](const View& view, int res, int ps) {
        std::vector<std::string> names;
        for (const BittySource& b :
             findBittySources(list, scene, geometry.shapes(), ViewRays(view), res, res, ps))
            names.push_back(list.sources[b.source].light.name);
        std::string all;
        for (const std::string& n : names) all += n.substr(0, n.find(' ')) + " ";
        return all;
    };
    // The 6-degree sun is too big to miss, the third is behind, the illum is skipped.
    EXPECT_EQ(found(o.view, 32, 1), "sun bulb ");
    // 256 pixels: the sun is 5.7 pixels wide, more than -ps 4 but not -ps 8; the bulb
    // (0.11 degrees) stays small.
    EXPECT_EQ(found(o.view, 256, 4), "bulb ");
    EXPECT_EQ(found(o.view, 256, 8), "sun bulb ");
    // A parallel view sees distant sources whole or not at all.
    View par;
    applyViewString(par, "-vtl -vp 0 0 0 -vd 0 1 0 -vh 1 -vv 1");
    EXPECT_EQ(found(par, 32, 1), "bulb ");
}

TEST(BittySources, NearSourceSetsTheDepth) {
    // A small bulb 5 away before a wall 10 away, between the central pixel centres.
    const std::string scene =
        "void light bulb 0 0 3 100 100 100\n"
        "bulb sphere lamp 0 0 4 0 5 0 0.005\n"
        "void plastic white 0 0 5 .5 .5 .5 0 0\n"
        "white polygon wall 0 0 12 -5 10 -5  5 10 -5  5 10 5  -5 10 5\n";
    const Rendered plain = render(scene, camera(), false);
    const Rendered r = render(scene, camera());
    for (int row : {15, 16})
        for (int x : {15, 16}) {
            const size_t at = size_t(row) * 32 + size_t(x);
            EXPECT_NEAR(plain.depth[at], 10, 0.01);
            EXPECT_NEAR(r.depth[at], 5, 0.01) << x << "," << row;
            EXPECT_GT(r.picture.pixels[at][1], plain.picture.pixels[at][1]);
        }
    EXPECT_NEAR(r.depth[0], plain.depth[0], 1e-6);
}

}  // namespace
}  // namespace rp::render
