// The daylight sky's skyfunc, evaluated through the calc module for photon emission,
// gives the same per-source flux as the CIE clear-sky formula written out in C++.
#include "light/pattern_emission.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_load.h"

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
    Scene scene = loadScene({std::string(RP_SHARED_DIR) + "/validation/daylight/scene.rad"});
    SceneGeometry geom(scene);
    material::PatternSet patterns(scene, {std::string(RP_SOURCE_DIR) + "/lib"});
    auto sources = findLightSources(scene, geom);
    EmissionOptions viaCalc, viaFormula;
    viaCalc.ports = viaFormula.ports =
        findPhotonPorts(scene, geom, {parsePortSpec("window_glass")});
    viaCalc.modifierFor = patternModifiers(patterns);
    viaFormula.modifierFor = [](const LightSource&) {
        return EmissionModifier{[](const EmissionQuery& q) { return Color::grey(clearSky(q.rayDir)); },
                                true};
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

}  // namespace rp::light
