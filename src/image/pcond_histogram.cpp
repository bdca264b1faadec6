// pcond's adaptation histogram and brightness map (RADIANCE's pcond3.c and getfovimg):
// the foveal image, random pixel samples, precomputed histograms and fixation points,
// the histogram adjustment of Ward Larson et al. 1997 (section 4: the cumulative
// distribution, clipped so that no brightness range gains contrast beyond the linear
// map's, or the human threshold's with -s) and its application to scanlines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <istream>
#include <ostream>

#include "image/pcond_internal.h"
#include "image/pfilt.h"
#include "util/error.h"

namespace rp::pcond_detail {
namespace {

constexpr double kClipShare = 0.025;    // share of samples allowed above the envelope (CVRATIO)
constexpr int kMaxPreHistogram = 1024;  // longest -I histogram (MAXPREHIST)

// Adds brightness b with weight w to the histogram and its mean, when inside its limits.
void addSample(Histogram& h, double lum, double lwmin, double lwmax, double w) {
    if (lum < lwmin + kTiny || lum >= lwmax - kTiny) return;
    const double b = brightness(lum);
    h.bwavg += w * b;
    h.counts[h.bin(b)] += w;
    h.total += w;
}

// RADIANCE compat (getlumsamp): n pixels drawn without replacement as the scanlines go
// by, each skip drawn with frandom(); the samples are stored last to first.
std::vector<float> luminanceSamples(Context& c, int n) {
    std::vector<float> samples(n);
    long pixelsLeft = static_cast<long>(c.len) * c.count;
    int s = -1, x = 0;
    while (n > 0) {
        if (x <= 0) {
            if (++s >= c.count) throw InputError("scanline read error");
            x = c.len;
        }
        const double r = c.random.next();
        int skip = 0;
        double cumulative = 0;
        while ((cumulative += (1. - cumulative) * n / (pixelsLeft - skip)) < r) ++skip;
        if (x < ++skip) {  // past the end of this scanline
            pixelsLeft -= x;
            x = 0;
            continue;
        }
        x -= skip;
        samples[--n] = static_cast<float>(c.luminance(c.scan(s)[x]));
        pixelsLeft -= skip;
    }
    return samples;
}

// Paraboloid weight, 0 at 90 degrees from the centre (a 180-degree fisheye's foveal image
// is 180 wide).
double centerWeight(const Context& c, int x, int y) {
    const double xr = (x - .5 * (c.fvxr - 1)) / 90., yr = (y - .5 * (c.fvyr - 1)) / 90.;
    const double p = 1. - xr * xr - yr * yr;
    return p < 0. ? 0. : p;
}

// Foveal position of picture position (x, y) (RADIANCE's loc2pix on the foveal size).
std::array<int, 2> fovealPosition(const Context& c, int px, int py) {
    const int xr = c.res.yMajor ? c.fvxr : c.fvyr, yr = c.res.yMajor ? c.fvyr : c.fvxr;
    const double lx = (px + .5) / c.res.xres, ly = (py + .5) / c.res.yres;
    int x = static_cast<int>(lx * xr + .5 - (lx < 0.0));
    int y = static_cast<int>(ly * yr + .5 - (ly < 0.0));
    if (c.res.xDecreasing) x = xr - 1 - x;
    if (c.res.yDecreasing) y = yr - 1 - y;
    return c.res.yMajor ? std::array<int, 2>{x, y} : std::array<int, 2>{y, x};
}

// Threshold ratio between display and world at world luminance lw (the slope limit).
double thresholdRatio(const Context& c, double lw, double blw) {
    return c.what.sensitivity ? contrastThreshold(luminanceOf(blw)) / contrastThreshold(lw)
                              : luminanceOf(blw) / lw;
}

// The histogram ceiling at world luminance lw, per unit of Tdb (clampf).
double clampFactor(const Context& c, double lw) {
    const double blw = displayBrightness(c, lw);
    // Brightness is a log: its derivative is 1/L, the inverse's is L.
    return thresholdRatio(c, lw, blw) / (luminanceOf(blw) * (c.bldmax - c.bldmin) / lw);
}

void makeCumulative(BrightnessMap& m) {
    m.total = 0;
    for (double v : m.counts) m.total += v;
    double sum = 0;
    for (int i = 0; i < kHistRes; ++i) {
        m.cumulative[i] = sum / m.total;
        sum += m.counts[i];
    }
    m.cumulative[kHistRes] = 1.;
}

}  // namespace

double Context::luminance(const Pixel& c) const {
    if (xyz) return c[1] / inputExposure;
    // RADIANCE compat: rgblum sums in single precision (COLOR times COLORMAT).
    const float y = c[0] * rgbToXyz[1][0] + c[1] * rgbToXyz[1][1] + c[2] * rgbToXyz[1][2];
    return kWhiteEfficacy * y / inputExposure;
}

double Context::scotopicLuminance(const Pixel& c) const {
    if (xyz) {  // approximation from X, Y and Z (cielum)
        const float yz = c[1] + c[2];
        return c[1] * (1.33 * (1. + static_cast<float>(yz / c[0])) - 1.68) / inputExposure;
    }
    return kScotopicWhite * kWhiteEfficacy * (c[0] * .062 + c[1] * .608 + c[2] * .330) /
           inputExposure;
}

void computeFovea(Context& c, const Header& header, PictureFormat format, const std::string& what) {
    c.fvxr = std::max(2, static_cast<int>(c.hn / kFoveaDiameter + 0.5));
    c.fvyr = std::max(2, static_cast<int>(c.vn / kFoveaDiameter + 0.5));
    if (!c.res.yMajor) std::swap(c.fvxr, c.fvyr);  // sizes along and across the scanlines
    // RADIANCE compat: pcond reads "pfilt -1 -b -pa 0 -x fvxr -y fvyr picture", RGBE.
    Picture scans(c.len, c.count);
    scans.format = format;
    scans.header = header;
    scans.pixels = c.pixels;
    PfiltOptions box;
    box.xres = c.fvxr;
    box.yres = c.fvyr;
    box.singlePass = true;
    const Picture small = runPfilt(scans, box, "", what, c.res.yMajor);
    if (small.width != c.fvxr || small.height != c.fvyr)
        throw InputError("error reading from pfilt process in fovimage");
    c.fovea = small.pixels;
    for (Pixel& p : c.fovea) p = toPixel(toColr(p));
}

void computeHistogram(Context& c) {
    if (c.what.preHistogram) return;
    double lwmin = 1e10, lwmax = 0.;
    for (const Pixel& p : c.fovea) {
        const double l = c.luminance(p);
        lwmin = std::min(lwmin, l);
        lwmax = std::max(lwmax, l);
    }
    const int nsamples = static_cast<int>(std::min<long>(static_cast<long>(c.fvxr) * c.fvyr * 16,
                                                         static_cast<long>(c.len) * c.count));
    const std::vector<float> samples = luminanceSamples(c, nsamples);
    for (int i = nsamples; i--;) {
        lwmin = std::min<double>(lwmin, samples[i]);
        lwmax = std::max<double>(lwmax, samples[i]);
    }
    Histogram& h = c.hist;
    lwmax = std::min(lwmax * 1.01, kLMax);
    h.bwmax = brightness(lwmax);
    if (lwmin < kLMin) {
        lwmin = kLMin;
        h.bwmin = brightness(kLMin);
    } else {  // the lowest bin is duplicated below
        h.bwmin = h.bwmax - (h.bwmax - brightness(lwmin)) * kHistRes / (kHistRes - 1);
        lwmin = luminanceOf(h.bwmin);
    }
    h.bwavg = h.total = 0;
    h.counts.fill(0);
    if (!c.what.fixations || c.fixationShare < 1. - kTiny) {  // global average
        for (int y = 0; y < c.fvyr; ++y)
            for (int x = 0; x < c.fvxr; ++x)
                addSample(h, c.luminance(c.fov(x, y)), lwmin, lwmax,
                          c.what.centerWeight ? centerWeight(c, x, y) : 1.);
        const double w = h.total / nsamples;  // point samples weigh as much as the fovea
        for (int i = nsamples; i--;) addSample(h, samples[i], lwmin, lwmax, w);
    }
    if (c.what.fixations && !c.fixations.empty()) {
        const double w = h.total > kTiny ? c.fixationShare / (1. - c.fixationShare) * h.total /
                                               c.fixations.size()
                                         : 1.;
        for (const auto& f : c.fixations)
            addSample(h, c.luminance(c.fov(f[0], f[1])), lwmin, lwmax, w);
    }
    h.bwavg /= h.total;
    if (lwmin > kLMin + kTiny) {  // false samples at the bottom
        h.counts[1] *= 0.5;
        h.counts[0] += h.counts[1];
    }
}

void readHistogram(Context& c, std::istream& in) {
    std::array<double, kMaxPreHistogram> counts{};
    double start = 0, step = 0, b = 0, last = 0;
    int i = 0;
    for (; i < kMaxPreHistogram && (in >> b >> counts[i]); ++i) {
        if (i > 1 && std::fabs(b - last - step) > .001)
            throw InputError("uneven step size in histogram data");
        if (i == 1 && (step = b - (start = last)) <= kTiny)
            throw InputError("illegal step in histogram data");
        last = b;
    }
    if (i < 2 || !in.eof()) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "format/length error loading histogram (log10L %f at %d)", b,
                      i);
        throw InputError(buf);
    }
    const int n = i;
    start *= M_LN10;  // log10 to natural log
    step *= M_LN10;
    Histogram& h = c.hist;
    for (i = 0; i < n && counts[i] <= kTiny; ++i) {
    }
    h.bwmin = start + (i - .001) * step;
    for (i = n; i-- && counts[i] <= kTiny;) {
    }
    h.bwmax = std::min(start + (i + 1.001) * step, brightness(kLMax));
    if (h.bwmin < brightness(kLMin))
        h.bwmin = brightness(kLMin);
    else  // the lowest bin is duplicated below
        h.bwmin = h.bwmax - (h.bwmax - h.bwmin) * kHistRes / (kHistRes - 1);
    h.bwavg = h.total = 0;
    h.counts.fill(0);
    b = start;
    for (i = 0; i < n; ++i, b += step) {
        if (b < h.bwmin + kTiny) continue;
        if (b >= h.bwmax - kTiny) break;
        h.bwavg += counts[i] * b;
        h.counts[h.bin(b)] += counts[i];
        h.total += counts[i];
    }
    h.bwavg /= h.total;
    if (h.bwmin > brightness(kLMin) + kTiny) {  // false samples at the bottom
        h.counts[1] *= 0.5;
        h.counts[0] += h.counts[1];
    }
}

void readFixations(Context& c, std::istream& in) {
    int px = 0, py = 0;
    while (in >> px >> py) {
        const std::array<int, 2> f = fovealPosition(c, px, py);
        for (int x = f[0] - 1; x <= f[0] + 1; ++x) {  // the nine neighbouring samples
            if (x < 0 || x >= c.fvxr) continue;
            for (int y = f[1] - 1; y <= f[1] + 1; ++y) {
                if (y < 0 || y >= c.fvyr) continue;
                const std::array<int, 2> p{x, y};
                if (std::find(c.fixations.begin(), c.fixations.end(), p) == c.fixations.end())
                    c.fixations.push_back(p);
            }
        }
    }
    if (!in.eof()) throw InputError("format error reading fixation data");
}

void checkWhatToDo(Context& c) {
    const Histogram& h = c.hist;
    if (h.bwmax - h.bwmin <= c.bldmax - c.bldmin) c.what.linear = true;  // fits the display
    if (h.bwmax - h.bwmin < 4.5) c.what.veil = false;  // RADIANCE's heuristic: no visible veil
    if (!c.what.acuity && !c.what.color) return;
    double sum = h.total * 0.05;  // the 5th percentile
    int i = 0;
    for (; i < kHistRes; ++i)
        if ((sum -= h.counts[i]) <= 0) break;
    const double l = luminanceOf((i + .5) * (h.bwmax - h.bwmin) / kHistRes + h.bwmin);
    // Acuity loss only shows when it is coarser than the pixels (cycles per degree).
    if (c.what.acuity && acuity(l) >= (c.res.xres / c.hn + c.res.yres / c.vn) / (2. * 180. / M_PI))
        c.what.acuity = false;
    if (l >= kTopMesopic) c.what.color = false;
}

double contrastThreshold(double la) {
    // Ferwerda et al. 1996, "A Model of Visual Adaptation for Realistic Image Synthesis":
    // rod and cone threshold-versus-intensity functions, log10 cd/m^2.
    if (la < 1.148e-4) return 1.38e-3;
    const double l10La = std::log10(la);
    double l10dL;
    if (l10La < -1.44)
        l10dL = std::pow(.405 * l10La + 1.6, 2.18) - 2.86;
    else if (l10La < -.0184)
        l10dL = l10La - .395;
    else if (l10La < 1.9)
        l10dL = std::pow(.249 * l10La + .65, 2.7) - .72;
    else
        l10dL = l10La - 1.255;
    return std::exp(M_LN10 * l10dL);
}

double displayBrightness(const Context& c, double lw) {
    const Histogram& h = c.hist;
    double b;
    if (lw <= kLMin || (b = brightness(lw)) <= h.bwmin + kTiny) return c.bldmin;
    if (b >= h.bwmax - kTiny) return c.bldmax;
    double x = kHistRes * (b - h.bwmin) / (h.bwmax - h.bwmin);
    const int i = static_cast<int>(x);
    x -= i;
    const double cf = c.map.cumulative[i] * (1. - x) + c.map.cumulative[i + 1] * x;
    return c.bldmin + cf * (c.bldmax - c.bldmin);
}

bool makeBrightnessMap(Context& c) {
    BrightnessMap& m = c.map;
    m.counts = c.hist.counts;
    const double s = (c.hist.bwmax - c.hist.bwmin) / kHistRes;  // bin width
    double trimmings;
    do {
        makeCumulative(m);
        if (m.total <= c.hist.total * kClipShare) return false;  // no compression needed
        const double tdb = m.total * s;
        trimmings = 0.;
        double b = c.hist.bwmin + .5 * s;
        for (int i = 0; i < kHistRes; ++i, b += s) {
            const double ceiling = tdb * clampFactor(c, luminanceOf(b));
            if (m.counts[i] > ceiling) {
                trimmings += m.counts[i] - ceiling;
                m.counts[i] = ceiling;
            }
        }
    } while (trimmings > m.total * kClipShare);
    return true;
}

void mapScan(const Context& c, Pixel* scan, int n) {
    const double ldmin = c.displayMin();
    for (int x = 0; x < n; ++x) {
        const double lw = c.luminance(scan[x]);
        if (lw < kLMin) {
            scan[x] = Pixel{0, 0, 0};
            continue;
        }
        const double b = displayBrightness(c, lw);
        double mult = (luminanceOf(b) - ldmin) / (c.displayMax - ldmin) / (lw * c.inputExposure);
        if (!c.xyz) mult *= kWhiteEfficacy;
        for (float& v : scan[x]) v = static_cast<float>(v * mult);
    }
}

void writeMapping(const Context& c, std::ostream& out) {
    double sf = c.scale * c.inputExposure;
    if (c.xyz) sf *= kWhiteEfficacy;
    const double s = (c.hist.bwmax - c.hist.bwmin) / kHistRes;
    double b = c.hist.bwmin + .5 * s;
    char buf[64];
    for (int i = 0; i < kHistRes; ++i, b += s) {
        const double wlum = luminanceOf(b);
        double dlum;
        if (c.what.linear)
            dlum = std::clamp(sf * wlum, c.displayMin(), c.displayMax);
        else
            dlum = luminanceOf(displayBrightness(c, wlum));
        std::snprintf(buf, sizeof buf, "%e %e\n", wlum, dlum);
        out << buf;
    }
}

}  // namespace rp::pcond_detail
