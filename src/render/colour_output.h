// What a colour result is printed as (RADIANCE 6 rtmain.c -pRGB -pXYZ -pc -pY -pS -pM -pA
// and -co; spec_rgb.c scolor_out): RGB, CIE XYZ, RGB of other primaries, one visual or
// radiometric channel, or the spectral samples themselves.
#pragma once

#include <array>
#include <span>
#include <string>

#include "util/spectrum.h"

namespace rp::render {

class ColourOutput {
public:
    enum class Primaries { kRgb, kXyz, kCustom, kNone };  // kNone: spectral (-co)
    enum class Channel { kNone, kPhotopic, kScotopic, kMelanopic, kAverage };

    // The options as RADIANCE 6 reads them, in order: each -p names primaries or one
    // channel; -co[+|-] (no sign: toggle) asks for spectral samples or cancels them.
    void setPrimaries(Primaries p);
    void setCustomPrimaries(const std::array<double, 8>& p);
    void setChannel(Channel c) { channel_ = c; }
    bool spectral() const { return primaries_ == Primaries::kNone && channel_ == Channel::kNone; }
    void setSpectral(bool on);

    // After parsing, for the run's sampling: one channel wins over primaries, spectral
    // output of 3 samples is RGB ("3 samples do not a spectrum make").
    void resolve(const spectral::Sampling& s);

    // Values per colour: 1 for a channel, n for spectral samples, else 3.
    int components() const;
    // The values of a colour given as its samples in the sampling (n values);
    // out.size() == components().
    void convert(std::span<const double> samples, std::span<double> out) const;
    // Whether the output is plain RGB of 3 samples (the values pass unchanged).
    bool identity() const;
    // rtrace's header lines for it: NCOMP= (components() times `perRecord` colours plus
    // `otherValues`), WAVELENGTH_SPLITS= for spectral output, PRIMARIES= for XYZ and
    // custom primaries.
    std::string headerLines(int perRecord, int otherValues) const;

private:
    Primaries primaries_ = Primaries::kRgb;
    Channel channel_ = Channel::kNone;
    std::array<double, 8> custom_{};
    spectral::Sampling sampling_;
};

}  // namespace rp::render
