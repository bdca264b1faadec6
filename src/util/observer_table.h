// Integrating a tabulated observer function over RADIANCE 6's spectral bands: shared by
// util/spectrum.cpp (the CIE 1931 observer) and util/observers.cpp (scotopic and
// melanopic). Internal to util.
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <vector>

namespace rp::spectral::detail {

// The integral of a function tabulated every `step` nm from `first` nm (a whole number of
// nanometres; zero outside the table) from the table's start up to a wavelength,
// normalised to 1 over the whole table, so that an equal-energy spectrum gives 1 (as
// RADIANCE 6's tables in spec_rgb.c) and a band's weight is a difference of two values.
// Kept every nanometre and interpolated between.
class Cumulative {
public:
    Cumulative(std::span<const double> f, double first, double step)
        : first_(static_cast<int>(first)),
          last_(static_cast<int>(first + step * static_cast<double>(f.size() - 1))) {
        // The table interpolated linearly, integrated exactly per nanometre.
        values_.resize(size_t(last_ - first_ + 1));
        double sum = 0;
        values_[0] = 0;
        for (int nm = first_; nm < last_; ++nm) {
            sum += 0.5 * (at(f, first, step, nm) + at(f, first, step, nm + 1));
            values_[size_t(nm - first_ + 1)] = sum;
        }
        for (double& v : values_) v /= sum;
    }
    double operator()(double nm) const {
        if (!(nm > first_)) return 0;
        if (nm >= last_) return 1;
        const int i = static_cast<int>(nm);
        const double t = nm - i;
        return values_[size_t(i - first_)] * (1 - t) + values_[size_t(i - first_ + 1)] * t;
    }

private:
    static double at(std::span<const double> f, double first, double step, int nm) {
        const double x = (nm - first) / step;
        const int i = std::min(static_cast<int>(x), static_cast<int>(f.size()) - 2);
        const double t = x - i;
        return f[size_t(i)] * (1 - t) + f[size_t(i + 1)] * t;
    }
    int first_, last_;
    std::vector<double> values_;
};

// The dot product of samples with an observer function over their bands. RADIANCE 6
// (spec_dot) truncates band edges to whole nanometres and its tables read as the CIE
// observer shifted about 1.5 nm toward the red; here the bands are integrated exactly,
// which moves a channel of a steep spectrum by up to ~4 % (README, "Spectral colour").
// A longest band reaching 780 nm takes the observer's tail beyond, as RADIANCE's.
inline double observe(std::span<const double> samples, const std::array<double, 4>& wl,
                      const Cumulative& c) {
    const int n = static_cast<int>(samples.size());
    const double step = (wl[0] - wl[3]) / n;
    double sum = 0, lo = wl[3];
    for (int k = 0; k < n; ++k) {  // k counts bands from the short end
        double hi = wl[3] + (k + 1) * step;
        if (k == n - 1 && hi >= 780) hi = 830;
        sum += (c(hi) - c(lo)) * samples[size_t(n - 1 - k)];
        lo = hi;
    }
    return sum;
}

}  // namespace rp::spectral::detail
