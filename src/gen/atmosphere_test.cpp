#include "gen/atmosphere.h"

#include <gtest/gtest.h>

#include <cmath>

#include "calc/data_file.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::gen::atmos {
namespace {

// An aerosol table of zeros: a pure Rayleigh atmosphere (with its ozone).
calc::DataFile noAerosol() {
    std::string text = "2\n0 60000 2\n0 19 20\n";
    for (int i = 0; i < 40; ++i) text += "0\n";
    return calc::DataFile::parse(text, "none");
}

Vec3 sunAt(double muS) { return {std::sqrt(1 - muS * muS), 0, muS}; }

// Band 0 (390 nm) carries almost no ozone absorption (3.6e-9 /m at the peak).
constexpr int kBlue = 0;

// Single scattering seen at the zenith from the ground of a plane-parallel exponential
// Rayleigh atmosphere without absorption: E0 P(nu) e^-tau (1 - e^-tau k) / k with
// k = 1/muS - 1, tau the vertical optical depth. The earth's curvature changes this by
// well under 1 % for a sun 42 degrees high.
TEST(Atmosphere, SingleScatteringMatchesThePlaneParallelClosedForm) {
    const Model m = Model::make(RayleighProfile::MidlatitudeWinter, noAerosol(), 1, 0);
    Resolution res;
    res.orders = 1;
    const Atmosphere a = Atmosphere::compute(m, res, 2);
    const double muS = 0.6645;
    const Spectrum l = a.radiance({0, 0, 1}, sunAt(muS), 10);
    for (int b : {0, 5, 19}) {
        const double tau =
            m.rayleigh[b] * m.rayleighScaleHeight * (1 - std::exp(-60000 / m.rayleighScaleHeight));
        const double k = 1 / muS - 1;
        const double phase = 3 / (16 * kPi) * (1 + muS * muS);
        const double closed =
            kExtraterrestrial[b] * phase * std::exp(-tau) * (1 - std::exp(-tau * k)) / k;
        // Band 5 (490 nm) loses 0.6 % to ozone, band 19 0.2 %.
        EXPECT_NEAR(l[b] / closed, 1, 0.015) << "band " << b;
    }
}

// Every order together against an independent Monte Carlo simulation of the same slab
// (conservative Rayleigh scattering, vertical optical depth 0.40788, muS 0.6645, black
// ground; 200,000 photons: python3 of a plane-parallel photon tracer with Rayleigh's
// phase function drawn by rejection gives diffuse transmission 0.22289 +- 0.00093 and
// reflection 0.23608 +- 0.00095 of the incident flux). The tables' quadrature keeps
// 97-98 % of it; without the orders beyond the second both fall 12 % short.
TEST(Atmosphere, MultipleScatteringMatchesMonteCarloAndConservesEnergy) {
    const Model m = Model::make(RayleighProfile::MidlatitudeWinter, noAerosol(), 1, 0);
    Resolution res;
    res.orders = 8;
    const Atmosphere a = Atmosphere::compute(m, res, 2);
    for (double muS : {0.9, 0.6645, 0.3}) {
        const Vec3 sun = sunAt(muS);
        const double in = kExtraterrestrial[kBlue] * muS;
        const double direct = in * a.transmittanceToTop(kGroundRadius, muS)[kBlue];
        const double diffuse = a.indirectIrradiance(kGroundRadius, muS)[kBlue];
        // The flux leaving the top, from radiance looking down just below it.
        double up = 0;
        const int nt = 48, np = 96;
        const double dt = 0.5 * kPi / nt, dp = 2 * kPi / np;
        for (int i = 0; i < nt; ++i) {
            const double th = (i + 0.5) * dt;
            for (int j = 0; j < np; ++j) {
                const double ph = (j + 0.5) * dp;
                const Vec3 d{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                             -std::cos(th)};
                up += a.radiance(d, sun, 59999)[kBlue] * std::cos(th) * std::sin(th) * dt * dp;
            }
        }
        EXPECT_NEAR((direct + diffuse + up) / in, 1, 0.015) << "muS " << muS;
        if (muS == 0.6645) {
            EXPECT_NEAR(diffuse / in / 0.22289, 1, 0.035);
            EXPECT_NEAR(up / in / 0.23608, 1, 0.035);
        }
    }
}

Resolution coarse() {
    Resolution r;
    r.transmittanceR = 16;
    r.transmittanceMu = 32;
    r.scatteringR = 4;
    r.scatteringMu = 8;
    r.scatteringMuS = 4;
    r.scatteringNu = 3;
    r.irradianceR = 4;
    r.irradianceMuS = 8;
    r.orders = 3;
    return r;
}

Model defaultModel() {
    return Model::make(RayleighProfile::MidlatitudeSummer,
                       calc::DataFile::load(std::string(RP_SOURCE_DIR) + "/lib/mie_ca.dat"), 1,
                       0.2);
}

TEST(Atmosphere, TheSameForAnyNumberOfThreadsAndAfterACacheRoundTrip) {
    const Model m = defaultModel();
    const Atmosphere one = Atmosphere::compute(m, coarse(), 1);
    const Atmosphere two = Atmosphere::compute(m, coarse(), 2);
    TempDir dir;
    const std::string path = (dir.path() / "a.atm").string();
    two.save(path, "key 1");
    Atmosphere read;
    EXPECT_FALSE(read.load(path, m, coarse(), "key 2"));
    Resolution other = coarse();
    other.scatteringNu = 4;
    EXPECT_FALSE(read.load(path, m, other, "key 1"));
    ASSERT_TRUE(read.load(path, m, coarse(), "key 1"));
    const Vec3 sun = normalize(Vec3{0.3, -0.5, 0.6});
    for (const Vec3& d :
         {Vec3{0, 0, 1}, normalize(Vec3{1, 0.2, 0.05}), normalize(Vec3{0.4, 0, -1})}) {
        const Spectrum a = one.radiance(d, sun, 10), b = two.radiance(d, sun, 10),
                       c = read.radiance(d, sun, 10);
        for (int k = 0; k < kBands; ++k) {
            EXPECT_EQ(a[k], b[k]);
            EXPECT_FLOAT_EQ(float(a[k]), float(c[k]));
        }
    }
}

// The ground seen from 10 m: what it reflects of the sun and sky (albedo / pi times the
// irradiance) through a few metres of air.
TEST(Atmosphere, GroundReflectsTheSunAndSky) {
    const Model m = defaultModel();
    Resolution res;  // RADIANCE's sizes: coarser ones blur the 10 m of air into 100s
    res.orders = 2;
    const Atmosphere a = Atmosphere::compute(m, res, 2);
    const Vec3 sun = sunAt(0.7);
    const Spectrum l = a.radiance({0, 0, -1}, sun, 10);
    const Spectrum sky = a.indirectIrradiance(kGroundRadius, 0.7);
    const Spectrum toSun = a.sunRadiance(sun, 0);
    for (int b : {0, 10, 19}) {
        const double e = sky[b] + toSun[b] * kSunSolidAngle * 0.7;
        EXPECT_NEAR(l[b] / (0.2 / kPi * e), 1, 0.01) << "band " << b;
    }
    // A sun below the tables' lowest (twilight) gives no direct light.
    EXPECT_EQ(a.sunRadiance(sunAt(-0.3), 10)[10], 0);
}

TEST(Atmosphere, RayleighProfileBySeasonAndLatitude) {
    const double deg = kPi / 180;
    EXPECT_EQ(rayleighProfileFor(47 * deg, 6), RayleighProfile::MidlatitudeSummer);
    EXPECT_EQ(rayleighProfileFor(47 * deg, 12), RayleighProfile::MidlatitudeWinter);
    EXPECT_EQ(rayleighProfileFor(-47 * deg, 12), RayleighProfile::MidlatitudeSummer);
    EXPECT_EQ(rayleighProfileFor(70 * deg, 1), RayleighProfile::SubarcticWinter);
    EXPECT_EQ(rayleighProfileFor(-10 * deg, 1), RayleighProfile::Tropical);
    EXPECT_STREQ(profileTag(RayleighProfile::SubarcticSummer), "ss");
}

TEST(Atmosphere, AerosolTableMustHaveTwentyBands) {
    const calc::DataFile bad = calc::DataFile::parse("2\n0 1000 2\n0 2 3\n1 2 3 4 5 6\n", "bad");
    EXPECT_THROW(Model::make(RayleighProfile::Tropical, bad, 1, 0.2), InputError);
}

}  // namespace
}  // namespace rp::gen::atmos
