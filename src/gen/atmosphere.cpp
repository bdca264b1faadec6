// The atmosphere's model (what it is made of) and its tables' lookups; the
// precomputation is in atmosphere_precompute.cpp.
#include "gen/atmosphere.h"

#include <cstring>
#include <fstream>

#include "gen/atmosphere_grid.h"
#include "util/error.h"
#include "util/file_write.h"

namespace rp::gen::atmos {

// Physical data as RADIANCE 6.1a's genssky tabulates them (src/gen/atmos.c): the
// extraterrestrial spectrum in 20 nm band means, the sea-level Rayleigh coefficients
// and scale heights of Anderson et al.'s five standard atmospheres, and the ozone
// absorption at its peak density.
const Spectrum kExtraterrestrial = {1.11099345, 1.75363199, 1.67126921, 1.97235667, 2.01863015,
                                    1.93612482, 1.87310758, 1.88792588, 1.86274213, 1.84433248,
                                    1.80370942, 1.73020456, 1.67036654, 1.57482149, 1.53646383,
                                    1.45515319, 1.38207435, 1.3265141,  1.26648111, 1.20592043};

namespace {

struct RayleighData {
    double scaleHeight;
    Spectrum beta;
};

const RayleighData& rayleighData(RayleighProfile p) {
    static const RayleighData kData[] = {
        {8820, {4.63889967e-05, 3.76703293e-05, 3.09193474e-05, 2.56223081e-05, 2.14198405e-05,
                1.80483398e-05, 1.53177709e-05, 1.30867298e-05, 1.12487269e-05, 9.72370830e-06,
                8.44932642e-06, 7.37769845e-06, 6.47116653e-06, 5.70005327e-06, 5.04091603e-06,
                4.47430240e-06, 3.98549839e-06, 3.56178512e-06, 3.19293761e-06, 2.87072599e-06}},
        {8100, {5.03857564e-05, 4.09159104e-05, 3.35832809e-05, 2.78298619e-05, 2.32653203e-05,
                1.96033395e-05, 1.66375116e-05, 1.42142496e-05, 1.22178890e-05, 1.05614786e-05,
                9.17729921e-06, 8.01334246e-06, 7.02870602e-06, 6.19115557e-06, 5.47522872e-06,
                4.85979708e-06, 4.32887894e-06, 3.86865960e-06, 3.46803311e-06, 3.11806054e-06}},
        {8550, {4.73789047e-05, 3.84741872e-05, 3.15791442e-05, 2.61690698e-05, 2.18769246e-05,
                1.84334785e-05, 1.56446412e-05, 1.33659912e-05, 1.14887667e-05, 9.93120528e-06,
                8.62962901e-06, 7.53513326e-06, 6.60925660e-06, 5.82168833e-06, 5.14848557e-06,
                4.56978082e-06, 4.07054608e-06, 3.63779107e-06, 3.26107261e-06, 2.93198523e-06}},
        {7600, {5.30623659e-05, 4.30894595e-05, 3.53673035e-05, 2.93082494e-05, 2.45012287e-05,
                2.06447149e-05, 1.75213353e-05, 1.49693438e-05, 1.28669320e-05, 1.11225291e-05,
                9.66481886e-06, 8.43902999e-06, 7.40208736e-06, 6.52004427e-06, 5.76608570e-06,
                5.11796089e-06, 4.55883914e-06, 4.07417187e-06, 3.65226316e-06, 3.28369923e-06}},
        {9050, {4.55376661e-05, 3.69790036e-05, 3.03519157e-05, 2.51520876e-05, 2.10267438e-05,
                1.77171168e-05, 1.50366593e-05, 1.28465622e-05, 1.10422904e-05, 9.54525887e-06,
                8.29426444e-06, 7.24230298e-06, 6.35240772e-06, 5.59544593e-06, 4.94840517e-06,
                4.39219003e-06, 3.91235655e-06, 3.49641927e-06, 3.13434084e-06, 2.81804244e-06}},
    };
    return kData[static_cast<int>(p)];
}

}  // namespace

const Spectrum& Model::ozoneAbsorption() {
    static const Spectrum kOzone = {3.5661864e-09, 1.4848362e-08, 4.5415674e-08, 1.2446184e-07,
                                    2.6461576e-07, 4.8451984e-07, 8.609148e-07,  1.480537e-06,
                                    1.8809e-06,    2.5107328e-06, 2.5263174e-06, 2.313507e-06,
                                    1.727741e-06,  1.2027012e-06, 7.915902e-07,  5.0639202e-07,
                                    3.5285684e-07, 2.23021e-07,   1.7395638e-07, 1.5052574e-07};
    return kOzone;
}

RayleighProfile rayleighProfileFor(double latitude, int month) {
    const double deg = std::fabs(latitude) * 180 / kPi;
    bool summer = month >= 4 && month <= 9;
    if (latitude < 0) summer = !summer;
    if (deg > 67)
        return summer ? RayleighProfile::SubarcticSummer : RayleighProfile::SubarcticWinter;
    if (deg > 23)
        return summer ? RayleighProfile::MidlatitudeSummer : RayleighProfile::MidlatitudeWinter;
    return RayleighProfile::Tropical;
}

const char* profileTag(RayleighProfile p) {
    static const char* kTags[] = {"ms", "mw", "ss", "sw", "tr"};
    return kTags[static_cast<int>(p)];
}

Model Model::make(RayleighProfile profile, const calc::DataFile& table, double mieScale,
                  double groundAlbedo) {
    if (table.dimensions() != 2 || table.axis(1).count != kBands)
        throw InputError("aerosol table must have 2 dimensions, altitude and 20 bands");
    Model m;
    m.rayleighScaleHeight = rayleighData(profile).scaleHeight;
    m.rayleigh = rayleighData(profile).beta;
    m.groundAlbedo = groundAlbedo;
    const auto& band = table.axis(1);
    const int steps = static_cast<int>((kTopRadius - kGroundRadius) / kMieStep);
    m.mie.resize(size_t(steps) + 1);
    for (int k = 0; k <= steps; ++k)
        for (int b = 0; b < kBands; ++b) {
            // The band axis is "0 19 20" in genssky's files; read it by position.
            const double at = band.points.empty() ? band.begin + b * (band.end - band.begin) / 19
                                                  : band.points[size_t(b)];
            const double point[2] = {k * kMieStep, at};
            m.mie[size_t(k)][b] = std::max(0.0, table.value(point) * mieScale);
        }
    return m;
}

double Model::rayleighDensity(double h) const {
    return std::clamp(std::exp(-h / rayleighScaleHeight), 0.0, 1.0);
}

// A tent from 10 km up to its peak at 25 km and down to nothing at 40 km.
double Model::ozoneDensity(double h) {
    const double d = h < 25000 ? h / 15000 - 2.0 / 3 : 8.0 / 3 - h / 15000;
    return std::clamp(d, 0.0, 1.0);
}

Spectrum Model::mieAt(double h) const {
    const double f = std::clamp(h / kMieStep, 0.0, double(mie.size() - 1));
    const size_t i0 = std::min(static_cast<size_t>(f), mie.size() - 2);
    const double w = f - double(i0);
    Spectrum s;
    for (int b = 0; b < kBands; ++b) s[b] = (1 - w) * mie[i0][b] + w * mie[i0 + 1][b];
    return s;
}

namespace grid {

double muSUnit(double muS) {
    const double d = distanceToTop(kGroundRadius, muS);
    const double dMin = kTopRadius - kGroundRadius, dMax = kH;
    const double a = (d - dMin) / (dMax - dMin);
    const double A = (distanceToTop(kGroundRadius, kMinSunCosine) - dMin) / (dMax - dMin);
    return std::clamp(std::max(1 - a / A, 0.0) / (1 + a), 0.0, 1.0);
}

double muSOfUnit(double x) {
    const double dMin = kTopRadius - kGroundRadius, dMax = kH;
    const double A = (distanceToTop(kGroundRadius, kMinSunCosine) - dMin) / (dMax - dMin);
    const double a = (A - x * A) / (1 + x * A);
    const double d = dMin + std::min(a, A) * (dMax - dMin);
    return d == 0 ? 1.0 : clampCosine((kH * kH - d * d) / (2 * kGroundRadius * d));
}

Unit4 scatteringUnit(double r, double mu, double muS, double nu, bool ground) {
    const double rho = safeSqrt(r * r - kGroundRadius * kGroundRadius);
    const double rmu = r * mu;
    const double disc = rmu * rmu - r * r + kGroundRadius * kGroundRadius;
    double xMu;
    if (ground) {
        const double d = -rmu - safeSqrt(disc), dMin = r - kGroundRadius, dMax = rho;
        xMu = dMax == dMin ? 0.0 : (d - dMin) / (dMax - dMin);
    } else {
        const double d = -rmu + safeSqrt(disc + kH * kH), dMin = kTopRadius - r, dMax = rho + kH;
        xMu = (d - dMin) / (dMax - dMin);
    }
    return {rho / kH, xMu, muSUnit(muS), 0.5 * (nu + 1)};
}

void scatteringParams(const Unit4& u, bool ground, double& r, double& mu, double& muS, double& nu) {
    const double rho = kH * u.r;
    r = std::sqrt(rho * rho + kGroundRadius * kGroundRadius);
    if (ground) {
        const double dMin = r - kGroundRadius, dMax = rho;
        const double d = dMin + u.mu * (dMax - dMin);
        mu = d == 0 ? -1.0 : clampCosine(-(rho * rho + d * d) / (2 * r * d));
    } else {
        const double dMin = kTopRadius - r, dMax = rho + kH;
        const double d = dMin + u.mu * (dMax - dMin);
        mu = d == 0 ? 1.0 : clampCosine((kH * kH - rho * rho - d * d) / (2 * r * d));
    }
    muS = muSOfUnit(u.muS);
    const double s = std::sqrt(std::max(0.0, (1 - mu * mu) * (1 - muS * muS)));
    nu = std::clamp(clampCosine(2 * u.nu - 1), mu * muS - s, mu * muS + s);
}

Spectrum lookup2(const std::vector<float>& t, int ny, int nx, Unit2 u) {
    const Span sx = span(u.x, nx), sy = span(u.y, ny);
    Spectrum s{};
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const double w = (j ? sy.w : 1 - sy.w) * (i ? sx.w : 1 - sx.w);
            if (w == 0) continue;
            addScaled(&t[(size_t(sy.i0 + j) * nx + sx.i0 + i) * kBands], w, s);
        }
    return s;
}

Spectrum lookupScattering(const std::vector<float>& t, const Resolution& res, double r, double mu,
                          double muS, double nu, bool ground) {
    const Unit4 u = scatteringUnit(r, mu, muS, nu, ground);
    const int half = res.scatteringMu / 2;
    const Span sr = span(u.r, res.scatteringR), sm = span(u.mu, half),
               ss = span(u.muS, res.scatteringMuS), sn = span(u.nu, res.scatteringNu);
    const int muBase = ground ? 0 : half;
    Spectrum out{};
    for (int a = 0; a < 16; ++a) {
        const int dr = a & 1, dm = (a >> 1) & 1, ds = (a >> 2) & 1, dn = (a >> 3) & 1;
        const double w = (dr ? sr.w : 1 - sr.w) * (dm ? sm.w : 1 - sm.w) * (ds ? ss.w : 1 - ss.w) *
                         (dn ? sn.w : 1 - sn.w);
        if (w == 0) continue;
        addScaled(&t[scatteringIndex(res, sr.i0 + dr, muBase + sm.i0 + dm, ss.i0 + ds, sn.i0 + dn)],
                  w, out);
    }
    return out;
}

Spectrum transmittanceAlong(const std::vector<float>& t, const Resolution& res, double r, double mu,
                            double d, bool ground) {
    const double rd = radiusAt(r, mu, d);
    const double mud = clampCosine((r * mu + d) / rd);
    auto top = [&](double rr, double m) {
        return lookup2(t, res.transmittanceR, res.transmittanceMu, transmittanceUnit(rr, m));
    };
    // Through the ground the ratio is taken the other way round, where both rays reach
    // the top without meeting the earth.
    const Spectrum a = ground ? top(rd, -mud) : top(r, mu);
    const Spectrum b = ground ? top(r, -mu) : top(rd, mud);
    Spectrum s;
    for (int i = 0; i < kBands; ++i) s[i] = b[i] > 0 ? std::min(a[i] / b[i], 1.0) : 0.0;
    return s;
}

Spectrum transmittanceToSun(const std::vector<float>& t, const Resolution& res, double r,
                            double muS) {
    const double sinH = kGroundRadius / r;
    const double cosH = -std::sqrt(std::max(0.0, 1 - sinH * sinH));
    const double edge = sinH * kSunAngularRadius;
    const double x = std::clamp((muS - cosH + edge) / (2 * edge), 0.0, 1.0);
    const double visible = x * x * (3 - 2 * x);
    Spectrum s = lookup2(t, res.transmittanceR, res.transmittanceMu, transmittanceUnit(r, muS));
    for (double& v : s) v *= visible;
    return s;
}

}  // namespace grid

Spectrum Atmosphere::scattered(double r, double mu, double muS, double nu, bool ground) const {
    const Spectrum ray = grid::lookupScattering(scattering_, res_, r, mu, muS, nu, ground);
    const Spectrum mie = grid::lookupScattering(singleMie_, res_, r, mu, muS, nu, ground);
    const double pr = grid::rayleighPhase(nu), pm = grid::miePhase(nu);
    Spectrum s;
    for (int b = 0; b < kBands; ++b) s[b] = ray[b] * pr + mie[b] * pm;
    return s;
}

Spectrum Atmosphere::transmittance(double r, double mu, double d, bool ground) const {
    return grid::transmittanceAlong(transmittance_, res_, r, mu, d, ground);
}

Spectrum Atmosphere::transmittanceToSun(double r, double muS) const {
    return grid::transmittanceToSun(transmittance_, res_, r, muS);
}

Spectrum Atmosphere::transmittanceToTop(double r, double mu) const {
    return grid::lookup2(transmittance_, res_.transmittanceR, res_.transmittanceMu,
                         grid::transmittanceUnit(r, mu));
}

Spectrum Atmosphere::indirectIrradiance(double r, double muS) const {
    return grid::lookup2(irradiance_, res_.irradianceR, res_.irradianceMuS,
                         grid::irradianceUnit(r, muS));
}

Spectrum Atmosphere::radiance(const Vec3& dir, const Vec3& sun, double height) const {
    const double r = kGroundRadius + height;
    const double mu = dir.z, muS = sun.z, nu = dot(dir, sun);
    const bool ground = grid::hitsGround(r, mu);
    Spectrum s = scattered(r, mu, muS, nu, ground);
    if (!ground) return s;
    // The ground point's own zenith differs from ours by the earth's curvature.
    const double d = grid::distanceToGround(r, mu);
    const Vec3 normal = normalize(Vec3{0, 0, r} + dir * d);
    const double muG = dot(normal, sun);
    const Spectrum indirect = indirectIrradiance(kGroundRadius, muG);
    const Spectrum toSun = transmittanceToSun(kGroundRadius, muG);
    const Spectrum path = transmittance(r, mu, d, true);
    for (int b = 0; b < kBands; ++b) {
        const double e = indirect[b] + kExtraterrestrial[b] * toSun[b] * std::max(muG, 0.0);
        s[b] += path[b] * model_.groundAlbedo / kPi * e;
    }
    return s;
}

Spectrum Atmosphere::sunRadiance(const Vec3& sun, double height) const {
    Spectrum s = transmittanceToSun(kGroundRadius + height, sun.z);
    for (int b = 0; b < kBands; ++b) s[b] *= kExtraterrestrial[b] / kSunSolidAngle;
    return s;
}

namespace {

constexpr char kMagic[8] = {'R', 'P', 'A', 'T', 'M', 'O', 'S', '1'};

size_t tableFloats(const Resolution& res) {
    return size_t(res.transmittanceR) * res.transmittanceMu * kBands +
           2 * grid::scatteringSize(res) + size_t(res.irradianceR) * res.irradianceMuS * kBands;
}

}  // namespace

void Atmosphere::save(const std::string& path, const std::string& key) const {
    AtomicFile f(path);
    f.write(kMagic, sizeof kMagic);
    const uint32_t keyLen = static_cast<uint32_t>(key.size());
    f.write(&keyLen, sizeof keyLen);
    f.write(key.data(), key.size());
    for (const auto* t : {&transmittance_, &scattering_, &singleMie_, &irradiance_})
        f.write(t->data(), t->size() * sizeof(float));
    f.commit();
}

bool Atmosphere::load(const std::string& path, const Model& model, const Resolution& res,
                      const std::string& key) {
    std::ifstream in(path, std::ios::binary);
    char magic[sizeof kMagic];
    uint32_t keyLen = 0;
    if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0 ||
        !in.read(reinterpret_cast<char*>(&keyLen), sizeof keyLen) || keyLen != key.size())
        return false;
    std::string stored(keyLen, '\0');
    if (!in.read(stored.data(), keyLen) || stored != key) return false;
    std::vector<float> all(tableFloats(res));
    if (!in.read(reinterpret_cast<char*>(all.data()), std::streamsize(all.size() * 4)) ||
        in.peek() != std::char_traits<char>::eof())
        return false;
    auto take = [&, at = size_t(0)](std::vector<float>& t, size_t n) mutable {
        t.assign(all.begin() + std::ptrdiff_t(at), all.begin() + std::ptrdiff_t(at + n));
        at += n;
    };
    model_ = model;
    res_ = res;
    take(transmittance_, size_t(res.transmittanceR) * res.transmittanceMu * kBands);
    take(scattering_, grid::scatteringSize(res));
    take(singleMie_, grid::scatteringSize(res));
    take(irradiance_, size_t(res.irradianceR) * res.irradianceMuS * kBands);
    return true;
}

}  // namespace rp::gen::atmos
