// RADIANCE 6's single-channel visual outputs besides photopic luminance: the scotopic
// (rtrace -pS) and melanopic (-pM) integrals of spectral samples.
#pragma once

#include <span>

#include "util/spectrum.h"

namespace rp::spectral {

// Integrals of samples (bands as in Sampling: n bands from wl[0], the longest, down to
// wl[3]) against the CIE scotopic luminous efficiency V'(λ) (CIE 1951) and the melanopic
// action spectrum s_mel(λ) (CIE S 026:2018), each normalised so that an equal-energy
// spectrum gives 1 (RADIANCE 6's spec_rgb.c scolor2scotopic, scolor2melanopic). The
// bands are integrated exactly, as photopic() and toXyz() do; for n == 3 (RGB) the
// three values are integrated over the bands wl[3]..wl[2], wl[2]..wl[1] and wl[1]..wl[0]
// (blue, green, red: 380-480-588-780 nm by default), as RADIANCE's spec_dot does.
// samples.size() == s.n.
double scotopic(std::span<const double> samples, const Sampling& s);
double melanopic(std::span<const double> samples, const Sampling& s);

// The efficacies RADIANCE 6 multiplies them by for output (color.h WHTSCOTOPIC and
// WHTMELANOPIC, the equal-energy white over 380-780 nm): rtrace -pS prints
// kScotopicEfficacy * scotopic(), -pM kMelanopicEfficacy * melanopic().
constexpr double kScotopicEfficacy = 412;
constexpr double kMelanopicEfficacy = 179;

}  // namespace rp::spectral
