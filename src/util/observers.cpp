// Scotopic and melanopic integrals (see observers.h).
#include "util/observers.h"

#include <array>

#include "util/error.h"
#include "util/observer_table.h"

namespace rp::spectral {

namespace {

// Both tables every 5 nm from 380 to 780 nm.
constexpr double kFirst = 380, kStep = 5;

// CIE scotopic luminous efficiency V'(λ) (CIE 1951; ISO 23539:2005/CIE S 010/E:2004),
// as distributed by the Colour & Vision Research Laboratory (CVRL, scvle_1.csv) and the
// colour-science package ("CIE 1951 Scotopic Standard Observer"), 380-780 nm every 5 nm.
constexpr std::array<double, 81> kScotopic = {
    0.000589,  0.001108,  0.002209, 0.00453,   0.00929,  0.01852,   0.03484,   0.0604,
    0.0966,    0.1436,    0.1998,   0.2625,    0.3281,   0.3931,    0.455,     0.513,
    0.567,     0.62,      0.676,    0.734,     0.793,    0.851,     0.904,     0.949,
    0.982,     0.998,     0.997,    0.975,     0.935,    0.88,      0.811,     0.733,
    0.65,      0.564,     0.481,    0.402,     0.3288,   0.2639,    0.2076,    0.1602,
    0.1212,    0.0899,    0.0655,   0.0469,    0.03315,  0.02312,   0.01593,   0.01088,
    0.00737,   0.00497,   0.003335, 0.002235,  0.001497, 0.001005,  0.000677,  0.000459,
    0.0003129, 0.0002146, 0.000148, 0.0001026, 7.15e-05, 5.01e-05,  3.533e-05, 2.501e-05,
    1.78e-05,  1.273e-05, 9.14e-06, 6.6e-06,   4.78e-06, 3.482e-06, 2.546e-06, 1.87e-06,
    1.379e-06, 1.022e-06, 7.6e-07,  5.67e-07,  4.25e-07, 3.196e-07, 2.413e-07, 1.829e-07,
    1.39e-07,
};

// Melanopic action spectrum s_mel(λ) of CIE S 026/E:2018 (the CIE S 026 α-opic Toolbox
// v1.049a, column "mel"; dataset DOI 10.25039/CIE.DS.vqqhzp5a), peak 1 at 490 nm,
// 380-780 nm every 5 nm.
constexpr std::array<double, 81> kMelanopic = {
    0.000918165, 0.00166724,  0.00309442,  0.00588035,  0.0114277,   0.0228112,   0.046155,
    0.0794766,   0.137237,    0.187096,    0.253865,    0.320679,    0.401587,    0.474002,
    0.553715,    0.629654,    0.708049,    0.785216,    0.860291,    0.917734,    0.965605,
    0.990621,    1,           0.992022,    0.965952,    0.922299,    0.862888,    0.785233,
    0.699628,    0.609422,    0.519309,    0.432533,    0.351707,    0.279135,    0.215722,
    0.162056,    0.118526,    0.0843457,   0.0587013,   0.0400089,   0.0268747,   0.0178624,
    0.0117901,   0.0077343,   0.00506686,  0.00331766,  0.00217698,  0.00143314,  0.000947313,
    0.000627648, 0.000417955, 0.000279801, 0.000188341, 0.000127337, 8.65751e-05, 5.91914e-05,
    4.06945e-05, 2.8132e-05,  1.95535e-05, 1.3648e-05,  9.57637e-06, 6.75425e-06, 4.78804e-06,
    3.40841e-06, 2.43819e-06, 1.75252e-06, 1.2656e-06,  9.18078e-07, 6.68991e-07, 4.89531e-07,
    3.59766e-07, 2.65493e-07, 1.9674e-07,  1.4637e-07,  1.09332e-07, 8.19587e-08, 6.16749e-08,
    4.65916e-08, 3.53272e-08, 2.68803e-08, 2.05258e-08,
};

const detail::Cumulative& cumulScotopic() {
    static const detail::Cumulative c(kScotopic, kFirst, kStep);
    return c;
}
const detail::Cumulative& cumulMelanopic() {
    static const detail::Cumulative c(kMelanopic, kFirst, kStep);
    return c;
}

double integrate(std::span<const double> samples, const Sampling& s, const detail::Cumulative& c) {
    RP_CHECK(static_cast<int>(samples.size()) == s.n);
    if (!s.isRgb()) return detail::observe(samples, s.wl, c);
    // RGB: the channels' own bands, blue from wl[3]; red reaching 780 nm takes the tail.
    const double top = s.wl[0] >= 780 ? 830 : s.wl[0];
    return (c(s.wl[2]) - c(s.wl[3])) * samples[2] + (c(s.wl[1]) - c(s.wl[2])) * samples[1] +
           (c(top) - c(s.wl[1])) * samples[0];
}

}  // namespace

double scotopic(std::span<const double> samples, const Sampling& s) {
    return integrate(samples, s, cumulScotopic());
}

double melanopic(std::span<const double> samples, const Sampling& s) {
    return integrate(samples, s, cumulMelanopic());
}

}  // namespace rp::spectral
