#include "material/chain_pict.h"

#include <cmath>

#include "image/picture.h"
#include "image/spectral_picture.h"
#include "util/error.h"

namespace rp::material {

namespace {

// One axis of RADIANCE's datavalue: the lower node index and the fractional position x
// (in node units, may lie outside [i, i+1] when extrapolating).
struct AxisPos {
    int i = 0;
    double x = 0;
};

AxisPos axisPos(double coord, double size, int count) {
    AxisPos a;
    a.x = coord / size * double(count - 1);
    double fi = std::floor(a.x);
    // RADIANCE truncates towards zero ((int)x); both give 0 for small negatives, and
    // the clamp below makes them agree everywhere else.
    a.i = fi < 0 ? 0 : (fi > count - 2 ? count - 2 : int(fi));
    if (a.x < 0) a.i = 0;
    return a;
}

// Linear in [i, i+1], linear for one more division outside, then harmonic taper.
double blend(double y0, double y1, const AxisPos& a) {
    int i = a.i;
    double x = a.x;
    if (x > i + 2) return (2 * y1 - y0) / (x - (i - 1));
    if (x < i - 1) return (2 * y0 - y1) / (i - x);
    return y0 * ((i + 1) - x) + y1 * (x - i);
}

}  // namespace

void PictTable::setSize(int width, int height, double pixelAspect) {
    width_ = width;
    height_ = height;
    // ray.html, Colorpict: the smaller dimension spans 1, the other the ratio (pixel
    // aspect = pixel height / width stretches v); getspec sizes spectral pictures alike.
    if (width <= height * pixelAspect) {
        uSize_ = 1;
        vSize_ = pixelAspect * height / width;
    } else {
        vSize_ = 1;
        uSize_ = double(width) / height / pixelAspect;
    }
}

PictTable PictTable::fromPixels(int width, int height, const std::vector<Color>& topFirst,
                                double pixelAspect) {
    RP_CHECK(width > 0 && height > 0 && topFirst.size() == size_t(width) * height);
    PictTable t;
    t.setSize(width, height, pixelAspect);
    t.bottomFirst_.resize(topFirst.size() * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                t.bottomFirst_[(size_t(height - 1 - y) * width + x) * 3 + size_t(c)] =
                    topFirst[size_t(y) * width + x][c];
    return t;
}

PictTable PictTable::loadSpectral(const std::string& path) {
    const SpectralPicture pic = readSpectralPicture(path);
    if (pic.sampling.n <= 3) throw InputError(path + ": not a spectral picture (NCOMP <= 3)");
    const double aspect = pic.pixelAspect();
    if (!(aspect > 1e-6)) throw InputError(path + ": bad PIXASPECT in picture");
    const int w = pic.width, h = pic.height, n = pic.sampling.n;
    PictTable t;
    t.setSize(w, h, aspect);
    t.channels_ = n;
    t.sampling_ = pic.sampling;
    t.bottomFirst_.resize(size_t(w) * h * n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto px = pic.at(x, y);
            std::copy(px.begin(), px.end(),
                      t.bottomFirst_.begin() + std::ptrdiff_t((size_t(h - 1 - y) * w + x) * n));
        }
    return t;
}

PictTable PictTable::load(const std::string& path) {
    Picture pic = readPicture(path);
    std::vector<Color> px(pic.pixels.size());
    for (size_t i = 0; i < px.size(); ++i)
        px[i] = Color(pic.pixels[i][0], pic.pixels[i][1], pic.pixels[i][2]);
    double aspect = pic.pixelAspect();
    if (!(aspect > 1e-6)) throw InputError(path + ": bad PIXASPECT in picture");
    return fromPixels(pic.width, pic.height, px, aspect);
}

Color PictTable::value(double u, double v) const {
    RP_CHECK(channels_ == 3);
    double c[3];
    values(u, v, std::span<double>(c, 3));
    return {c[0], c[1], c[2]};
}

void PictTable::values(double u, double v, std::span<double> out) const {
    const size_t n = size_t(channels_);
    RP_CHECK(out.size() == n);
    auto at = [&](int x, int y, size_t c) {
        return bottomFirst_[(size_t(y) * width_ + x) * n + c];
    };
    // A single row or column has nothing to interpolate along that axis.
    if (width_ == 1 && height_ == 1) {
        for (size_t c = 0; c < n; ++c) out[c] = at(0, 0, c);
        return;
    }
    if (height_ == 1) {
        AxisPos a = axisPos(u, uSize_, width_);
        for (size_t c = 0; c < n; ++c) out[c] = blend(at(a.i, 0, c), at(a.i + 1, 0, c), a);
        return;
    }
    AxisPos av = axisPos(v, vSize_, height_);
    if (width_ == 1) {
        for (size_t c = 0; c < n; ++c) out[c] = blend(at(0, av.i, c), at(0, av.i + 1, c), av);
        return;
    }
    // RADIANCE interpolates along the rows first (the last dimension, u), then along v.
    AxisPos au = axisPos(u, uSize_, width_);
    for (size_t c = 0; c < n; ++c) {
        double lo = blend(at(au.i, av.i, c), at(au.i + 1, av.i, c), au);
        double hi = blend(at(au.i, av.i + 1, c), at(au.i + 1, av.i + 1, c), au);
        out[c] = blend(lo, hi, av);
    }
}

}  // namespace rp::material
