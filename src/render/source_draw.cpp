// rpict's bitty sources (see source_draw.h).
#include "render/source_draw.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "render/renderer.h"
#include "util/error.h"

namespace rp::render {

namespace {

using Point = std::array<double, 2>;

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

// The part of `in` where coordinate `axis` is >= cut (keepHigh) or < cut (otherwise):
// one step of Sutherland & Hodgman's clipping ("Reentrant polygon clipping", CACM 1974).
ImagePolygon clipHalf(const ImagePolygon& in, int axis, double cut, bool keepHigh) {
    auto inside = [&](const Point& p) { return keepHigh ? p[axis] >= cut : p[axis] < cut; };
    auto add = [&](ImagePolygon& out, const Point& p) { out.add(p[0], p[1]); };
    auto crossing = [&](const Point& a, const Point& b) {
        const int other = 1 - axis;
        Point r;
        r[size_t(axis)] = cut;
        r[size_t(other)] = a[other] + (cut - a[axis]) / (b[axis] - a[axis]) * (b[other] - a[other]);
        return r;
    };
    ImagePolygon out;
    if (in.n == 0) return out;
    Point prev = in.v[size_t(in.n - 1)];
    for (int i = 0; i < in.n; ++i) {
        const Point& p = in.v[size_t(i)];
        if (inside(p)) {
            if (!inside(prev)) add(out, crossing(prev, p));
            add(out, p);
        } else if (inside(prev)) {
            add(out, crossing(prev, p));
        }
        prev = p;
    }
    return out;
}

// Two axes perpendicular to unit `n` and to each other, each of length `half`.
void squareAxes(const Vec3& n, double half, Vec3& u, Vec3& v) {
    orthonormalFrame(n, u, v);
    u *= half;
    v *= half;
}

// The four corners centre -u -v, +u -v, +u +v, -u +v (a parallelogram's, in order).
int parallelogram(const Vec3& centre, const Vec3& u, const Vec3& v, std::array<Vec3, 8>& out) {
    out[0] = centre - u - v;
    out[1] = centre + u - v;
    out[2] = centre + u + v;
    out[3] = centre - u + v;
    return 4;
}

// The eight corners of the box centre +-a +-b +-c.
int box(const Vec3& centre, const Vec3& a, const Vec3& b, const Vec3& c, std::array<Vec3, 8>& out) {
    for (int i = 0; i < 8; ++i)
        out[size_t(i)] = centre + ((i & 1) ? a : -a) + ((i & 2) ? b : -b) + ((i & 4) ? c : -c);
    return 8;
}

// The corners of a flat source facing `from` (none if it faces away: RADIANCE checks
// the centre only). A 4-vertex polygon gives its own vertices (RADIANCE's parallelogram
// from vertices 0, 1 and 3, the same for a parallelogram); other polygons and rings the
// square of their area about their centre, oriented by the surface's frame (RADIANCE
// picks a random one).
int flatCorners(const SourceList& list, const DirectSource& src, const Scene& scene,
                const ShapeSet& shapes, const Vec3& from, std::array<Vec3, 8>& out) {
    Vec3 normal, u, v;
    double area = 0;
    const PlanarRegion* region = nullptr;
    if (src.light.shape == light::EmitterShape::Ring) {
        const RingShape& r = shapes.rings[size_t(src.light.shapeIndex)];
        normal = r.normal, u = r.e1, v = r.e2;
        area = kPi * r.r1 * r.r1;  // RADIANCE's ss2, the hole included
    } else {
        region = &list.regions[size_t(src.region)];
        normal = region->normal, u = region->uAxis, v = region->vAxis;
        area = region->area;
    }
    if (dot(src.centre - from, normal) >= 0) return 0;  // faces away
    if (region) {
        const std::vector<double>& xyz = scene.prims[size_t(src.light.prim)].rargs;
        if (xyz.size() == 12) {
            for (size_t k = 0; k < 4; ++k) out[k] = {xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]};
            return 4;
        }
    }
    const double half = 0.5 * std::sqrt(area);
    return parallelogram(src.centre, u * half, v * half, out);
}

// The world points whose images outline `src` (see sourceImage); 0 if none. `hull`: the
// outline is their convex hull rather than the points in order.
int sourceCorners(const SourceList& list, const DirectSource& src, const Scene& scene,
                  const ShapeSet& shapes, const View& view, std::array<Vec3, 8>& out, bool& hull) {
    const size_t i = size_t(src.light.shapeIndex);
    hull = false;
    switch (src.light.shape) {
        case light::EmitterShape::Distant: {
            if (view.type == ViewType::kParallel) return 0;  // all or nothing: the pixels see it
            const DistantSource& d = shapes.sources[i];
            // RADIANCE compat (srcsupp.c ssetsrc, srcdraw.c): its "radius" sqrt(ss2/pi);
            // from 0.05 on the pixel rays cannot miss it.
            if (std::sqrt(d.solidAngle / kPi) >= 0.05) return 0;
            Vec3 u, v;
            squareAxes(d.dir, 0.5 * std::sqrt(d.solidAngle), u, v);
            const int n = parallelogram(d.dir, u, v, out);
            // RADIANCE compat (sourcepoly): the square one unit past the fore plane.
            for (int k = 0; k < n; ++k)
                out[size_t(k)] = out[size_t(k)] * (1 + view.fore) + view.point;
            return n;
        }
        case light::EmitterShape::Polygon:
        case light::EmitterShape::Ring:
            return flatCorners(list, src, scene, shapes, view.point, out);
        case light::EmitterShape::Sphere: {
            hull = true;
            // RADIANCE compat (srcsupp.c sphsetsrc): a world-aligned cube of half side
            // 0.7236 r.
            const double h = 0.7236 * shapes.spheres[i].radius;
            return box(shapes.spheres[i].center, {h, 0, 0}, {0, h, 0}, {0, 0, h}, out);
        }
        case light::EmitterShape::Cone: {
            hull = true;
            // RADIANCE compat (srcsupp.c cylsetsrc): half the length along the axis,
            // 0.8559 r across it (RADIANCE takes no cones; the larger radius here).
            const ConeShape& c = shapes.cones[i];
            const double r = 0.8559 * std::max(c.r0, c.r1);
            return box(c.p0 + c.axis * (0.5 * c.length), c.axis * (0.5 * c.length), c.e1 * r,
                       c.e2 * r, out);
        }
    }
    return 0;
}

// Applies source value `value` (distance `dist`) over fraction `w` of pixel `px`.
void blend(Pixel& px, float* z, const Color& value, double dist, double w) {
    const Pixel v{float(value.r), float(value.g), float(value.b)};
    if (z && dist < 0.99 * *z) {
        *z = float(dist);  // the source is in front: it takes its share whatever was there
    } else if (!bigDiff(v, px, 0.01)) {
        // RADIANCE compat (srcdraw.c): the pixel ray saw the source, which lights only
        // the part w of the pixel.
        for (int c = 0; c < 3; ++c) px[c] = float(px[c] * w);
        return;
    }
    for (int c = 0; c < 3; ++c) px[c] = float(px[c] * (1 - w) + v[c] * w);
}

// Draws one source into the pixels of picture rows [rowBegin, rowEnd) its image covers.
void drawOne(const BittySource& s, const ViewRays& rays, Picture& pic, std::vector<float>* depth,
             int rowBegin, int rowEnd, const SourceRayValue& value) {
    const int xres = pic.width, yres = pic.height;
    double x0 = 1, x1 = 0, y0 = 1, y1 = 0;
    for (int k = 0; k < s.image.n; ++k) {
        x0 = std::min(x0, s.image.v[size_t(k)][0]), x1 = std::max(x1, s.image.v[size_t(k)][0]);
        y0 = std::min(y0, s.image.v[size_t(k)][1]), y1 = std::max(y1, s.image.v[size_t(k)][1]);
    }
    // Image y runs up from the bottom, picture rows down from the top.
    const int px0 = std::max(0, int(std::floor(x0 * xres)));
    const int px1 = std::min(xres - 1, int(std::ceil(x1 * xres)) - 1);
    const int py0 = std::max(yres - rowEnd, int(std::floor(y0 * yres)));
    const int py1 = std::min(yres - 1 - rowBegin, int(std::ceil(y1 * yres)) - 1);
    for (int py = py0; py <= py1; ++py)
        for (int px = px0; px <= px1; ++px) {
            // Each pixel's overlap is clipped from the whole image polygon, so that it
            // does not depend on which rows are drawn together.
            const ImagePolygon part = s.image.clip(double(px) / xres, (px + 1.0) / xres,
                                                   double(py) / yres, (py + 1.0) / yres);
            if (part.n < 3) continue;
            const double w = part.area() * xres * yres;
            if (!(w > 0)) continue;  // touches the pixel only
            const Point c = part.centre();
            const std::optional<ViewRays::Ray> ray = rays.ray(c[0], c[1]);
            if (!ray) continue;  // outside a fisheye's circle
            const int row = yres - 1 - py;
            double dist = HUGE_VAL;
            const Color v =
                value(s.source, *ray, uint64_t(row) * uint64_t(xres) + uint64_t(px), &dist);
            if (v.brightness() <= kFtiny) continue;                         // blocked or missed
            if (ray->maxDistance > 0 && dist > ray->maxDistance) continue;  // past -va
            const size_t at = size_t(row) * size_t(xres) + size_t(px);
            blend(pic.pixels[at], depth ? &(*depth)[at] : nullptr, v, dist, w);
        }
}

}  // namespace

void ImagePolygon::add(double x, double y) {
    RP_CHECK(n < kMaxVertices);
    v[size_t(n++)] = {x, y};
}

double ImagePolygon::area() const {
    double a = 0;  // the shoelace formula
    for (int i = 0, j = n - 1; i < n; j = i++)
        a += v[size_t(j)][0] * v[size_t(i)][1] - v[size_t(i)][0] * v[size_t(j)][1];
    return 0.5 * std::fabs(a);
}

std::array<double, 2> ImagePolygon::centre() const {
    Point c{0, 0};
    for (int i = 0; i < n; ++i) c[0] += v[size_t(i)][0], c[1] += v[size_t(i)][1];
    if (n > 0) c[0] /= n, c[1] /= n;
    return c;
}

ImagePolygon ImagePolygon::clip(double x0, double x1, double y0, double y1) const {
    return clipHalf(clipHalf(clipHalf(clipHalf(*this, 1, y0, true), 1, y1, false), 0, x0, true), 0,
                    x1, false);
}

double ImagePolygon::minWidth2(double aspect2) const {
    const double sy = std::sqrt(aspect2);
    double least = HUGE_VAL;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        // The polygon's extent perpendicular to edge j -> i, in x units.
        const double ex = v[size_t(i)][0] - v[size_t(j)][0];
        const double ey = (v[size_t(i)][1] - v[size_t(j)][1]) * sy;
        const double len2 = ex * ex + ey * ey;
        double most = 0;
        for (int k = 0; k < n; ++k) {
            const double h = ex * (v[size_t(k)][1] - v[size_t(j)][1]) * sy -
                             ey * (v[size_t(k)][0] - v[size_t(j)][0]);
            if (len2 > 0) most = std::max(most, h * h / len2);
        }
        least = std::min(least, most);
    }
    return least;
}

ImagePolygon convexHull(const std::array<double, 2>* points, int n) {
    std::vector<Point> p(points, points + n);
    std::sort(p.begin(), p.end());
    // Lower then upper chain; a point that does not turn left is dropped.
    auto turn = [](const Point& o, const Point& a, const Point& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<Point> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    ImagePolygon out;
    for (size_t i = 0; i + 1 < k; ++i) out.add(h[i][0], h[i][1]);
    return out;
}

bool sourceImage(const SourceList& list, const DirectSource& src, const Scene& scene,
                 const ShapeSet& shapes, const ViewRays& rays, ImagePolygon& image) {
    std::array<Vec3, 8> corners;
    bool hull = false;
    const int n = sourceCorners(list, src, scene, shapes, rays.view(), corners, hull);
    if (n == 0) return false;
    std::array<Point, 8> points;
    for (int k = 0; k < n; ++k) {
        // RADIANCE compat (sourcepoly): any corner off the image drops the whole source.
        const std::optional<ViewRays::Location> loc = rays.locate(corners[size_t(k)]);
        if (!loc || !loc->good()) return false;
        points[size_t(k)] = {loc->x, loc->y};
    }
    image = ImagePolygon{};
    if (hull) {
        image = convexHull(points.data(), n);
    } else {
        for (int k = 0; k < n; ++k) image.add(points[size_t(k)][0], points[size_t(k)][1]);
    }
    return image.n >= 3;
}

std::vector<BittySource> findBittySources(const SourceList& list, const Scene& scene,
                                          const ShapeSet& shapes, const ViewRays& rays, int xres,
                                          int yres, int sampleSpacing) {
    std::vector<BittySource> out;
    if (xres <= 0 || yres <= 0) return out;
    const int ps = std::clamp(sampleSpacing, 1, kMaxSampleSpacing);
    const ImagePlaneSize plane = imagePlaneSize(rays.view());
    const double aspect2 =
        (plane.vertical * plane.vertical) / (plane.horizontal * plane.horizontal);
    const double limit2 = double(ps) * ps / (double(xres) * xres);
    for (size_t i = 0; i < list.realCount; ++i) {
        const DirectSource& src = list.sources[i];
        if (src.light.params.kind == material::LightParams::Kind::Illum) continue;
        BittySource b;
        b.source = i;
        if (!sourceImage(list, src, scene, shapes, rays, b.image)) continue;
        b.image = b.image.clip(0, 1, 0, 1);
        if (b.image.n < 3) continue;
        if (b.image.minWidth2(aspect2) > limit2) continue;  // the pixel rays see it
        out.push_back(b);
    }
    return out;
}

void drawBittySources(const std::vector<BittySource>& sources, const ViewRays& rays,
                      Picture& picture, std::vector<float>* depth, int rowBegin, int rowEnd,
                      const SourceRayValue& value) {
    rowBegin = std::max(rowBegin, 0);
    rowEnd = std::min(rowEnd, picture.height);
    if (rowBegin >= rowEnd) return;
    for (const BittySource& s : sources) drawOne(s, rays, picture, depth, rowBegin, rowEnd, value);
}

RowsPass bittySourcePass(const Renderer& renderer, const RpictOptions& frame) {
    const Renderer* one[1] = {&renderer};
    return bittySourcePass(one, spectral::Sampling{}, frame);
}

RowsPass bittySourcePass(std::span<const Renderer* const> passes,
                         const spectral::Sampling& sampling, const RpictOptions& frame) {
    const Renderer& first = *passes[0];
    if (!first.options().direct.visibility) return {};  // -dv-: sources are not seen
    auto rays = std::make_shared<const ViewRays>(frame.view);
    const PictureSize size = pictureSize(frame);
    auto sources = std::make_shared<const std::vector<BittySource>>(
        findBittySources(first.directSources(), first.scene(), first.geometry().shapes(), *rays,
                         size.xres, size.yres, frame.sampleSpacing));
    if (sources->empty()) return {};
    // One context a pass: the pass runs on the thread that hands rows over, one call at a
    // time.
    std::vector<std::shared_ptr<Renderer::Context>> contexts;
    for (const Renderer* r : passes)
        contexts.emplace_back(r->makeContext().release(), Renderer::ContextDeleter{});
    std::vector<const Renderer*> renderers(passes.begin(), passes.end());
    SourceRayValue value = [renderers, contexts, sampling, bands = spectral::passesOf(sampling)](
                               size_t source, const ViewRays::Ray& ray, uint64_t index,
                               double* distance) {
        const Color c0 = renderers[0]->traceToSource(*contexts[0], source, ray.origin,
                                                     ray.direction, index, distance);
        if (renderers.size() == 1) return c0;
        // The same source in each pass's list, found by its surface.
        const int32_t prim = renderers[0]->directSources().sources[source].light.prim;
        double samples[spectral::kMaxSamples] = {};
        for (size_t p = 0; p < renderers.size(); ++p) {
            Color c = c0;
            if (p > 0) {
                const int32_t s = renderers[p]->directSources().sourceOfPrim[size_t(prim)];
                double ignored = 0;
                c = s < 0 ? Color{}
                          : renderers[p]->traceToSource(*contexts[p], size_t(s), ray.origin,
                                                        ray.direction, index, &ignored);
            }
            bands[p].placeBands(c, std::span<double>(samples, size_t(sampling.n)));
        }
        return spectral::toRgb(std::span<const double>(samples, size_t(sampling.n)), sampling);
    };
    return [rays, sources, value](Picture& pic, std::vector<float>* depth, int begin, int end) {
        drawBittySources(*sources, *rays, pic, depth, begin, end, value);
    };
}

}  // namespace rp::render
