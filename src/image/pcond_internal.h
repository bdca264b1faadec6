// The state pcond's steps share (RADIANCE keeps it in globals, pcond.h): the picture in
// its file's scanline order, the foveal image, the luminance histogram and the brightness
// map. Only pcond*.cpp include this; the tool's interface is pcond.h.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "image/picture.h"
#include "image/view.h"

namespace rp::pcond_detail {

constexpr int kHistRes = 100;                  // histogram bins (HISTRES)
constexpr double kTiny = 1e-6;                 // RADIANCE's FTINY
constexpr double kLMin = 1e-7;                 // least visible world luminance, cd/m^2
constexpr double kLMax = 1e7;                  // greatest
constexpr double kWhiteEfficacy = 179;         // lm/W of uniform white (WHTEFFICACY)
constexpr double kScotopicWhite = 2.26;        // scotopic/photopic ratio of white (SWNORM)
constexpr double kBottomMesopic = 5.62e-3;     // below: scotopic only, cd/m^2
constexpr double kTopMesopic = 5.62;           // above: photopic only
constexpr double kFoveaDiameter = M_PI / 180;  // 1 degree, in radians
constexpr double kVeilShare = 0.08;            // share of adaptation from the veil (VADAPT)

// Brightness is the natural log of luminance (Bl/Lb in RADIANCE's pcond.h).
inline double brightness(double lum) { return std::log(lum); }
inline double luminanceOf(double b) { return std::exp(b); }

// RADIANCE's COLORMAT: single precision, applied as colortrans.
using ColorMatrix = std::array<std::array<float, 3>, 3>;
// Chromaticities: red x y, green x y, blue x y, white x y (RGBPRIMS, floats).
using Primaries = std::array<float, 8>;

// glibc's drand48() before any seeding (state 0), which RADIANCE's frandom() is on
// Linux: pcond's random pixel samples then fall where RADIANCE's fall.
class Drand48 {
public:
    double next() {
        state_ = (0x5DEECE66DULL * state_ + 0xB) & ((1ULL << 48) - 1);
        return std::ldexp(static_cast<double>(state_), -48);
    }

private:
    uint64_t state_ = 0;
};

// What to do (RADIANCE's what2do flags); the run clears the effects that would not show.
struct Flags {
    bool acuity = false, veil = false, sensitivity = false, color = false;
    bool centerWeight = false, fixations = false, preHistogram = false, linear = false;
};

struct Histogram {
    std::array<double, kHistRes> counts{};
    double total = 0;
    double bwmin = 0, bwmax = 0;  // brightness limits
    double bwavg = 0;             // mean brightness

    int bin(double b) const { return static_cast<int>(kHistRes * (b - bwmin) / (bwmax - bwmin)); }
};

// The histogram clipped to the contrast envelope and its cumulative distribution
// (RADIANCE's modhist, mhistot, cumf).
struct BrightnessMap {
    std::array<double, kHistRes> counts{};
    double total = 0;
    std::array<double, kHistRes + 1> cumulative{};
};

struct Context {
    Flags what;
    double displayMax = 100, displayRange = 100;
    double bldmin = 0, bldmax = 0;  // display brightness range
    double displayMin() const { return displayMax / displayRange; }

    bool xyz = false;        // XYZE input (cielum), else RGBE (rgblum)
    ColorMatrix rgbToXyz{};  // input RGB to XYZ, white balanced to equal energy
    double inputExposure = 1;
    std::optional<Primaries> inputPrimaries;  // the header's PRIMARIES= (nullopt: standard)

    // The picture as its file stores it: scanline s is pixels[s*len .. s*len+len).
    Resolution res;
    int len = 0, count = 0;
    std::vector<Pixel> pixels;
    const Pixel* scan(int s) const { return pixels.data() + static_cast<size_t>(s) * len; }

    std::optional<ViewRays> view;
    double hn = 1, vn = 1;  // image-plane sizes (RADIANCE's sqrt(hn2), sqrt(vn2))

    // Foveal image: 1-degree averages, fvxr along the scanlines.
    int fvxr = 0, fvyr = 0;
    std::vector<Pixel> fovea;
    Pixel& fov(int x, int y) { return fovea[static_cast<size_t>(y) * fvxr + x]; }
    const Pixel& fov(int x, int y) const { return fovea[static_cast<size_t>(y) * fvxr + x]; }

    Histogram hist;
    BrightnessMap map;
    double fixationShare = 0;
    std::vector<std::array<int, 2>> fixations;  // foveal (x, y)
    Drand48 random;
    double scale = 0;  // linear scale factor (RADIANCE's scalef)

    std::vector<Pixel> veil;                    // veiling image, foveal resolution
    std::vector<std::array<float, 3>> rayDirs;  // per foveal pixel

    // Photopic and scotopic world luminance of a pixel, cd/m^2 (plum, slum).
    double luminance(const Pixel& c) const;
    double scotopicLuminance(const Pixel& c) const;
};

// pcond_histogram.cpp
void computeFovea(Context& c, const Header& header, PictureFormat format, const std::string& what);
void computeHistogram(Context& c);
void readHistogram(Context& c, std::istream& in);
void readFixations(Context& c, std::istream& in);
void checkWhatToDo(Context& c);
bool makeBrightnessMap(Context& c);                     // false: no compression needed (use linear)
double contrastThreshold(double adaptation);            // htcontrs: just noticeable dL, cd/m^2
double displayBrightness(const Context& c, double lw);  // BLw
void mapScan(const Context& c, Pixel* scan, int n);
void writeMapping(const Context& c, std::ostream& out);

// pcond_vision.cpp
double acuity(double adaptation);  // hacuity: cycles per degree
void computeVeil(Context& c);
void addVeil(const Context& c, Pixel* scan, int s);
void scotopicScan(const Context& c, Pixel* scan, int n);

// Variable-resolution resampling of the picture (pcond4.c's scan bars): each output
// pixel interpolates the level of a 2x2-averaged pyramid whose sample spacing matches
// the acuity at its foveal adaptation luminance. Reads the picture's scanlines in order.
class AcuitySampler {
public:
    explicit AcuitySampler(Context& c);
    void scanline(Pixel* out, int s);

private:
    struct Bar {
        int exponent = 0;  // samples are 2^exponent pixels wide
        int ring = 0;      // scanlines kept
        int len = 0;
        int read = 0;  // scanlines made so far
        std::vector<Pixel> data;
        Pixel* line(int y) { return data.data() + static_cast<size_t>(y % ring) * len; }
    };
    const Pixel* barLine(size_t bar, int y);
    Pixel barValue(int x, int y, size_t bar);
    Pixel sample(int x, int y, double rate);

    const Context& c_;
    std::vector<float> rates_;  // samples per pixel wanted, foveal resolution
    std::vector<Bar> bars_;     // coarsest first, exponent 0 last
    int fileLine_ = 0;          // next scanline of the picture
};

// pcond_color.cpp
// RGB to XYZ for `p` (nullopt: RADIANCE's standard primaries), von Kries balanced from
// p's white to equal energy (comprgb2xyzWBmat).
ColorMatrix rgbToXyzBalanced(const std::optional<Primaries>& p);
// Input RGB (nullopt: standard) to output RGB, white balanced (comprgb2rgbWBmat).
ColorMatrix rgbToRgbBalanced(const std::optional<Primaries>& from,
                             const std::optional<Primaries>& to);
// XYZ to output RGB, white balanced from equal energy (compxyz2rgbWBmat).
ColorMatrix xyzToRgbBalanced(const std::optional<Primaries>& to);
// Matrix, then desaturation into the unit cube (matscan).
void matrixScan(const ColorMatrix& m, Pixel* scan, int n);

// A macbethcal(1) calibration: colour matrix, gamut limits and per-channel curves.
struct Macbeth {
    ColorMatrix matrix{};
    std::array<std::array<float, 6>, 3> xa{}, ya{};
    Pixel cmin{}, cmax{};
};
Macbeth readMacbeth(std::istream& in, const std::string& what);
void macbethScan(const Macbeth& mb, Pixel* scan, int n);

}  // namespace rp::pcond_detail
