// See vwrays.h.
#include "rays/vwrays.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <ostream>
#include <vector>

#include "render/rpict_options.h"
#include "util/error.h"
#include "util/rng.h"

namespace rp::rays {

namespace {

constexpr double kTiny = 1e-6;  // RADIANCE's FTINY

// The command line's view with the picture's view lines applied on top (RADIANCE's
// viewfile), and the picture's resolution.
View viewOf(const VwraysOptions& o, Resolution* res) {
    View v = o.view;
    if (o.picture.empty()) return v;
    std::ifstream in(o.picture, std::ios::binary);
    if (!in) throw InputError(o.picture + ": cannot open");
    const PictureInfo info = readPictureInfo(in, o.picture);
    int n = 0;
    for (const std::string& line : info.header.lines)
        if (isViewLine(line)) n += applyViewString(v, line);
    if (n == 0) throw InputError(o.picture + ": no view in picture");
    *res = info.resolution;
    return v;
}

Resolution resolutionOf(const VwraysOptions& o) {
    if (!o.picture.empty()) return {};
    render::RpictOptions r;
    r.view = o.view;
    r.xres = o.xres;
    r.yres = o.yres;
    r.pixelAspect = o.pixelAspect;
    const render::PictureSize s = render::pictureSize(r);
    Resolution res;
    res.xres = s.xres;
    res.yres = s.yres;
    return res;
}

// Opens the depth buffer of an xres by yres picture: one float per pixel, no more, no less.
void openDepth(std::ifstream& depth, const std::string& path, const Resolution& res) {
    depth.open(path, std::ios::binary | std::ios::ate);
    if (!depth) throw InputError(path + ": cannot open");
    const int64_t expected = int64_t(res.xres) * res.yres;
    const int64_t actual = int64_t(depth.tellg()) / int64_t(sizeof(float));
    if (actual != expected)
        throw InputError(path + ": expected length is " + std::to_string(expected) +
                         ", actual length is " + std::to_string(actual));
    depth.seekg(0);
}

}  // namespace

Vwrays::Vwrays(const VwraysOptions& options)
    : opt_(options), res_(resolutionOf(options)), rays_(viewOf(options, &res_)) {
    params_.jitter = opt_.jitter;
    params_.aperture = opt_.aperture;
}

std::string Vwrays::dimensionsLine() const {
    // RADIANCE compat (vwrays.c): "-ld+" only for a picture given without a depth buffer
    // whose view has an aft plane; a view from options always gets "-ld-".
    const bool aft = !opt_.picture.empty() && opt_.depthFile.empty() && rays_.view().aft > kTiny;
    return "-x " + std::to_string(res_.xres) + " -y " + std::to_string(res_.yres) + " -ld" +
           (aft ? '+' : '-');
}

std::optional<ViewRays::Ray> Vwrays::jittered(double x, double y, uint64_t seed,
                                              uint64_t index) const {
    // render::pixelRay's recipe and stream use (pixel jitter, an unused motion-blur draw,
    // the aperture), so that seed 0 at a pixel gives rpict's ray (vwrays_test.cpp).
    Rng rng(seed, RngDomain::Pixel, index);
    const double jx = 0.5 + params_.jitter * (0.5 - rng.uniform());
    const double jy = 0.5 + params_.jitter * (0.5 - rng.uniform());
    auto ray = rays_.ray((x + jx) / res_.xres, (y + jy) / res_.yres);
    if (!ray) return ray;
    (void)rng.uniform();
    const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
    if (!rays_.jitterAperture(*ray, params_.aperture, u1, u2, u3)) return std::nullopt;
    return ray;
}

void Vwrays::put(std::ostream& out, const std::optional<ViewRays::Ray>& r, double z,
                 bool depthScalesDirection) const {
    double v[6] = {0, 0, 0, 0, 0, 0};
    if (r) {
        for (int i = 0; i < 3; ++i) {
            v[i] = r->origin[i];
            v[3 + i] = r->direction[i];
        }
        if (z >= 0 && depthScalesDirection) {
            // RADIANCE compat (vwrays.c putrays): the reversed direction keeps the depth
            // as its length; from -i positions (pix2rays) it is unit length.
            for (int i = 0; i < 3; ++i) {
                v[3 + i] = -v[3 + i] * z;
                v[i] -= v[3 + i];
            }
        } else if (z >= 0) {
            for (int i = 0; i < 3; ++i) {
                v[i] += v[3 + i] * z;
                v[3 + i] = -v[3 + i];
            }
        } else if (r->maxDistance > kTiny) {
            // The aft plane's distance as the direction's length (rtrace -ld+).
            for (int i = 3; i < 6; ++i) v[i] *= r->maxDistance;
        }
    }
    if (opt_.format == 'a') {
        char buf[128];
        const int n = std::snprintf(buf, sizeof buf, "%.5e %.5e %.5e %.5e %.5e %.5e\n", v[0], v[1],
                                    v[2], v[3], v[4], v[5]);
        out.write(buf, n);
    } else if (opt_.format == 'f') {
        float f[6];
        for (int i = 0; i < 6; ++i) f[i] = float(v[i]);
        out.write(reinterpret_cast<const char*>(f), sizeof f);
    } else {
        out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
}

void Vwrays::writeAll(std::ostream& out) const {
    const int scanlen = res_.scanlineLength(), nscans = res_.scanlineCount();
    std::ifstream depth;
    std::vector<float> z(size_t(scanlen), -1.0f);
    if (!opt_.depthFile.empty()) openDepth(depth, opt_.depthFile, res_);
    for (int sc = 0; sc < nscans; ++sc) {
        if (depth.is_open() &&
            !depth.read(reinterpret_cast<char*>(z.data()), std::streamsize(z.size() * 4)))
            throw InputError(opt_.depthFile + ": depth buffer read error");
        for (int si = 0; si < scanlen; ++si) {
            // The picture's scanline order to image x (from the left), y (from the bottom).
            int x = res_.yMajor ? si : sc, y = res_.yMajor ? sc : si;
            if (res_.xDecreasing) x = res_.xres - 1 - x;
            if (res_.yDecreasing) y = res_.yres - 1 - y;
            const int row = res_.yres - 1 - y;
            const uint64_t index = uint64_t(row) * uint64_t(res_.xres) + uint64_t(x);
            for (int c = 0; c < opt_.repeat; ++c) {
                // The first ray of a pixel is rpict's; repeats draw from streams of their own.
                const auto r =
                    c == 0 ? render::pixelRay(rays_, nullptr, params_, x, row, res_.xres, res_.yres)
                           : jittered(x, y, uint64_t(c), index);
                put(out, r, depth.is_open() ? double(z[size_t(si)]) : -1.0, true);
            }
        }
    }
}

void Vwrays::writeFromInput(std::istream& in, std::ostream& out) const {
    std::ifstream depth;
    if (!opt_.depthFile.empty()) openDepth(depth, opt_.depthFile, res_);
    uint64_t index = 0;
    double px = 0, py = 0;
    while (in >> px >> py) {
        double z = -1;
        if (depth.is_open()) {
            const double lx = (px + .5) / res_.xres, ly = (py + .5) / res_.yres;
            if (lx < 0 || lx >= 1 || ly < 0 || ly >= 1)
                throw InputError("input pixel outside image");
            // Image location to the picture's scanline and position on it. RADIANCE compat
            // (loc2pix after pix2rays' half-pixel shift): rounding makes this the pixel up
            // and right of the one the ray goes through.
            int x = int(lx * res_.xres + .5 - (lx < 0)), y = int(ly * res_.yres + .5 - (ly < 0));
            if (res_.xDecreasing) x = res_.xres - 1 - x;
            if (res_.yDecreasing) y = res_.yres - 1 - y;
            const int si = res_.yMajor ? x : y, sc = res_.yMajor ? y : x;
            const int64_t at = int64_t(sc) * res_.scanlineLength() + si;
            if (at < 0) throw InputError(opt_.depthFile + ": depth buffer read error");
            float zv = 0;
            depth.clear();
            depth.seekg(std::streamoff(at * 4));
            if (!depth.read(reinterpret_cast<char*>(&zv), 4))
                throw InputError(opt_.depthFile + ": depth buffer read error");
            z = zv;
        }
        for (int c = 0; c < opt_.repeat; ++c)
            put(out, jittered(px, py, uint64_t(c), index), z, false);
        ++index;
        if (opt_.unbuffered) out.flush();
    }
    if (!in.eof()) throw InputError("expected px py on input");
}

}  // namespace rp::rays
