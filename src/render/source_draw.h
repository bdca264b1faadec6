// rpict's bitty sources (RADIANCE srcdraw.c): light sources thinner in the picture than
// the pixel sampling (-ps) are usually missed by the pixel rays, so once the pixels are
// final each such source is drawn into the pixels its image polygon covers. The picture
// loop is rpict.h's (RenderRows::finish calls this); the rays to the sources are the
// direct calculation's (DirectLighting::traceToward).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "image/picture.h"
#include "image/view.h"
#include "render/rpict.h"
#include "render/source_list.h"
#include "util/color.h"
#include "util/spectrum.h"

namespace rp::render {

class Renderer;

// A convex polygon in image coordinates (x right, y up, the picture's [0,1]^2).
struct ImagePolygon {
    static constexpr int kMaxVertices = 24;
    std::array<std::array<double, 2>, kMaxVertices> v{};
    int n = 0;

    void add(double x, double y);
    double area() const;
    // The mean of the vertices (RADIANCE's convex_center: not the centroid).
    std::array<double, 2> centre() const;
    // The part inside [x0, x1) x [y0, y1) (edges at x0 and y0 included, as RADIANCE's
    // box_clip_poly); fewer than 3 vertices when nothing is left.
    ImagePolygon clip(double x0, double x1, double y0, double y1) const;
    // The square of the smallest width over the polygon's edge directions, y distances
    // scaled by sqrt(aspect2) (RADIANCE's minw2, aspect2 = (vertical/horizontal)^2 of
    // the image plane).
    double minWidth2(double aspect2) const;
};

// The convex hull of `n` points (Andrew's monotone chain), counter-clockwise.
ImagePolygon convexHull(const std::array<double, 2>* points, int n);

// A source drawn into the picture: its index in SourceList::sources and its image.
struct BittySource {
    size_t source = 0;
    ImagePolygon image;
};

// The image polygon of `src` (RADIANCE sourcepoly), false if it has none: a distant
// source (0.05 rad radius at most, none in a parallel view) as the square of its solid
// angle around its direction; a flat source that faces the view as its four corners (a
// 4-vertex polygon's own, else the square of its area around its centre); any other as
// the convex hull of its bounding cube (RADIANCE's 0.7236 r for spheres, its cylinder box
// for the cone family). Every corner must be in the image, in front and within -va.
bool sourceImage(const SourceList& list, const DirectSource& src, const Scene& scene,
                 const ShapeSet& shapes, const ViewRays& rays, ImagePolygon& image);

// RADIANCE init_drawsources: the real sources, illums excepted, whose image (clipped to
// the picture) is narrower than `sampleSpacing` (-ps, 1 to 16) pixels.
std::vector<BittySource> findBittySources(const SourceList& list, const Scene& scene,
                                          const ShapeSet& shapes, const ViewRays& rays, int xres,
                                          int yres, int sampleSpacing);

// The radiance of source `source` along a view ray (zero: blocked or missed), and in
// *distance how far away it is. `index` keys random numbers (the pixel's row * xres + x).
using SourceRayValue =
    std::function<Color(size_t source, const ViewRays::Ray& ray, uint64_t index, double* distance)>;

// RADIANCE drawsources on picture rows [rowBegin, rowEnd) (row 0 at the top): for each
// pixel a source's image overlaps by a fraction w of the pixel, the source's value along
// the view ray through the overlap's centre replaces that fraction of the pixel. With a
// depth buffer a nearer source also sets the depth. RADIANCE compat: a pixel within 1 %
// of the value (the pixel ray saw the source) is only scaled by w.
void drawBittySources(const std::vector<BittySource>& sources, const ViewRays& rays,
                      Picture& picture, std::vector<float>* depth, int rowBegin, int rowEnd,
                      const SourceRayValue& value);

// The RenderRows::finish of an rpict frame rendered with `renderer` (`frame`: its view and
// size): draws its bitty sources. Empty with -dv- or when there are none.
RowsPass bittySourcePass(const Renderer& renderer, const RpictOptions& frame);
// The same for a frame rendered in spectral passes (render/spectral_passes.h): each
// source's value is the RGB of its bands from every pass (a pass in which the source has
// no light has no such source: zero there).
RowsPass bittySourcePass(std::span<const Renderer* const> passes,
                         const spectral::Sampling& sampling, const RpictOptions& frame);

}  // namespace rp::render
