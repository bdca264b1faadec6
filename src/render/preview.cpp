#include "render/preview.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "material/type_traits.h"

namespace rp {

Pixel previewColour(const Scene& scene, int32_t modifier) {
    const Pixel grey{0.5f, 0.5f, 0.5f};
    if (modifier == kVoid) return grey;
    const Primitive& m = scene.prims[modifier];
    if (m.rargs.size() < 3) return grey;
    Pixel c{float(m.rargs[0]), float(m.rargs[1]), float(m.rargs[2])};
    auto [r, g, b] = c;
    switch (material::typeTraits(m.type).preview) {
        case material::TypeTraits::Preview::Emitter: {
            // Emitters show as white-ish, keeping their colour balance.
            float mx = std::max({r, g, b});
            return mx > 0 ? Pixel{r / mx, g / mx, b / mx} : grey;
        }
        case material::TypeTraits::Preview::Reflectance:
            return c;
        case material::TypeTraits::Preview::Grey:
            return grey;
    }
    return grey;
}

Picture renderPreview(const Scene& scene, const SceneGeometry& geometry,
                      const PreviewOptions& options, PreviewStats* stats) {
    ViewRays rays(options.view);
    // Keep the view's aspect ratio inside xres x yres (RADIANCE's normaspect, -pa 1).
    double va = options.view.vertical, ha = options.view.horizontal;
    double aspect = 1.0;
    if (options.view.type == ViewType::kPerspective)
        aspect = std::tan(va * kPi / 360) / std::tan(ha * kPi / 360);
    else if (options.view.type == ViewType::kParallel)
        aspect = va / ha;
    int xres = options.xres, yres = options.yres;
    if (aspect * xres > yres)
        xres = std::max(1, int(std::lround(yres / aspect)));
    else
        yres = std::max(1, int(std::lround(xres * aspect)));

    Picture pic(xres, yres);
    std::atomic<long> hits{0};
    auto start = std::chrono::steady_clock::now();
    tbb::parallel_for(tbb::blocked_range<int>(0, yres), [&](const tbb::blocked_range<int>& r) {
        long localHits = 0;
        for (int y = r.begin(); y < r.end(); ++y) {
            for (int x = 0; x < xres; ++x) {
                // Picture rows run top to bottom; view y runs bottom to top.
                auto vr = rays.ray((x + 0.5) / xres, 1.0 - (y + 0.5) / yres);
                Pixel& px = pic.at(x, y);
                px = Pixel{0, 0, 0};
                if (!vr) continue;
                Ray ray{vr->origin, vr->direction,
                        vr->maxDistance > 0 ? vr->maxDistance : HUGE_VAL};
                auto hit = geometry.closestHit(ray);
                if (!hit) continue;
                ++localHits;
                double cosine = std::fabs(dot(hit->normal, ray.dir));
                float shade = float(0.25 + 0.75 * cosine);
                Pixel c = previewColour(scene, hit->modifier);
                px = Pixel{c[0] * shade, c[1] * shade, c[2] * shade};
            }
        }
        hits += localHits;
    });
    if (stats) {
        stats->rays = long(xres) * yres;
        stats->hits = hits;
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    pic.header.lines.push_back(viewHeaderLine(options.view));
    return pic;
}

}  // namespace rp
