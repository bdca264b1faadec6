// pfilt's filters (see pfilt_filter.h). Sizes follow RADIANCE's pfilt so that outputs
// agree pixel for pixel: each output pixel has a centre input pixel
// (int)((c + .5) * xres / ncols); the box averages the input pixels whose centres fall
// in the output pixel; the Gaussian weighs a window of 2 radii with exp(-r^2) looked up
// in steps of 0.05 in r^2, flat inside the output pixel's own area.
#include "image/pfilt_filter.h"

#include <algorithm>
#include <cmath>

namespace rp {
namespace {

constexpr double kCheckRadius = 2.0;    // filter window, in radii
constexpr double kSpreadRadius = 5.0;   // threshold filter: widest spread, in radii
constexpr double kSquareRadius = 1.13;  // sqrt(4/pi): radius of a unit square's area
constexpr double kThresholdGoal = 0.2;
constexpr double kRadiusGoal = 0.1;
constexpr double kTiny = 1e-6;

// i modulo n in [0, n): columns around a 360-degree panorama.
int wrapIndex(int i, int n) { return ((i % n) + n) % n; }

// exp(-r2) for r2 in steps of 0.05, flat at exp(-plateau) for r2 <= plateau.
struct GaussTable {
    std::vector<float> v;
    GaussTable(double plateau) : v(static_cast<size_t>(444 * kCheckRadius * kCheckRadius)) {
        for (size_t i = 0; i < v.size(); ++i)
            v[i] = static_cast<float>(i * 0.05 <= plateau ? std::exp(-plateau)
                                                          : std::exp(-(i * 0.05)));
        v[0] = static_cast<float>(std::exp(-plateau));
    }
    double operator()(double r2) const {
        const size_t i = static_cast<size_t>(20. * r2 + .5);
        return i < v.size() ? v[i] : v.back();
    }
};

class Filter {
public:
    Filter(const Picture& in, const PfiltFrame& f) : in_(in), f_(f) {
        xbox_ = f.xres / f.ncols / 2 + 1;
        ybox_ = f.yres / f.nrows / 2 + 1;
    }
    int xCentre(int c) const { return static_cast<int>((c + .5) * f_.xres / f_.ncols); }
    int yCentre(int r) const { return static_cast<int>((r + .5) * f_.yres / f_.nrows); }

    // Input column x wrapped around a 360-degree panorama (-1 when outside, not wrapping).
    int column(int x) const {
        if (x >= 0 && x < f_.xres) return x;
        if (!f_.wrap) return -1;
        return wrapIndex(x, f_.xres);
    }

    // Calls visit(x, y, column) for each input pixel of output pixel (c, r)'s box: x may
    // lie beyond the picture's sides when the filter wraps, column is its pixel.
    template <class Visit>
    void forBox(int c, int r, Visit visit) const {
        const int xc = xCentre(c), yc = yCentre(r);
        for (int y = yc + 1 - ybox_; y <= yc + ybox_; ++y) {
            if (y < 0) continue;
            if (y >= f_.yres) break;
            const double dy = f_.yRatio < 1 ? f_.yRatio * y - (r + .5) : double(y - yc);
            if (dy < -0.5) continue;
            if (dy >= 0.5) break;
            for (int x = xc + 1 - xbox_; x <= xc + xbox_; ++x) {
                const int col = column(x);
                if (col < 0) continue;
                const double dx = f_.xRatio < 1 ? f_.xRatio * x - (c + .5) : double(x - xc);
                if (dx < -0.5) continue;
                if (dx >= 0.5) break;
                visit(x, y, col);
            }
        }
    }

    Pixel box(int c, int r) const {
        Pixel sum{0, 0, 0};
        int n = 0;
        forBox(c, r, [&](int, int y, int col) {
            const Pixel& p = in_.at(col, y);
            for (int k = 0; k < 3; ++k) sum[k] += p[k];
            ++n;
        });
        if (n > 1)
            for (float& s : sum) s = static_cast<float>(s * (1.0 / n));
        return sum;
    }

    Picture boxPicture() const {
        Picture out(f_.ncols, f_.nrows);
        for (int r = 0; r < f_.nrows; ++r)
            for (int c = 0; c < f_.ncols; ++c) out.at(c, r) = box(c, r);
        return out;
    }

    Picture gaussPicture(double rad) const {
        const GaussTable g(f_.xRatio * f_.yRatio * 0.25 / (rad * rad));
        const int xrad = static_cast<int>(kCheckRadius * rad / f_.xRatio + 1);
        const int yrad = static_cast<int>(kCheckRadius * rad / f_.yRatio + 1);
        Picture out(f_.ncols, f_.nrows);
        for (int r = 0; r < f_.nrows; ++r)
            for (int c = 0; c < f_.ncols; ++c) {
                const int xc = xCentre(c), yc = yCentre(r);
                double sum[3] = {0, 0, 0}, wsum = kTiny;
                for (int y = std::max(0, yc - yrad); y <= yc + yrad && y < f_.yres; ++y) {
                    const double dy = (f_.yRatio * (y + .5) - (r + .5)) / rad;
                    for (int x = xc - xrad; x <= xc + xrad; ++x) {
                        const int col = column(x);
                        if (col < 0) continue;
                        const double dx = (f_.xRatio * (x + .5) - (c + .5)) / rad;
                        const double w = g(dx * dx + dy * dy);
                        wsum += w;
                        const Pixel& p = in_.at(col, y);
                        for (int k = 0; k < 3; ++k) sum[k] += static_cast<float>(p[k] * w);
                    }
                }
                for (int k = 0; k < 3; ++k) out.at(c, r)[k] = static_cast<float>(sum[k] / wsum);
            }
        return out;
    }

    Picture thresholdPicture(double rad) const;

private:
    const Picture& in_;
    const PfiltFrame& f_;
    int xbox_ = 1, ybox_ = 1;
};

// The threshold filter: each input pixel is spread over the output with a Gaussian whose
// radius m * rad grows (m in [1, orad / rad / 2]) until the pixel's contrast to the ring
// average around its output pixel, weighed by the Gaussian's peak, is near the limit.
Picture Filter::thresholdPicture(double rad) const {
    const int orad = static_cast<int>(kCheckRadius * kSpreadRadius * rad + 1);
    const double plateau = f_.xRatio * f_.yRatio * 0.25 / (rad * rad);
    GaussTable g(plateau);
    double integral = M_PI * plateau * std::exp(-plateau);
    for (double d = std::sqrt(plateau) + 0.05; d <= kSquareRadius * kCheckRadius; d += 0.1)
        integral += 0.1 * 2.0 * M_PI * d * std::exp(-d * d);
    const double norm = f_.xRatio * f_.yRatio / (rad * rad * integral);
    for (float& v : g.v) v = static_cast<float>(v * norm);
    // Ring of each squared offset (-1 beyond orad).
    std::vector<int> ring(static_cast<size_t>(2 * orad * orad + 1), -1);
    for (int k = 0; k <= orad * orad; ++k) ring[k] = static_cast<int>(std::sqrt(double(k)));

    // Brightness of the box-filtered output. RADIANCE's pfilt reads its input through a
    // ring of 2 * yrad + 1 scanlines and box-filters output row R when it reaches row
    // R - orad, when the input is read only to row ycent + yrad; where the ratio is not
    // whole, R's box can reach one row further, and gets what the ring holds there (the
    // row barsize above, or zeros before any). We do the same so outputs agree.
    const int yrad = static_cast<int>(orad / f_.yRatio + ybox_);
    const int barsize = 2 * yrad + 1;
    std::vector<float> grey(static_cast<size_t>(f_.ncols) * f_.nrows);
    for (int r = 0; r < f_.nrows; ++r) {
        const int lastRead = yCentre(std::max(0, r - orad)) + yrad;
        for (int c = 0; c < f_.ncols; ++c) {
            Pixel sum{0, 0, 0};
            int n = 0;
            forBox(c, r, [&](int, int y, int col) {
                int row = y;
                while (row > lastRead) row -= barsize;
                if (row >= 0) {
                    const Pixel& p = in_.at(col, row);
                    for (int k = 0; k < 3; ++k) sum[k] += p[k];
                }
                ++n;
            });
            if (n > 1)
                for (float& v : sum) v = static_cast<float>(v * (1.0 / n));
            grey[size_t(r) * f_.ncols + c] = static_cast<float>(f_.brightness(sum));
        }
    }

    Picture out(f_.ncols, f_.nrows);
    std::vector<float> ringSum(orad + 1);
    std::vector<int> ringCount(orad + 1);
    std::vector<float> weights;
    for (int rc = 0; rc < f_.nrows; ++rc)
        for (int cc = 0; cc < f_.ncols; ++cc) {
            std::fill(ringSum.begin(), ringSum.end(), 0.f);
            std::fill(ringCount.begin(), ringCount.end(), 0);
            for (int r = -orad; r <= orad; ++r) {
                if (rc + r < 0) continue;
                if (rc + r >= f_.nrows) break;
                for (int c = -orad; c <= orad; ++c) {
                    int oc = cc + c;
                    if (oc < 0 || oc >= f_.ncols) {
                        if (!f_.wrap) continue;
                        oc = wrapIndex(oc, f_.ncols);
                    }
                    const int k = ring[c * c + r * r];
                    if (k < 0) continue;
                    ringSum[k] += grey[size_t(rc + r) * f_.ncols + oc];
                    ++ringCount[k];
                }
            }
            // The multiplier of the Gaussian radius for a pixel of brightness p0.
            auto pick = [&](double p0) {
                double m = 1.0;
                double lo = 1.0, hi = orad / rad / kCheckRadius;
                for (int iter = static_cast<int>(4.0 / kThresholdGoal); iter > 0; --iter) {
                    int i = std::min(orad,
                                     static_cast<int>(kSquareRadius * kCheckRadius * rad * m + .5));
                    double avg = 0, wsum = 0;
                    while (i--) {
                        double t = (i + .5) / (m * rad);
                        t = g(t * t);
                        avg += t * ringSum[i];
                        wsum += t * ringCount[i];
                    }
                    if (avg < 1e-20) return 1.0;
                    avg /= wsum;
                    const double denom = m * m / g.v[0] - p0 / avg;
                    if (denom <= kTiny) {
                        if (m >= hi - kRadiusGoal) break;
                        m = hi;
                        continue;
                    }
                    const double num = std::abs(p0 / avg - 1.0);
                    const double t = num / denom;
                    if (t <= f_.threshold) {
                        if (m <= lo + kRadiusGoal ||
                            (f_.threshold - t) / f_.threshold <= kThresholdGoal)
                            break;
                    } else if (m >= hi - kRadiusGoal ||
                               (t - f_.threshold) / f_.threshold <= kThresholdGoal) {
                        break;
                    }
                    const double prev = m;
                    m = std::sqrt(g.v[0] * (num / f_.threshold + p0 / avg));
                    if (m < prev) {
                        if (m <= lo + kTiny) m = 0.5 * (lo + prev);
                        hi = prev;
                    } else {
                        if (m >= hi - kTiny) m = 0.5 * (hi + prev);
                        lo = prev;
                    }
                }
                return m;
            };
            forBox(cc, rc, [&](int px, int py, int col) {
                const Pixel& pv = in_.at(col, py);
                const double m = pick(f_.brightness(pv));
                const double pc = f_.xRatio * (px + .5), pr = f_.yRatio * (py + .5);
                const int ksize = std::min(orad, static_cast<int>(kCheckRadius * m * rad + 1));
                const int r0 = std::max(0, rc - ksize), r1 = std::min(f_.nrows - 1, rc + ksize);
                const int c0 = f_.wrap ? cc - ksize : std::max(0, cc - ksize);
                const int c1 = f_.wrap ? cc + ksize : std::min(f_.ncols - 1, cc + ksize);
                weights.clear();
                double sum = 0;
                for (int r = r0; r <= r1; ++r) {
                    double dy2 = (pr - (r + .5)) / (m * rad);
                    dy2 *= dy2;
                    for (int c = c0; c <= c1; ++c) {
                        const double dx = (pc - (c + .5)) / (m * rad);
                        weights.push_back(static_cast<float>(g(dx * dx + dy2)));
                        sum += weights.back();
                    }
                }
                double scale = 1.0 / sum;
                if (f_.xRatio < 1.0) scale *= f_.xRatio;
                if (f_.yRatio < 1.0) scale *= f_.yRatio;
                size_t i = 0;
                for (int r = r0; r <= r1; ++r)
                    for (int c = c0; c <= c1; ++c) {
                        const double w = scale * weights[i++];
                        Pixel& o = out.at(wrapIndex(c, f_.ncols), r);
                        for (int k = 0; k < 3; ++k) o[k] += static_cast<float>(pv[k] * w);
                    }
            });
        }
    return out;
}

}  // namespace

void addStarPoints(Picture& pic, const std::vector<HotPixel>& hot, double spreadFactor) {
    for (int y = 0; y < pic.height; ++y)
        for (auto h = hot.rbegin(); h != hot.rend(); ++h) {
            int xmin, xmax;
            if (h->slope > kTiny) {
                xmin = static_cast<int>((y - h->y - 0.5) / h->slope + h->x);
                xmax = static_cast<int>((y - h->y + 0.5) / h->slope + h->x);
            } else if (h->slope < -kTiny) {
                xmin = static_cast<int>((y - h->y + 0.5) / h->slope + h->x);
                xmax = static_cast<int>((y - h->y - 0.5) / h->slope + h->x);
            } else if (y == h->y) {
                xmin = 0;
                xmax = pic.width - 1;
            } else {
                continue;
            }
            xmin = std::max(xmin, 0);
            xmax = std::min(xmax, pic.width - 1);
            for (int x = xmin; x <= xmax; ++x) {
                const double d2 = double(x - h->x) * (x - h->x) + double(y - h->y) * (y - h->y);
                Pixel& p = pic.at(x, y);
                if (d2 > spreadFactor) {
                    const double s = spreadFactor / d2;
                    if (s < kTiny) continue;
                    for (int k = 0; k < 3; ++k) p[k] += static_cast<float>(h->value[k] * s);
                } else if (d2 > kTiny) {
                    for (int k = 0; k < 3; ++k) p[k] += h->value[k];
                }
            }
        }
}

Picture filterPicture(const Picture& in, const PfiltFrame& frame) {
    PfiltFrame f = frame;
    if (f.radius > kTiny && f.nrows >= f.yres && f.ncols >= f.xres)
        f.radius *= (f.yRatio + f.xRatio) / 2.0;  // magnifying: radius in input pixels
    const Filter filter(in, f);
    if (f.threshold > kTiny) return filter.thresholdPicture(f.radius);
    if (f.radius > kTiny) return filter.gaussPicture(f.radius);
    return filter.boxPicture();
}

}  // namespace rp
