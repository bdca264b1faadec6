// Bias-compensated bandwidth choice and its statistics (see bias_comp.h).
#include "pmap/bias_comp.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "util/vec.h"

namespace rp::pmap {

void BiasCompStats::add(int bandwidth, double relError) {
    ++lookups;
    minBandwidth = std::min(minBandwidth, bandwidth);
    maxBandwidth = std::max(maxBandwidth, bandwidth);
    sumBandwidth += bandwidth;
    minError = std::min(minError, relError);
    maxError = std::max(maxError, relError);
    sumError2 += relError * relError;
}

void BiasCompStats::merge(const BiasCompStats& o) {
    lookups += o.lookups;
    minBandwidth = std::min(minBandwidth, o.minBandwidth);
    maxBandwidth = std::max(maxBandwidth, o.maxBandwidth);
    sumBandwidth += o.sumBandwidth;
    minError = std::min(minError, o.minError);
    maxError = std::max(maxError, o.maxError);
    sumError2 += o.sumError2;
}

double BiasCompStats::rmsError() const {
    return lookups ? std::sqrt(sumError2 / double(lookups)) : 0;
}

std::string BiasCompStats::report(const char* photonType) const {
    if (!lookups) return {};
    return fmt::format("{}/{}/{:.1f} {}, ({:.3f}/{:.3f}/{:.3f} error)", minBandwidth, maxBandwidth,
                       meanBandwidth(), photonType, minError, maxError, rmsError());
}

BiasCompResult compensateBias(std::span<FoundPhoton> hits, double searchDist2, bool full, int bwMin,
                              int bwMax, std::vector<std::array<double, 3>>& prefix) {
    BiasCompResult res;
    const size_t m = hits.size();
    if (m < 2) return res;
    // Ties broken by the photons' contents so the order (and so the sums) never depends
    // on the search or the store.
    auto key = [](const FoundPhoton& f) {
        return std::tuple(f.dist2, f.flux[0], f.flux[1], f.flux[2], f.flux[3], f.norm[0], f.norm[1],
                          f.norm[2], f.flags, f.primary);
    };
    std::sort(hits.begin(), hits.end(),
              [&](const FoundPhoton& a, const FoundPhoton& b) { return key(a) < key(b); });
    // prefix[j] = flux of photons 1..j (1-based), summed in distance order.
    if (prefix.size() < m + 1) prefix.resize(m + 1);
    prefix[0] = {0, 0, 0};
    for (size_t i = 0; i < m; ++i) {
        const auto f = hits[i].fluxRgb();
        for (int c = 0; c < 3; ++c) prefix[i + 1][c] = prefix[i][c] + f[c];
    }
    const int last = static_cast<int>(m) - 1;  // largest bandwidth with a (j+1)-th distance
    const int b2 = std::clamp(bwMax, 1, last);
    const int b1 = std::clamp(bwMin, 1, b2);

    auto estimate = [&](int j) {
        const double dj = hits[j - 1].dist2;
        const double dNext = (j == last && !full) ? searchDist2 : double(hits[j].dist2);
        const double r2 = 0.25 * (dj + dNext + 2 * std::sqrt(dj * dNext));
        std::array<double, 3> e;
        for (int c = 0; c < 3; ++c) e[c] = prefix[j][c] / (kPi * kPi * r2);
        return e;
    };
    // Weighted history of estimates (weight j^2), kept as running sums per channel.
    std::array<double, 3> sumW1 = {0, 0, 0}, sumW2 = {0, 0, 0};
    double totalWeight = 0;
    std::array<double, 3> mean{}, var{};
    auto addToHistory = [&](const std::array<double, 3>& e, int j) {
        const double w = double(j) * double(j);
        totalWeight += w;
        for (int c = 0; c < 3; ++c) {
            sumW1[c] += w * e[c];
            sumW2[c] += w * e[c] * e[c];
            mean[c] = sumW1[c] / totalWeight;
            var[c] = std::max(0.0, sumW2[c] / totalWeight - mean[c] * mean[c]);
        }
    };
    for (int j = 1; j <= b1; ++j) addToHistory(estimate(j), j);

    auto plausible = [&](const std::array<double, 3>& e) {
        double p = 0;
        for (int c = 0; c < 3; ++c) {
            const double d = mean[c] - e[c];
            if (var[c] > 0)
                p += std::exp(-0.5 * d * d / var[c]);
            else
                p += std::abs(d) <= 1e-12 * std::abs(mean[c]) ? 1.0 : 0.0;
        }
        return p / 3 >= kBiasCompAccept;
    };

    int lo = b1, hi = b2;
    std::array<double, 3> eLo = estimate(b1);
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        const std::array<double, 3> eMid = estimate(mid);
        if (plausible(eMid)) {
            addToHistory(eMid, mid);
            lo = mid;
            eLo = eMid;
        } else {
            hi = mid;
        }
    }
    res.density = eLo;
    res.bandwidth = lo;
    double err = 0;
    for (int c = 0; c < 3; ++c) err += mean[c] > 0 ? eLo[c] / mean[c] - 1 : 0;
    res.relError = err / 3;
    return res;
}

}  // namespace rp::pmap
