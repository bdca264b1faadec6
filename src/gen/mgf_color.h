// MGF colours (the MGF 2.0 spec, "c", "cxy", "cspec", "cct", "cmix"): a colour kept as
// CIE (x, y) chromaticity and/or a 41-sample spectrum over 380..780 nm, converted between
// the two as RADIANCE's MGF library does, and to RADIANCE RGB as mgf2rad does. The MGF
// parser is mgf_reader.h; the material choice is mgf2rad.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rp::gen {

// RADIANCE dithers every stored spectral sample with rand() (glibc's, never seeded, so
// seed 1): this reproduces that sequence, one per conversion as one per mgf2rad process,
// so that spectral colours convert to the same digits.
class MgfDither {
public:
    MgfDither();
    double next();  // RADIANCE frand(): rand() / (RAND_MAX + 0.5), in [0, 1)

private:
    std::array<uint32_t, 31> ring_{};  // the last 31 values of the recurrence
    uint64_t n_ = 0;                   // index of the next value
};

struct MgfColor {
    static constexpr int kMinWl = 380, kMaxWl = 780, kSamples = 41;
    static constexpr int kWlStep = (kMaxWl - kMinWl) / (kSamples - 1);
    static constexpr int kMaxSample = 10000;  // nominal largest sample value

    // What is set and how it was defined (RADIANCE's C_CSSPEC ... C_CSEFF bits).
    enum Flag : uint8_t { SpecSet = 1, SpecDefined = 2, XySet = 4, XyDefined = 8, EffSet = 16 };

    uint8_t flags = XyDefined | XySet | SpecSet | EffSet;
    // Samples and chromaticity in RADIANCE's storage types (short, float), so that
    // conversions round as mgf2rad's do.
    std::array<int16_t, kSamples> samples{};
    long sampleSum = 0;
    float x = 1.f / 3, y = 1.f / 3;
    float efficacy = 178.006f;  // lm/W

    // The default colour: equal-energy white (every sample at kMaxSample).
    MgfColor();

    // cxy: false for x or y below 0 or x + y above 1.
    bool setXy(double cx, double cy);
    // cspec: samples from wlMin to wlMax; false when no energy lands in 380..780 nm.
    bool setSpectrum(double wlMin, double wlMax, const std::vector<float>& values,
                     MgfDither& dither);
    // cct: a black body at `kelvin`; false below 1000 K.
    bool setBlackBody(double kelvin, MgfDither& dither);
    // Fills in the representations in `want` (Flag bits) from those set; a spectrum
    // from xy needs `dither`.
    void convert(unsigned want, MgfDither* dither = nullptr);
    // RADIANCE c_isgrey: chromaticity within 0.01 of the white point.
    bool isGrey();
};

// cmix: w1 parts of c1 and w2 parts of c2 (spectrally when either was defined by a
// spectrum, else in xy), as RADIANCE's c_cmix.
MgfColor mixColors(double w1, MgfColor c1, double w2, MgfColor c2, MgfDither& dither);

// mgf2rad's cvtcolor: the colour at luminance Y = intensity as RADIANCE RGB (nominal CRT
// primaries, equal-energy white), negative components desaturated away (cie_rgb).
std::array<float, 3> mgfColorToRgb(MgfColor c, double intensity);

}  // namespace rp::gen
