// Spectral colour as RADIANCE 6 defines it: n samples (bands of equal width) from the
// longest wavelength down to the shortest, the conversions between spectra, RGB and CIE
// XYZ, and the visual integrals (photopic, scotopic, melanopic). RGB is the case n == 3,
// where the "samples" are RADIANCE's red, green and blue and no conversion applies.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "util/color.h"

namespace rp::spectral {

// RADIANCE 6 allows at most 24 samples (MAXCSAMP).
constexpr int kMaxSamples = 24;

// -cs n and -cw: n bands over wl[0] (longest, nm) down to wl[3]; wl[1] and wl[2] split
// red from green and green from blue, and rgb[] are the samples nearest the primaries'
// peaks (RADIANCE's WLPART and CNDX).
struct Sampling {
    int n = 3;
    std::array<double, 4> wl{780, 588, 480, 380};
    std::array<int, 3> rgb{0, 1, 2};

    bool isRgb() const { return n == 3; }
    // Band width, negative: wavelengths fall with the sample index.
    double step() const { return (wl[3] - wl[0]) / n; }
    double centre(int i) const { return wl[0] + (i + 0.5) * step(); }
    bool operator==(const Sampling&) const = default;
};

// RADIANCE 6's setspectrsamp: nullopt when it rejects the sampling (fewer than 3 samples,
// a range under 50 nm). More than kMaxSamples are cut to kMaxSamples. A range that misses
// a primary's peak wavelength is split in thirds (RADIANCE warns; `tuned` is false).
struct SamplingChoice {
    Sampling sampling;
    bool tuned = true;
};
std::optional<SamplingChoice> makeSampling(int n, double wlA, double wlB);

// The renderer traces three channels at a time. With more samples it renders a sampling
// in passes, each over three consecutive bands (a last pass short of bands repeats its
// last one): since every colour operation of the renderer works channel by channel, a
// pass gives its bands as they are among all n. Whatever enters the renderer as a
// colour goes through its pass: an RGB colour takes, in each band, the primary whose
// range holds the band's centre (RADIANCE 6's setscolor), a spectrum its bands. RGB
// rendering is the single pass of the 3-sample sampling, where both are the identity.
struct Pass {
    Sampling sampling;
    int first = 0;                        // the pass's first band
    std::array<int, 3> primary{0, 1, 2};  // the RGB primary each of its bands takes

    int band(int j) const { return first + j < sampling.n ? first + j : sampling.n - 1; }
    Color ofRgb(const Color& c) const { return {c[primary[0]], c[primary[1]], c[primary[2]]}; }
    // The pass's bands of samples in the working sampling (sampling.n values).
    Color ofSamples(std::span<const double> s) const {
        return {s[band(0)], s[band(1)], s[band(2)]};
    }
    // The reverse: a colour this pass rendered into its bands of all n samples (a last
    // pass's repeated band is not written twice).
    void placeBands(const Color& c, std::span<double> samples) const {
        for (int j = 0; j < 3 && first + j < sampling.n; ++j) samples[size_t(first + j)] = c[j];
    }
    bool operator==(const Pass&) const = default;
};
// The passes that render a sampling: ceil(n / 3).
std::vector<Pass> passesOf(const Sampling& s);
// The file a pass keeps of what a run writes per pass (photon maps, ambient files): the
// name itself for RGB and the first pass, else "<name>.<first>-<last>" beside it.
std::string passFile(const std::string& name, const Pass& pass);
// "-cs n -cw nmA nmB bands first-last" for a pass of a spectral sampling, "" for RGB: what
// a file made by one pass records, so that another pass does not read it.
std::string passLabel(const Pass& pass);

// Samples of an RGB colour (RADIANCE's setscolor): each band takes the primary of the
// channel its centre falls in.
void fromRgb(const Color& rgb, const Sampling& s, std::span<double> out);

// Box re-binning of a uniformly sampled spectrum (src over swl0..swl1, either order)
// onto dst's bands over dwl0 > dwl1, each band the average of the source over it, zero
// outside the source's range (RADIANCE's convertscolor).
void resample(std::span<double> dst, double dwl0, double dwl1, std::span<const double> src,
              double swl0, double swl1);

// A measured spectrum (src: bands over swl0..swl1, either order) in the working
// sampling: re-binned onto s's bands, or for RGB integrated against the CIE observer
// and converted to RADIANCE RGB (RADIANCE 6's convertscolorcol). out.size() == s.n.
void toWorking(std::span<const double> src, double swl0, double swl1, const Sampling& s,
               std::span<double> out);

// CIE XYZ of samples (RADIANCE's scolor2cie; for n == 3 the RGB -> XYZ matrix).
Color toXyz(std::span<const double> samples, const Sampling& s);
// RADIANCE RGB of samples (scolor2rgb: XYZ then RGB with negative primaries pulled to
// the grey of equal luminance; for n == 3 the samples themselves).
Color toRgb(std::span<const double> samples, const Sampling& s);
// Band averages per RGB channel (RADIANCE's scolor2color, the fast lossy conversion
// pictures use).
Color bandAverages(std::span<const double> samples, const Sampling& s);
// Photopic luminance factor Y (for n == 3, RADIANCE's bright()).
double photopic(std::span<const double> samples, const Sampling& s);

// XYZ -> RGB for primaries (rx ry gx gy bx by wx wy), white mapped to (1,1,1);
// row-major. RADIANCE's standard primaries are kStandardPrimaries.
constexpr std::array<double, 8> kStandardPrimaries = {0.640, 0.330, 0.290,   0.600,
                                                      0.150, 0.060, 1.0 / 3, 1.0 / 3};
std::array<double, 9> rgbFromXyz(const std::array<double, 8>& primaries);
// RADIANCE's clipgamut with the lower limit only: a colour with a negative primary is
// pulled toward the grey of luminance y until none is; black when y <= 0.
Color clipNegative(const Color& rgb, double y);

}  // namespace rp::spectral
