// Patterned sources emit as the renderer sees them: the daylight sky's skyfunc gives the
// flux of the CIE clear-sky formula written out in C++, and a luminaire's brightdata
// distribution (in inches, turned) the flux of its intensity table.
#include "light/pattern_emission.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "scene/reader.h"
#include "scene/scene_load.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::light {

namespace {
// skybright.cal for the daylight scene's skyfunc (gensky +s: type 1, zenith 8.79,
// ground 20, normalisation 0.526, sun direction), as a function of D (pointing at the sky).
double clearSky(const Vec3& d) {
    const Vec3 sun{0.153855, -0.727432, 0.668708};
    double cosg = std::clamp(dot(d, sun), -1.0, 1.0), gamma = std::acos(cosg);
    double grad = d.z > 0.01 ? 1 - std::exp(-0.32 / d.z) : 1;
    double sky = 8.79 * (0.91 + 10 * std::exp(-3 * gamma) + 0.45 * cosg * cosg) * grad / 0.526;
    double w = std::pow(d.z + 1.01, 10);
    return (w * sky + 20.0 / w) / (w + 1 / w);
}
}  // namespace

TEST(PatternEmission, DaylightSkyFluxMatchesTheFormula) {
    RP_REQUIRE_SHARED("validation/daylight");
    Scene scene = loadScene({std::string(RP_SHARED_DIR) + "/validation/daylight/scene.rad"});
    SceneGeometry geom(scene);
    material::SurfaceChains chains(scene, {std::string(RP_SOURCE_DIR) + "/lib"});
    auto sources = findLightSources(scene, geom);
    EmissionOptions viaCalc, viaFormula;
    viaCalc.ports = viaFormula.ports = findPhotonPorts(scene, geom, {PortSpec{"window_glass"}});
    viaCalc.modifierFor = patternModifiers(chains);
    viaFormula.modifierFor = [](const LightSource&) {
        return EmissionModifier{
            [](const EmissionQuery& q) { return Color::grey(clearSky(q.rayDir)); }, true};
    };
    EmissionPlan a(geom, sources, viaCalc), b(geom, sources, viaFormula);
    ASSERT_EQ(a.sources().size(), 3u);
    for (int s = 0; s < 3; ++s) {
        double fa = a.sourceFlux(s).g, fb = b.sourceFlux(s).g;
        EXPECT_GT(fb, 0);
        EXPECT_NEAR(fa, fb, 1e-6 * fb) << "source " << s;
    }
    // Photons from the same index leave the same way whichever evaluator made the plan.
    EmittedPhoton pa = a.emitPhoton(7, 1234), pb = b.emitPhoton(7, 1234);
    EXPECT_NEAR(dot(pa.ray.dir, pb.ray.dir), 1, 1e-9);
}

// A 1 m x 1 m downlight whose distribution is in inches and turned (rect_fixture.rad's
// pattern transform): radiance 10 * v(theta) / Rdot, v linear through 1, 0.5, 0 at 0, 45
// and 90 degrees off nadir, the same in every azimuth. Its flux is the intensity
// integrated over the lower hemisphere, 10 * 2 pi * int v(theta) sin(theta) dtheta per
// square metre. Reading the table through an unscaled D (all of it at 0 degrees) gave
// 10 * 2 pi (2.7 times as much). The flux is a jittered stratified sum over the direction
// table (-dp 1000 per sr; 0.05 % off here): 1 % tolerance. The photons' mean cosine has a
// standard error of 0.0015 for 20,000 photons: 0.01 is about 7 of them.
TEST(PatternEmission, LuminaireDataFluxIsItsIntegratedIntensity) {
    TempDir dir;
    std::ofstream(dir.file("dist.dat")) << "1\n0 90 3\n1 0.5 0\n";
    std::ofstream(dir.file("flat.cal")) << "flat(v) = v / Rdot;\ntheta = Acos(Dz) / DEGREE;\n";
    Scene scene = parseScene(
        "void brightdata dist 12 flat dist.dat flat.cal theta -s 0.0254 -rz 90 -t 0 0 3\n"
        "0 0\n"
        "dist light lamp 0 0 3 10 10 10\n"
        "lamp polygon panel 0 0 12  0 0 3  0 1 3  1 1 3  1 0 3\n",
        "lum.rad");
    SceneGeometry geom(scene);
    material::SurfaceChains chains(scene,
                                   {dir.path().string(), std::string(RP_SOURCE_DIR) + "/lib"});
    EmissionOptions eo;
    eo.partitionSize = 0.5;  // a few partitions: each evaluates the chain 6,000 times
    eo.modifierFor = patternModifiers(chains);
    EmissionPlan plan(geom, findLightSources(scene, geom), eo);
    ASSERT_EQ(plan.sources().size(), 1u);
    // int_0^{pi/2} v sin: v = 1 - t/(pi/2) on [0, pi/2] (the table is linear throughout).
    const double half = M_PI / 2;
    double integral = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        double t = (i + 0.5) * half / n;
        integral += (1 - t / half) * std::sin(t) * half / n;
    }
    const double expected = 10 * 2 * M_PI * integral;
    EXPECT_NEAR(plan.sourceFlux(0).g, expected, 0.01 * expected);
    // Every photon leaves downwards, more of them near the axis than a cosine would send.
    double meanCos = 0;
    const int photons = 20000;
    for (int i = 0; i < photons; ++i) meanCos += -plan.emitPhoton(3, uint64_t(i)).ray.dir.z;
    meanCos /= photons;
    // Photons go as L cos = 10 v per steradian: mean cos = int v cos sin / int v sin
    // = (1/2 - 1/4) / (1 - 2/pi) = 0.688 (0.5 for a uniform v).
    const double expectedCos = 0.25 / (1 - 2 / M_PI);
    EXPECT_NEAR(meanCos, expectedCos, 0.01);
}

}  // namespace rp::light
