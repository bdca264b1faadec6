// pcond's human-vision effects (RADIANCE's pcond4.c and scotscan): veiling glare from
// the scattering in the eye (-v), acuity loss in the dark (-a) and the mesopic/scotopic
// loss of colour (-c). Ward Larson et al. 1997, sections 5 and 6.
#include <cmath>
#include <stdexcept>

#include "image/pcond_internal.h"
#include "util/error.h"

namespace rp::pcond_detail {
namespace {

// Direction of each foveal pixel's centre through the picture's view (compraydir); zero
// outside a fisheye's circle.
void computeRayDirections(Context& c) {
    if (!c.rayDirs.empty()) return;
    c.rayDirs.assign(static_cast<size_t>(c.fvxr) * c.fvyr, {0.f, 0.f, 0.f});
    for (int y = 0; y < c.fvyr; ++y)
        for (int x = 0; x < c.fvxr; ++x) {
            // Scanline y and position x to image location (h from the left, v from the
            // bottom), in the file's orientation.
            const double along = (x + .5) / c.fvxr, across = (y + .5) / c.fvyr;
            double h, v;
            if (c.res.yMajor) {
                h = c.res.xDecreasing ? 1. - along : along;
                v = c.res.yDecreasing ? 1. - across : across;
            } else {
                h = c.res.xDecreasing ? 1. - across : across;
                v = c.res.yDecreasing ? 1. - along : along;
            }
            const std::optional<ViewRays::Ray> r = c.view->ray(h, v);
            if (!r) continue;
            c.rayDirs[static_cast<size_t>(y) * c.fvxr + x] = {static_cast<float>(r->direction.x),
                                                              static_cast<float>(r->direction.y),
                                                              static_cast<float>(r->direction.z)};
        }
}

float dotf(const std::array<float, 3>& a, const std::array<float, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Scattered light reaching foveal pixel (px, py) from all the others, weighted by
// 1/theta^2 (approximated as cos/(2(1-cos)); Holladay's glare formula), normalised.
Pixel veilAt(const Context& c, int px, int py) {
    const std::array<float, 3>& d0 = c.rayDirs[static_cast<size_t>(py) * c.fvxr + px];
    double t2sum = 0.;
    Pixel sum{0, 0, 0};
    for (int y = 0; y < c.fvyr; ++y)
        for (int x = 0; x < c.fvxr; ++x) {
            if (x == px && y == py) continue;
            double t2 = dotf(d0, c.rayDirs[static_cast<size_t>(y) * c.fvxr + x]);
            if (t2 <= kTiny) continue;
            t2 *= .5 / (1. - t2);
            for (int i = 0; i < 3; ++i) sum[i] += static_cast<float>(c.fov(x, y)[i] * t2);
            t2sum += t2;
        }
    if (t2sum > kTiny)
        for (float& v : sum) v = static_cast<float>(v * (kVeilShare / t2sum));
    return sum;
}

// Foveal-grid position of picture position t of n, and its interpolation weight.
void fovealCell(int t, int n, int cells, int& i, double& d) {
    d = (t + .5) / n * cells - .5;
    i = static_cast<int>(d);
    while (i >= cells - 1) --i;
    d -= i;
}

}  // namespace

double acuity(double la) { return 17.25 * std::atan(1.4 * std::log10(la) + 0.35) + 25.72; }

void computeVeil(Context& c) {
    if (!c.veil.empty()) return;
    computeRayDirections(c);
    c.veil.resize(c.fovea.size());
    for (int py = 0; py < c.fvyr; ++py)
        for (int px = 0; px < c.fvxr; ++px)
            c.veil[static_cast<size_t>(py) * c.fvxr + px] = veilAt(c, px, py);
    // The veil adapts the eye too: it replaces kVeilShare of each foveal sample.
    for (size_t k = 0; k < c.fovea.size(); ++k)
        for (int i = 0; i < 3; ++i)
            c.fovea[k][i] = static_cast<float>(c.fovea[k][i] * (1. - kVeilShare)) + c.veil[k][i];
    computeHistogram(c);
}

void addVeil(const Context& c, Pixel* scan, int s) {
    int vy, vx;
    double dy, dx;
    fovealCell(s, c.count, c.fvyr, vy, dy);
    auto veil = [&c](int x, int y, int i) {
        return c.veil[static_cast<size_t>(y) * c.fvxr + x][i];
    };
    for (int x = 0; x < c.len; ++x) {
        fovealCell(x, c.len, c.fvxr, vx, dx);
        for (int i = 0; i < 3; ++i) {
            const double lv = (1. - dy) * veil(vx, vy, i) + dy * veil(vx, vy + 1, i);
            const double uv = (1. - dy) * veil(vx + 1, vy, i) + dy * veil(vx + 1, vy + 1, i);
            scan[x][i] =
                static_cast<float>((1. - kVeilShare) * scan[x][i] + (1. - dx) * lv + dx * uv);
        }
    }
}

void scotopicScan(const Context& c, Pixel* scan, int n) {
    for (int i = 0; i < n; ++i) {
        const double lw = c.luminance(scan[i]);
        double inColor;  // share of photopic (colour) vision, linear over the mesopic range
        if (lw >= kTopMesopic)
            inColor = 1.;
        else if (lw <= kBottomMesopic)
            inColor = 0.;
        else
            inColor = (lw - kBottomMesopic) / (kTopMesopic - kBottomMesopic);
        if (inColor >= 1. - kTiny) continue;
        double b = (1. - inColor) * c.scotopicLuminance(scan[i]) * c.inputExposure / kScotopicWhite;
        if (!c.xyz) b /= kWhiteEfficacy;
        const float grey = static_cast<float>(b);
        for (float& v : scan[i])
            v = (inColor <= kTiny ? 0.f : static_cast<float>(v * inColor)) + grey;
    }
}

AcuitySampler::AcuitySampler(Context& c) : c_(c) {
    computeRayDirections(c);
    const int fx = c.fvxr, fy = c.fvyr;
    rates_.assign(static_cast<size_t>(fx) * fy, 0.f);
    auto rate = [this, fx](int x, int y) -> float& {
        return rates_[static_cast<size_t>(y) * fx + x];
    };
    auto dir = [&c, fx](int x, int y) { return c.rayDirs[static_cast<size_t>(y) * fx + x]; };
    double maxRate = 1.;
    for (int y = 1; y < fy - 1; ++y)
        for (int x = 1; x < fx - 1; ++x) {
            // Solid angle of one picture pixel here, from the neighbouring directions.
            Vec3 dx, dy;
            for (int i = 0; i < 3; ++i) {
                dx[i] = 0.5 * fx / c.len * static_cast<float>(dir(x + 1, y)[i] - dir(x - 1, y)[i]);
                dy[i] =
                    0.5 * fy / c.count * static_cast<float>(dir(x, y + 1)[i] - dir(x, y - 1)[i]);
            }
            const Vec3 cp = cross(dx, dy);
            const double omega = 0.5 * std::sqrt(dot(cp, cp));
            if (omega <= kTiny * kTiny) {
                rate(x, y) = 1.f;
                continue;
            }
            // Pixels per resolvable cycle.
            rate(x, y) = static_cast<float>(M_PI / 180. / std::sqrt(omega) /
                                            acuity(c.luminance(c.fov(x, y))));
            if (rate(x, y) > maxRate) maxRate = rate(x, y);
        }
    for (int x = 1; x < fx - 1; ++x) {  // the border copies its inner neighbours
        rate(x, 0) = rate(x, 1);
        rate(x, fy - 1) = rate(x, fy - 2);
    }
    for (int y = 0; y < fy; ++y) {
        rate(0, y) = rate(1, y);
        rate(fx - 1, y) = rate(fx - 2, y);
    }
    // Levels from the next power of two above the coarsest rate down to the pixels; each
    // keeps twice the scanlines of the coarser one (RADIANCE's sballoc).
    int ring = 2;
    for (int e = static_cast<int>(std::log(maxRate) / std::log(2.)) + 1; e >= 0; --e) {
        Bar b;
        b.len = c.len >> e;
        if (b.len <= 0) continue;
        b.exponent = e;
        b.ring = ring;
        b.data.resize(static_cast<size_t>(b.len) * ring);
        ring <<= 1;
        bars_.push_back(std::move(b));
    }
}

const Pixel* AcuitySampler::barLine(size_t bar, int y) {
    Bar& b = bars_[bar];
    if (y < b.read - b.ring) throw std::logic_error("pcond: acuity scanline no longer kept");
    // RADIANCE compat (getascan): every line made while catching up averages the finer
    // lines 2y and 2y+1 of the requested y.
    for (; y >= b.read; ++b.read) {
        Pixel* out = b.line(b.read);
        if (b.exponent == 0) {
            if (fileLine_ >= c_.count) throw InputError("scanline read error");
            const Pixel* in = c_.scan(fileLine_++);
            std::copy(in, in + b.len, out);
            continue;
        }
        const Pixel* l0 = barLine(bar + 1, 2 * y);
        const Pixel* l1 = barLine(bar + 1, 2 * y + 1);
        for (int i = 0; i < b.len; ++i)
            for (int k = 0; k < 3; ++k) {
                const float sum = l0[2 * i][k] + l0[2 * i + 1][k] + l1[2 * i][k] + l1[2 * i + 1][k];
                out[i][k] = static_cast<float>(sum * 0.25);
            }
    }
    return b.line(y);
}

Pixel AcuitySampler::barValue(int x, int y, size_t bar) {
    const Bar& b = bars_[bar];
    if (b.exponent == 0) return barLine(bar, y)[x];
    const double size = 1 << b.exponent;
    double dx = (x + .5) / size - .5, dy = (y + .5) / size - .5;
    int ix = static_cast<int>(dx), iy = static_cast<int>(dy);
    while (ix >= b.len - 1) --ix;
    while (iy >= (c_.count >> b.exponent) - 1) --iy;
    dx -= ix;
    dy -= iy;
    const Pixel* l0 = barLine(bar, iy);
    const Pixel* l1 = barLine(bar, iy + 1);
    Pixel col;
    for (int k = 0; k < 3; ++k) {  // bilinear, in RADIANCE's single-precision steps
        const float lo =
            static_cast<float>(l0[ix][k] * (1. - dx)) + static_cast<float>(l0[ix + 1][k] * dx);
        const float hi =
            static_cast<float>(l1[ix][k] * (1. - dx)) + static_cast<float>(l1[ix + 1][k] * dx);
        col[k] = static_cast<float>(lo * (1. - dy)) + static_cast<float>(hi * dy);
        if (col[k] < 0.f) col[k] = 0.f;
    }
    return col;
}

Pixel AcuitySampler::sample(int x, int y, double rate) {
    size_t b = 0;
    while (bars_[b].exponent != 0 && (1 << bars_[b + 1].exponent) > rate) ++b;
    Pixel col = barValue(x, y, b);
    if (bars_[b].exponent == 0) return col;  // never finer than the pixels
    const Pixel finer = barValue(x, y, b + 1);
    const double d = ((1 << bars_[b].exponent) - rate) / (1 << bars_[b + 1].exponent);
    for (int k = 0; k < 3; ++k)
        col[k] = static_cast<float>(col[k] * (1. - d)) + static_cast<float>(finer[k] * d);
    return col;
}

void AcuitySampler::scanline(Pixel* out, int s) {
    const Context& c = c_;
    int iy, ix;
    double dy, dx;
    fovealCell(s, c.count, c.fvyr, iy, dy);
    auto r = [this, &c](int x, int y) { return rates_[static_cast<size_t>(y) * c.fvxr + x]; };
    for (int x = 0; x < c.len; ++x) {
        fovealCell(x, c.len, c.fvxr, ix, dx);
        const double rate = (1. - dy) * ((1. - dx) * r(ix, iy) + dx * r(ix + 1, iy)) +
                            dy * ((1. - dx) * r(ix, iy + 1) + dx * r(ix + 1, iy + 1));
        out[x] = sample(x, s, rate);
    }
}

}  // namespace rp::pcond_detail
