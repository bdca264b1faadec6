// Building the atmosphere's tables order by order (Bruneton and Neyret 2008, in the
// 2017 formulation): transmittance, single scattering, then for every further order the
// light scattered at each point (from the previous order's radiance and the ground's
// reflection of the previous order's irradiance), the ground's new irradiance, and the
// new radiance integrated along every ray. Every grid cell is computed on its own, so
// any number of threads gives the same tables.
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "gen/atmosphere.h"
#include "gen/atmosphere_grid.h"
#include "util/error.h"

namespace rp::gen::atmos {

namespace {

using namespace grid;

// Integration steps along a ray and over the sphere of directions (those of the
// reference formulation).
constexpr int kTransmittanceSteps = 500;
constexpr int kRaySteps = 50;
constexpr int kDensityTheta = 16;     // and twice as many azimuths
constexpr int kIrradianceTheta = 16;  // over the upper hemisphere; four times the azimuths

struct Work {
    const Model& model;
    const Resolution& res;
    std::vector<float> transmittance;
    std::vector<float> deltaRayleigh, deltaMie;  // single scattering, without phase
    std::vector<float> deltaMultiple;            // the last order's radiance
    std::vector<float> density;                  // the light scattered at each point
    std::vector<float> deltaIrradiance;          // the ground's irradiance of the last order
};

void store(const Spectrum& s, float* out) {
    for (int b = 0; b < kBands; ++b) out[b] = static_cast<float>(s[b]);
}

void computeTransmittance(Work& w) {
    const Resolution& res = w.res;
    w.transmittance.assign(size_t(res.transmittanceR) * res.transmittanceMu * kBands, 0.f);
    const Spectrum& ozone = Model::ozoneAbsorption();
    tbb::parallel_for(0, res.transmittanceR, [&](int j) {
        for (int i = 0; i < res.transmittanceMu; ++i) {
            double r, mu;
            transmittanceParams({gridUnit(i, res.transmittanceMu), gridUnit(j, res.transmittanceR)},
                                r, mu);
            const double dx = distanceToTop(r, mu) / kTransmittanceSteps;
            double rayleigh = 0, ozoneDepth = 0;
            Spectrum mie{};
            for (int k = 0; k <= kTransmittanceSteps; ++k) {
                const double d = k * dx;
                const double h = std::sqrt(d * d + 2 * r * mu * d + r * r) - kGroundRadius;
                const double wt = (k == 0 || k == kTransmittanceSteps) ? 0.5 : 1.0;
                rayleigh += wt * w.model.rayleighDensity(h);
                ozoneDepth += wt * Model::ozoneDensity(h);
                const Spectrum m = w.model.mieAt(h);
                for (int b = 0; b < kBands; ++b) mie[b] += wt * m[b];
            }
            Spectrum t;
            for (int b = 0; b < kBands; ++b)
                t[b] = std::exp(-dx *
                                (rayleigh * w.model.rayleigh[b] + mie[b] + ozoneDepth * ozone[b]));
            store(t, &w.transmittance[(size_t(j) * res.transmittanceMu + i) * kBands]);
        }
    });
}

// The sun's irradiance on a horizontal surface, its disc partly set near the horizon.
void computeDirectIrradiance(Work& w) {
    const Resolution& res = w.res;
    w.deltaIrradiance.assign(size_t(res.irradianceR) * res.irradianceMuS * kBands, 0.f);
    for (int j = 0; j < res.irradianceR; ++j)
        for (int i = 0; i < res.irradianceMuS; ++i) {
            const double r =
                kGroundRadius + gridUnit(j, res.irradianceR) * (kTopRadius - kGroundRadius);
            const double muS = 2 * gridUnit(i, res.irradianceMuS) - 1;
            const double a = kSunAngularRadius;
            const double cosine = muS < -a ? 0.0 : muS > a ? muS : (muS + a) * (muS + a) / (4 * a);
            Spectrum t = lookup2(w.transmittance, res.transmittanceR, res.transmittanceMu,
                                 transmittanceUnit(r, muS));
            for (int b = 0; b < kBands; ++b) t[b] *= kExtraterrestrial[b] * cosine;
            store(t, &w.deltaIrradiance[(size_t(j) * res.irradianceMuS + i) * kBands]);
        }
}

// Calls f(cell offset, r, mu, muS, nu, ground) for every scattering cell, in parallel.
template <class F>
void forEachScatteringCell(const Resolution& res, F f) {
    const int half = res.scatteringMu / 2;
    tbb::parallel_for(0, res.scatteringR * res.scatteringMu, [&](int rm) {
        const int ir = rm / res.scatteringMu, im = rm % res.scatteringMu;
        const bool ground = im < half;
        for (int is = 0; is < res.scatteringMuS; ++is)
            for (int in = 0; in < res.scatteringNu; ++in) {
                const Unit4 u{gridUnit(ir, res.scatteringR),
                              gridUnit(ground ? im : im - half, half),
                              gridUnit(is, res.scatteringMuS), gridUnit(in, res.scatteringNu)};
                double r, mu, muS, nu;
                scatteringParams(u, ground, r, mu, muS, nu);
                f(scatteringIndex(res, ir, im, is, in), r, mu, muS, nu, ground);
            }
    });
}

void computeSingleScattering(Work& w) {
    const Resolution& res = w.res;
    w.deltaRayleigh.assign(scatteringSize(res), 0.f);
    w.deltaMie.assign(scatteringSize(res), 0.f);
    forEachScatteringCell(
        res, [&](size_t at, double r, double mu, double muS, double nu, bool ground) {
            const double dx = distanceToBoundary(r, mu, ground) / kRaySteps;
            Spectrum ray{}, mie{};
            for (int k = 0; k <= kRaySteps; ++k) {
                const double d = k * dx;
                const double rd = radiusAt(r, mu, d);
                const double muSd = clampCosine((r * muS + d * nu) / rd);
                const Spectrum along = transmittanceAlong(w.transmittance, res, r, mu, d, ground);
                const Spectrum toSun = transmittanceToSun(w.transmittance, res, rd, muSd);
                const double wt = (k == 0 || k == kRaySteps) ? 0.5 : 1.0;
                const double density = w.model.rayleighDensity(rd - kGroundRadius);
                const Spectrum m = w.model.mieAt(rd - kGroundRadius);
                for (int b = 0; b < kBands; ++b) {
                    const double t = wt * along[b] * toSun[b];
                    ray[b] += t * density;
                    mie[b] += t * m[b];
                }
            }
            for (int b = 0; b < kBands; ++b) {
                ray[b] *= dx * kExtraterrestrial[b] * w.model.rayleigh[b];
                mie[b] *= dx * kExtraterrestrial[b];
            }
            store(ray, &w.deltaRayleigh[at]);
            store(mie, &w.deltaMie[at]);
        });
}

// Radiance of scattering order `order` (1: single scattering, with its phase functions).
Spectrum orderRadiance(const Work& w, int order, double r, double mu, double muS, double nu,
                       bool ground) {
    if (order > 1) return lookupScattering(w.deltaMultiple, w.res, r, mu, muS, nu, ground);
    Spectrum s = lookupScattering(w.deltaRayleigh, w.res, r, mu, muS, nu, ground);
    const Spectrum m = lookupScattering(w.deltaMie, w.res, r, mu, muS, nu, ground);
    const double pr = rayleighPhase(nu), pm = miePhase(nu);
    for (int b = 0; b < kBands; ++b) s[b] = s[b] * pr + m[b] * pm;
    return s;
}

struct Direction {
    Vec3 v;
    double solidAngle;
};

// The light of order `order` arriving at radius r from every direction of a 16 x 32
// grid, with the sun at azimuth 0: sky and the ground's reflection of the previous
// order's irradiance.
void incidentLight(const Work& w, int order, double r, double muS,
                   const std::vector<Direction>& dirs, std::vector<Spectrum>& light) {
    const Vec3 sun{std::sqrt(std::max(0.0, 1 - muS * muS)), 0, muS};
    for (size_t k = 0; k < dirs.size(); ++k) {
        const Vec3& d = dirs[k].v;
        const bool ground = hitsGround(r, d.z);
        Spectrum l = orderRadiance(w, order, r, d.z, muS, dot(d, sun), ground);
        if (ground) {
            const double dist = distanceToGround(r, d.z);
            const Spectrum t = transmittanceAlong(w.transmittance, w.res, r, d.z, dist, true);
            const Vec3 normal = normalize(Vec3{0, 0, r} + d * dist);
            const Spectrum e = lookup2(w.deltaIrradiance, w.res.irradianceR, w.res.irradianceMuS,
                                       irradianceUnit(kGroundRadius, dot(normal, sun)));
            for (int b = 0; b < kBands; ++b) l[b] += t[b] * w.model.groundAlbedo / kPi * e[b];
        }
        light[k] = l;
    }
}

std::vector<Direction> sphereDirections() {
    std::vector<Direction> dirs;
    const double step = kPi / kDensityTheta;
    for (int l = 0; l < kDensityTheta; ++l) {
        const double theta = (l + 0.5) * step;
        for (int m = 0; m < 2 * kDensityTheta; ++m) {
            const double phi = (m + 0.5) * step;
            dirs.push_back({{std::cos(phi) * std::sin(theta), std::sin(phi) * std::sin(theta),
                             std::cos(theta)},
                            step * step * std::sin(theta)});
        }
    }
    return dirs;
}

// The light scattered towards every direction at every point (scattering density J).
void computeDensity(Work& w, int order) {
    const Resolution& res = w.res;
    const std::vector<Direction> dirs = sphereDirections();
    w.density.assign(scatteringSize(res), 0.f);
    const int half = res.scatteringMu / 2;
    tbb::parallel_for(0, res.scatteringR * res.scatteringMuS, [&](int rs) {
        const int ir = rs / res.scatteringMuS, is = rs % res.scatteringMuS;
        const double r = scatteringRadius(gridUnit(ir, res.scatteringR));
        const double muS = muSOfUnit(gridUnit(is, res.scatteringMuS));
        std::vector<Spectrum> light(dirs.size());
        incidentLight(w, order - 1, r, muS, dirs, light);
        const double h = r - kGroundRadius;
        const double rayleigh = w.model.rayleighDensity(h);
        const Spectrum mie = w.model.mieAt(h);
        const double sinS = std::sqrt(std::max(0.0, 1 - muS * muS));
        for (int im = 0; im < res.scatteringMu; ++im)
            for (int in = 0; in < res.scatteringNu; ++in) {
                const bool ground = im < half;
                const Unit4 u{gridUnit(ir, res.scatteringR),
                              gridUnit(ground ? im : im - half, half),
                              gridUnit(is, res.scatteringMuS), gridUnit(in, res.scatteringNu)};
                double rr, mu, muSs, nu;
                scatteringParams(u, ground, rr, mu, muSs, nu);
                const double sinV = std::sqrt(std::max(0.0, 1 - mu * mu));
                const double cosPhi =
                    sinV * sinS > 0 ? std::clamp((nu - mu * muS) / (sinV * sinS), -1.0, 1.0) : 1.0;
                const Vec3 view{sinV * cosPhi, sinV * std::sqrt(1 - cosPhi * cosPhi), mu};
                Spectrum j{};
                for (size_t k = 0; k < dirs.size(); ++k) {
                    const double c = dot(view, dirs[k].v);
                    const double pr = rayleigh * rayleighPhase(c) * dirs[k].solidAngle;
                    const double pm = miePhase(c) * dirs[k].solidAngle;
                    for (int b = 0; b < kBands; ++b)
                        j[b] += light[k][b] * (w.model.rayleigh[b] * pr + mie[b] * pm);
                }
                store(j, &w.density[scatteringIndex(res, ir, im, is, in)]);
            }
    });
}

// The sky's irradiance of order `order` on horizontal surfaces at every height.
void computeIndirectIrradiance(Work& w, int order, std::vector<float>& total) {
    const Resolution& res = w.res;
    std::vector<float> delta(size_t(res.irradianceR) * res.irradianceMuS * kBands, 0.f);
    const double dTheta = 0.5 * kPi / kIrradianceTheta, dPhi = dTheta;
    tbb::parallel_for(0, res.irradianceR, [&](int j) {
        for (int i = 0; i < res.irradianceMuS; ++i) {
            const double r =
                kGroundRadius + gridUnit(j, res.irradianceR) * (kTopRadius - kGroundRadius);
            const double muS = 2 * gridUnit(i, res.irradianceMuS) - 1;
            const Vec3 sun{std::sqrt(std::max(0.0, 1 - muS * muS)), 0, muS};
            Spectrum e{};
            for (int t = 0; t < kIrradianceTheta; ++t) {
                const double theta = (t + 0.5) * dTheta;
                for (int p = 0; p < 4 * kIrradianceTheta; ++p) {
                    const double phi = (p + 0.5) * dPhi;
                    const Vec3 d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                 std::cos(theta)};
                    const Spectrum l = orderRadiance(w, order, r, d.z, muS, dot(d, sun), false);
                    const double wt = d.z * dTheta * dPhi * std::sin(theta);
                    for (int b = 0; b < kBands; ++b) e[b] += l[b] * wt;
                }
            }
            store(e, &delta[(size_t(j) * res.irradianceMuS + i) * kBands]);
        }
    });
    for (size_t k = 0; k < delta.size(); ++k) total[k] += delta[k];
    w.deltaIrradiance = std::move(delta);
}

// The radiance of order `order`: the density integrated along every ray.
void computeMultipleScattering(Work& w, std::vector<float>& scattering) {
    const Resolution& res = w.res;
    w.deltaMultiple.assign(scatteringSize(res), 0.f);
    forEachScatteringCell(
        res, [&](size_t at, double r, double mu, double muS, double nu, bool ground) {
            const double dx = distanceToBoundary(r, mu, ground) / kRaySteps;
            Spectrum sum{};
            for (int k = 0; k <= kRaySteps; ++k) {
                const double d = k * dx;
                const double rd = radiusAt(r, mu, d);
                const double mud = clampCosine((r * mu + d) / rd);
                const double muSd = clampCosine((r * muS + d * nu) / rd);
                const Spectrum j = lookupScattering(w.density, res, rd, mud, muSd, nu, ground);
                const Spectrum t = transmittanceAlong(w.transmittance, res, r, mu, d, ground);
                const double wt = (k == 0 || k == kRaySteps) ? 0.5 : 1.0;
                for (int b = 0; b < kBands; ++b) sum[b] += wt * j[b] * t[b] * dx;
            }
            store(sum, &w.deltaMultiple[at]);
            const double pr = rayleighPhase(nu);
            for (int b = 0; b < kBands; ++b) scattering[at + b] += static_cast<float>(sum[b] / pr);
        });
}

}  // namespace

Atmosphere Atmosphere::compute(const Model& model, const Resolution& res, int threads) {
    if (res.orders < 1) throw InputError("the scattering order must be at least 1");
    if (res.scatteringMu % 2 || res.scatteringMu < 4)
        throw InputError("the scattering tables need an even mu size of at least 4");
    Atmosphere a;
    a.model_ = model;
    a.res_ = res;
    Work w{model, res, {}, {}, {}, {}, {}, {}};
    tbb::task_arena arena(std::max(1, threads));
    arena.execute([&] {
        computeTransmittance(w);
        computeDirectIrradiance(w);
        computeSingleScattering(w);
        a.scattering_ = w.deltaRayleigh;
        a.singleMie_ = w.deltaMie;
        a.irradiance_.assign(size_t(res.irradianceR) * res.irradianceMuS * kBands, 0.f);
        for (int order = 2; order <= res.orders; ++order) {
            computeDensity(w, order);
            computeIndirectIrradiance(w, order - 1, a.irradiance_);
            computeMultipleScattering(w, a.scattering_);
        }
    });
    a.transmittance_ = std::move(w.transmittance);
    return a;
}

}  // namespace rp::gen::atmos
