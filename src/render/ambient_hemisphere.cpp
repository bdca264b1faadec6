// Hemisphere sampling for the ambient calculation (see ambient_hemisphere.h).
#include "render/ambient_hemisphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

namespace rp::render {

namespace {

struct Division {
    Color sum;                      // sum of sample radiances
    double sumB = 0;                // brightness sum (for the neighbours' spread)
    double prior = 0;               // variance around it, from its neighbours (super-sampling)
    double minDistance = 1e10;      // nearest surface seen through this division
    double hessian[3] = {0, 0, 0};  // sum over samples of their Hessian terms (see below)
    int n = 0;
};

double meanBrightness(const Division& d) { return d.n > 0 ? d.sumB / d.n : 0; }

// HemisphereEstimate::horizonDistance and overheadInverseDistance from the divisions.
void occluders(std::span<const Division> div, int M, int N, HemisphereEstimate& est) {
    est.horizonDistance.assign(size_t(N), 1e10);
    double overhead = 0;
    int overheadCount = 0;
    for (int j = 0; j < M; ++j) {
        const bool horizon = double(j + 1) / M > 0.8, above = double(j + 1) / M <= 0.25;
        if (!horizon && !above) continue;
        for (int k = 0; k < N; ++k) {
            const double d = div[size_t(j) * N + k].minDistance;
            if (horizon)
                est.horizonDistance[size_t(k)] = std::min(est.horizonDistance[size_t(k)], d);
            if (above) {
                overhead += d < 1e10 ? 1 / d : 0;
                ++overheadCount;
            }
        }
    }
    est.overheadInverseDistance = overheadCount > 0 ? overhead / overheadCount : 0;
}

}  // namespace

double HemisphereEstimate::maxCurvature() const {
    double mean = 0.5 * (hessian[0] + hessian[2]);
    double half = 0.5 * (hessian[0] - hessian[2]);
    return std::abs(mean) + std::sqrt(half * half + hessian[1] * hessian[1]);
}

void tangentFrame(const Vec3& n, Vec3& u, Vec3& v) {
    // Duff, Burgess, Christensen et al. 2017, "Building an Orthonormal Basis, Revisited".
    double sign = std::copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double b = n.x * n.y * a;
    u = Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    v = Vec3(b, sign + n.y * n.y * a, -n.y);
}

HemisphereParams hemisphereDivisions(int divisions, int supersamples, double weight, bool cached) {
    HemisphereParams p;
    if (cached) {
        p.thetaDivisions = std::max(3, int(std::sqrt(divisions * weight / kPi) + 0.5));
        p.phiDivisions = std::max(1, int(kPi * p.thetaDivisions + 0.5));
    } else {
        const int n = std::max(1, int(std::sqrt(divisions * weight) + 0.5));
        p.thetaDivisions = std::max(1, int(n / std::sqrt(kPi) + 0.5));
        p.phiDivisions = std::max(1, int(double(n) * n / p.thetaDivisions + 0.5));
    }
    p.superSamples = std::max(0, int(supersamples * weight + 0.5));
    return p;
}

HemisphereEstimate sampleHemisphere(const Vec3& origin, const Vec3& normal,
                                    const HemisphereParams& params, HemisphereTracer& tracer,
                                    Rng& rng) {
    const int M = std::max(1, params.thetaDivisions);
    const int N = std::max(1, params.phiDivisions);
    Vec3 ux, uy;
    tangentFrame(normal, ux, uy);
    // Most hemispheres without the cache are a few divisions (deep, light rays): those
    // live on the stack, as a heap block per hemisphere was a visible part of their cost.
    constexpr size_t kOnStack = 16;
    std::array<Division, kOnStack> few;
    std::vector<Division> many;
    const size_t count = size_t(M) * N;
    if (count > kOnStack) many.resize(count);
    const std::span<Division> div =
        count > kOnStack ? std::span<Division>(many) : std::span<Division>(few.data(), count);
    HemisphereEstimate est;
    const double share = 1.0 / (double(M) * N);  // of a division's only sample
    int firstPassUntraced = 0;

    // One jittered sample in division (j, k): sin^2(theta) is uniform for a cosine
    // density, so rows of equal sin^2 width carry equal weight (Ward et al. 1988).
    auto shoot = [&](int j, int k) {
        double sin2 = (j + rng.uniform()) / M;
        double phi = 2 * kPi * (k + rng.uniform()) / N;
        double sinT = std::sqrt(sin2), cosT = std::sqrt(std::max(0.0, 1 - sin2));
        Vec3 dir =
            normalize(ux * (std::cos(phi) * sinT) + uy * (std::sin(phi) * sinT) + normal * cosT);
        HemisphereTracer::Sample s =
            tracer.trace(origin, dir, params.sampleLevel, params.sampleWeight, share);
        Division& d = div[size_t(j) * N + k];
        if (!s.traced && d.n == 0) ++firstPassUntraced;
        double b = s.radiance.brightness();
        d.sum += s.radiance;
        d.sumB += b;
        ++d.n;
        double dist = s.distance > 0 ? s.distance : 1e10;
        d.minDistance = std::min(d.minDistance, dist);
        if (params.gradients && dist < 1e10) {
            // Hessian of this sample's share of the value under a tangential move of the
            // point (see the header): the surface seen is a small patch at distance d with
            // unit normal facing back along -mu (mu . dir = cos_phi); its share of E is
            // L A cos(theta') cos(phi') / r'^2 with the patch area A fixed, and twice
            // differentiating at the centre gives, in the tangent frame (t = tangential part
            // of dir, mu_t of mu), L pi/(MN) / (d^2 cos_phi) times
            //     24 cos_phi t t^T - 4 (mu_t t^T + t mu_t^T) - 4 cos_phi I.
            // Exact for an infinite plane (the sum vanishes, as irradiance does not change
            // along it) and for a sphere around the point. Grazing patches are capped.
            Vec3 mu = s.normal;
            double cphi = dot(mu, dir);
            if (cphi < 0) {
                mu = -mu;
                cphi = -cphi;
            }
            if (dot(mu, mu) < 0.5) {  // unknown normal: a patch facing the point
                mu = dir;
                cphi = 1;
            }
            cphi = std::max(cphi, 0.05);
            double tx = std::cos(phi) * sinT, ty = std::sin(phi) * sinT;
            double mx = dot(mu, ux), my = dot(mu, uy);
            double f = b / (dist * dist * cphi);
            d.hessian[0] += f * (24 * cphi * tx * tx - 8 * mx * tx - 4 * cphi);
            d.hessian[1] += f * (24 * cphi * tx * ty - 4 * (mx * ty + tx * my));
            d.hessian[2] += f * (24 * cphi * ty * ty - 8 * my * ty - 4 * cphi);
        }
        est.sumInverseDistance += 1 / dist;
        ++est.samples;
        if (dist < 1e10) ++est.hits;
    };

    for (int j = 0; j < M; ++j)
        for (int k = 0; k < N; ++k) shoot(j, k);
    est.divisions = M * N;
    est.untraced = firstPassUntraced;

    // RADIANCE compat (ambcomp.c samp_hemi): no super-sampling of 49 divisions or fewer
    // (MINADIV^2), where the neighbours' differences say little.
    // Nor where samples were lost (ambcomp.c: a "soft failure" is not super-sampled).
    if (params.superSamples > 0 && M * N > 49 && est.untraced == 0) {
        // How much radiance varies around each division: the spread of its neighbours'
        // samples (phi wraps around), not counting its own. RADIANCE (ambcomp.c
        // getambdiffs) uses the differences to the division's own sample; then a bright
        // first sample draws the extra samples that dilute it, and a dark one keeps its
        // division dark: 46 % low on stripes finer than a division, 8 % on sky between
        // slats at -ab 2. (RADIANCE's own stops super-sampling where two neighbouring
        // divisions are black, so there it does not show.)
        for (int j = 0; j < M; ++j)
            for (int k = 0; k < N; ++k) {
                double b[4];
                int count = 0;
                auto add = [&](int jj, int kk) {
                    b[count++] = meanBrightness(div[size_t(jj) * N + kk]);
                };
                if (j > 0) add(j - 1, k);
                if (j + 1 < M) add(j + 1, k);
                if (N > 1) {
                    add(j, (k + N - 1) % N);
                    add(j, (k + 1) % N);
                }
                double mean = 0, var = 0;
                for (int i = 0; i < count; ++i) mean += b[i] / count;
                for (int i = 0; i < count; ++i) var += (b[i] - mean) * (b[i] - mean) / count;
                div[size_t(j) * N + k].prior = var;
            }
        // As ambcomp.c ambsupersamp: the super-samples are shared out once, in proportion
        // to the guessed variances (rounded at random).
        double remaining = 0;
        for (const Division& d : div) remaining += d.prior;
        int left = params.superSamples;
        for (size_t i = 0; i < div.size() && left > 0 && remaining > 0; ++i) {
            const double e = div[i].prior;
            for (int n = int(e / remaining * left + rng.uniform()); n > 0 && left > 0; --n, --left)
                shoot(int(i) / N, int(i) % N);
            remaining -= e;
        }
    }

    for (const Division& d : div) est.value += d.sum / d.n;
    est.value = est.value / double(div.size());
    if (!params.gradients) return est;
    occluders(div, M, N, est);
    for (const Division& d : div)
        for (int i = 0; i < 3; ++i) est.hessian[i] += d.hessian[i] / d.n;
    for (double& h : est.hessian) h /= double(div.size());

    // Row boundaries: sin^2(theta_j-) = j / M.
    auto sinBound = [&](int j) { return std::sqrt(double(j) / M); };
    auto thetaBound = [&](int j) { return std::asin(std::min(1.0, sinBound(j))); };
    auto L = [&](int j, int k) { return meanBrightness(div[size_t(j) * N + (k % N)]); };
    auto R = [&](int j, int k) { return div[size_t(j) * N + (k % N)].minDistance; };

    // Rotational gradient (Ward & Heckbert 1992, eq. 10 in our sign convention):
    // dV/d(rotation) = E_cos[L tan(theta) v_phi], with tan and v_phi averaged exactly over
    // each division so the horizon row stays finite.
    Vec3 gr;
    const double sincPhi = N > 1 ? std::sin(kPi / N) / (kPi / N) : 0;
    for (int k = 0; k < N; ++k) {
        double phi = 2 * kPi * (k + 0.5) / N;
        Vec3 vk = ux * -std::sin(phi) + uy * std::cos(phi);
        double rowSum = 0;
        for (int j = 0; j < M; ++j) {
            double t0 = thetaBound(j), t1 = thetaBound(j + 1);
            double tanAvg =
                M * ((t1 - std::sin(t1) * std::cos(t1)) - (t0 - std::sin(t0) * std::cos(t0)));
            rowSum += L(j, k) * tanAvg;
        }
        gr += vk * (rowSum * sincPhi);
    }
    est.gradDirection = gr / (double(M) * N);

    // Translational gradient (Ward & Heckbert 1992, eq. 12): moving the point shifts the
    // division boundaries over the surfaces seen, by (dx / distance); each boundary
    // contributes the radiance step across it times its cosine-weighted length.
    Vec3 gt;
    for (int k = 0; k < N; ++k) {
        double phiC = 2 * kPi * (k + 0.5) / N, phiB = 2 * kPi * k / N;
        Vec3 uk = ux * std::cos(phiC) + uy * std::sin(phiC);
        Vec3 vkb = ux * -std::sin(phiB) + uy * std::cos(phiB);
        double radial = 0, tangential = 0;
        for (int j = 1; j < M; ++j) {
            double s = sinBound(j), c2 = 1 - s * s;
            radial += s * c2 * (L(j, k) - L(j - 1, k)) / std::min(R(j, k), R(j - 1, k));
        }
        if (N > 1)
            for (int j = 0; j < M; ++j) {
                int km = (k + N - 1) % N;
                tangential += (sinBound(j + 1) - sinBound(j)) * (L(j, k) - L(j, km)) /
                              std::min(R(j, k), R(j, km));
            }
        gt += uk * (2 * std::sin(kPi / N) * radial) + vkb * tangential;
    }
    est.gradPosition = gt / kPi;
    return est;
}

}  // namespace rp::render
