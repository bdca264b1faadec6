// The straight-edge model of a density estimate's disc and its fit (see edge_estimate.h).
#include "pmap/edge_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rp::pmap {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNoEdge = -std::numeric_limits<double>::infinity();

double clampUnit(double x) { return std::clamp(x, -1.0, 1.0); }

// acos(x) / pi for x in [-1, 1] to 2e-8 / pi (Abramowitz & Stegun 4.4.46): the likelihood
// evaluates it k times per trial edge, where std::acos costs more.
double acosOverPi(double x) {
    const double a = std::fabs(x);
    double p = -0.0012624911;
    for (double c : {0.0066700901, -0.0170881256, 0.0308918810, -0.0501743046, 0.0889789874,
                     -0.2145988016, 1.5707963050})
        p = p * a + c;
    const double r = std::sqrt(1 - a) * p / kPi;
    return x >= 0 ? r : 1 - r;
}

// Log likelihood of the photons under the edge at `delta`, over that of the uniform disc:
// sum log(a(u_i) / A) (a = edgeCircleFraction, A = edgeDiscFraction). `invRoot` holds
// 1/sqrt(u_i) in descending order (ascending u), so photons within the lit inner circle
// (u <= delta^2, delta > 0; a = 1) are a prefix to skip. Factors are multiplied in runs and
// logged together: the log is the dearest part.
double logLikelihood(std::span<const double> invRoot, double delta) {
    const double area = edgeDiscFraction(delta);
    if (area <= 0) return kNoEdge;
    size_t i = 0;
    if (delta > 0)
        while (i < invRoot.size() && delta * invRoot[i] >= 1) ++i;
    double sum = 0, product = 1;
    for (; i < invRoot.size(); ++i) {
        product *= 1 - acosOverPi(clampUnit(delta * invRoot[i]));
        if (product < 1e-200) {
            if (!(product > 0)) return kNoEdge;  // a photon in the dark: impossible edge
            sum += std::log(product);
            product = 1;
        }
    }
    return sum + std::log(product) - double(invRoot.size()) * std::log(area);
}

}  // namespace

double edgeDiscFraction(double delta) {
    const double d = clampUnit(delta);
    return (kPi - std::acos(d) + d * std::sqrt(1 - d * d)) / kPi;
}

double edgeCircleFraction(double delta, double u) {
    if (u <= 0) return delta > 0 ? 1 : delta < 0 ? 0 : 0.5;
    return 1 - std::acos(clampUnit(delta / std::sqrt(u))) / kPi;
}

double edgeRadialCdf(double delta, double u) {
    if (u <= 0) return 0;
    if (u >= 1) return 1;
    return u * edgeDiscFraction(delta / std::sqrt(u)) / edgeDiscFraction(delta);
}

bool edgeWorthFitting(std::span<const double> u) {
    // Under the uniform disc, k min(u) is about exponential with mean 1 and the mean of u
    // normal with mean 1/2 and variance 1/(12 k). Outside an edge the nearest photons are
    // missing (a large minimum); inside one they crowd the centre (a small mean).
    const double k = double(u.size());
    double low = 1, sum = 0;
    for (double v : u) {
        low = std::min(low, v);
        sum += v;
    }
    const double z = (sum / k - 0.5) * std::sqrt(12 * k);
    return k * low >= kPretestGap || std::fabs(z) >= kPretestMean;
}

EdgeFit maximiseEdgeLikelihood(std::span<const double> sortedU, std::vector<double>& scratch) {
    EdgeFit best;  // delta 1: no edge, likelihood ratio 0
    if (sortedU.size() < kMinEdgePhotons) return best;
    // A photon at the query itself (u = 0) is taken to lie just off it.
    constexpr double kMinU = 1e-12;
    scratch.resize(sortedU.size());
    for (size_t i = 0; i < sortedU.size(); ++i)
        scratch[i] = 1 / std::sqrt(std::max(sortedU[i], kMinU));
    const std::span<const double> inv(scratch);
    // Edges darker than the nearest photon are impossible; delta = 1 is the uniform disc.
    const double lo = std::max(-1.0, -std::sqrt(std::max(sortedU[0], kMinU)));
    constexpr int kGrid = 24;
    const double step = (1 - lo) / kGrid;
    for (int j = 1; j < kGrid; ++j) {
        const double d = lo + j * step;
        const double l = logLikelihood(inv, d);
        if (l > best.logLikelihoodRatio) best = {d, l, 1};
    }
    if (best.delta >= 1) return best;
    // Golden-section search within a grid step either side of the best grid point.
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double a = best.delta - step, b = best.delta + step;
    double c = b - g * (b - a), d = a + g * (b - a);
    double lc = logLikelihood(inv, c), ld = logLikelihood(inv, d);
    for (int it = 0; it < 12; ++it) {
        if (lc > ld) {
            b = d, d = c, ld = lc;
            c = b - g * (b - a), lc = logLikelihood(inv, c);
        } else {
            a = c, c = d, lc = ld;
            d = a + g * (b - a), ld = logLikelihood(inv, d);
        }
    }
    if (lc > best.logLikelihoodRatio) best = {c, lc, 1};
    if (ld > best.logLikelihoodRatio) best = {d, ld, 1};
    return best;
}

double edgeFactor(const EdgeFit& fit, const EdgeParams& params) {
    const double stat = 2 * fit.logLikelihoodRatio;
    if (!(stat > params.onset)) return 1;
    const double w = std::min(1.0, (stat - params.onset) / (params.full - params.onset));
    const double lit = std::clamp(0.5 + fit.delta / (2 * params.blur), 0.0, 1.0);
    return (1 - w) + w * lit / edgeDiscFraction(fit.delta);
}

EdgeFit fitEdge(std::span<double> u, std::vector<double>& scratch, const EdgeParams& params) {
    if (u.size() < kMinEdgePhotons || !edgeWorthFitting(u)) return {};
    std::sort(u.begin(), u.end());
    EdgeFit fit = maximiseEdgeLikelihood(u, scratch);
    fit.factor = edgeFactor(fit, params);
    return fit;
}

double edgeOffsetOfFraction(double fraction) {
    if (fraction <= 0) return -1;
    if (fraction >= 1) return 1;
    double lo = -1, hi = 1;
    for (int i = 0; i < 48; ++i) {
        const double mid = 0.5 * (lo + hi);
        (edgeDiscFraction(mid) < fraction ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double edgeGradientFactor(std::span<const double> u, double delta, std::vector<double>& scratch) {
    if (u.size() < kMinEdgePhotons) return 1;
    const double d = clampUnit(delta);
    const double area = edgeDiscFraction(d);
    const double moment = -2 / (3 * kPi) * std::pow(1 - d * d, 1.5);
    if (!(area > 0) || moment == 0) return 1;
    // Written as p(u) = a(u) / A + gamma c(u), c = m - Mx a / A, with gamma = beta / (A +
    // beta Mx), the log likelihood is concave in gamma (a mixture's weight): Newton
    // converges from 0. The factor is then 1 - gamma Mx. A photon the probes' edge leaves
    // outside (a = 0) counts as just inside.
    scratch.clear();  // a_i / A and c_i, in turn
    for (double ui : u) {
        const double root = std::sqrt(std::max(ui, 1e-12));
        const double c = clampUnit(d / root);
        const double a = std::max(1 - acosOverPi(c), 1e-3) / area;
        const double m = -root * std::sqrt(1 - c * c) / kPi;
        scratch.push_back(a);
        scratch.push_back(m - moment * a);
    }
    // 1 + beta x >= 0 over the part (x from -1 to delta), with a margin; gamma rises with beta.
    const double betaMax = 0.95, betaMin = d > 0.01 ? -0.95 / d : -95;
    auto gammaOf = [&](double beta) { return beta / (area + beta * moment); };
    const double lo = gammaOf(betaMin), hi = gammaOf(betaMax);
    double gamma = 0;
    for (int iter = 0; iter < 30; ++iter) {
        double g = 0, h = 0;
        for (size_t i = 0; i < scratch.size(); i += 2) {
            const double c = scratch[i + 1], v = scratch[i] + gamma * c;
            g += c / v;
            h -= c * c / (v * v);
        }
        if (!(h < 0)) return 1;  // no photon says anything about the gradient
        const double next = std::clamp(gamma - g / h, lo, hi);
        const bool done = std::fabs(next - gamma) < 1e-7;
        gamma = next;
        if (done) break;
    }
    return 1 - gamma * moment;
}

}  // namespace rp::pmap
