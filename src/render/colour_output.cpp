// Colour output conversions (see colour_output.h).
#include "render/colour_output.h"

#include <cmath>
#include <cstdio>
#include <numeric>

#include "image/white_balance.h"
#include "util/error.h"
#include "util/observers.h"

namespace rp::render {

namespace {

// RADIANCE's WHTEFFICACY: lumens per watt of its equal-energy white.
constexpr double kWhiteEfficacy = 179;

}  // namespace

void ColourOutput::setPrimaries(Primaries p) {
    primaries_ = p;
    channel_ = Channel::kNone;
}

void ColourOutput::setCustomPrimaries(const std::array<double, 8>& p) {
    // RADIANCE compat (rtmain.c -pc): within 0.001 of the standard primaries is RGB.
    bool standard = true;
    for (size_t i = 0; i < 8; ++i)
        standard = standard && std::fabs(p[i] - spectral::kStandardPrimaries[i]) <= .001;
    custom_ = p;
    setPrimaries(standard ? Primaries::kRgb : Primaries::kCustom);
}

void ColourOutput::setSpectral(bool on) {
    if (on) {
        primaries_ = Primaries::kNone;
        channel_ = Channel::kNone;
    } else if (primaries_ == Primaries::kNone) {
        primaries_ = Primaries::kRgb;
    }
}

void ColourOutput::resolve(const spectral::Sampling& s) {
    sampling_ = s;
    if (channel_ != Channel::kNone) return;
    if (primaries_ == Primaries::kNone && s.isRgb()) primaries_ = Primaries::kRgb;
}

int ColourOutput::components() const {
    if (channel_ != Channel::kNone) return 1;
    return primaries_ == Primaries::kNone ? sampling_.n : 3;
}

bool ColourOutput::identity() const {
    return channel_ == Channel::kNone && primaries_ == Primaries::kRgb && sampling_.isRgb();
}

void ColourOutput::convert(std::span<const double> samples, std::span<double> out) const {
    RP_CHECK(static_cast<int>(samples.size()) == sampling_.n &&
             static_cast<int>(out.size()) == components());
    const spectral::Sampling& s = sampling_;
    switch (channel_) {
        case Channel::kPhotopic:
            out[0] = kWhiteEfficacy * spectral::photopic(samples, s);
            return;
        case Channel::kScotopic:
            out[0] = spectral::kScotopicEfficacy * spectral::scotopic(samples, s);
            return;
        case Channel::kMelanopic:
            out[0] = spectral::kMelanopicEfficacy * spectral::melanopic(samples, s);
            return;
        case Channel::kAverage:
            out[0] = std::accumulate(samples.begin(), samples.end(), 0.0) / s.n;
            return;
        case Channel::kNone:
            break;
    }
    Color c;
    switch (primaries_) {
        case Primaries::kNone:
            std::copy(samples.begin(), samples.end(), out.begin());
            return;
        case Primaries::kXyz:
            c = spectral::toXyz(samples, s) * kWhiteEfficacy;
            break;
        case Primaries::kRgb:
            c = spectral::toRgb(samples, s);
            break;
        case Primaries::kCustom: {
            // RADIANCE 6 (rtrace.c putscolor): XYZ, then the primaries' RGB with a white
            // balance, negative primaries pulled to the grey of the same luminance.
            std::array<float, 8> p;
            for (int i = 0; i < 8; ++i) p[size_t(i)] = float(custom_[size_t(i)]);
            const std::array<float, 9> m = xyzToRgbWhiteBalanced(p);
            const Color xyz = spectral::toXyz(samples, s);
            const Color rgb{m[0] * xyz.r + m[1] * xyz.g + m[2] * xyz.b,
                            m[3] * xyz.r + m[4] * xyz.g + m[5] * xyz.b,
                            m[6] * xyz.r + m[7] * xyz.g + m[8] * xyz.b};
            c = spectral::clipNegative(rgb, xyz.g);
            break;
        }
    }
    out[0] = c.r;
    out[1] = c.g;
    out[2] = c.b;
}

std::string ColourOutput::headerLines(int perRecord, int otherValues) const {
    std::string h = "NCOMP=" + std::to_string(perRecord * components() + otherValues) + "\n";
    if (channel_ != Channel::kNone) return h;
    char buf[120];
    if (primaries_ == Primaries::kNone) {
        std::snprintf(buf, sizeof buf, "WAVELENGTH_SPLITS= %g %g %g %g\n", sampling_.wl[0],
                      sampling_.wl[1], sampling_.wl[2], sampling_.wl[3]);
        h += buf;
    } else if (primaries_ == Primaries::kXyz) {
        h += "PRIMARIES= 1.0000 0.0000 0.0000 1.0000 0.0000 0.0000 0.3333 0.3333\n";
    } else if (primaries_ == Primaries::kCustom) {
        std::snprintf(buf, sizeof buf, "PRIMARIES= %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n",
                      custom_[0], custom_[1], custom_[2], custom_[3], custom_[4], custom_[5],
                      custom_[6], custom_[7]);
        h += buf;
    }
    return h;
}

}  // namespace rp::render
