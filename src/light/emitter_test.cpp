// Tests for emitter.h: exact flux of each emitter kind (independent of -ds), equal
// photon weights summing to the flux, direction and position distributions (4 sigma or
// chi-square at 1e-4 significance), ports, the cube emission of distant sources, the
// EmissionModifier hook, and the cornell lamp / daylight sources.
#include "light/emitter.h"

#include <gtest/gtest.h>

#include "light/light_test_util.h"
#include "scene/scene_load.h"
#include "util/shared_for_tests.h"

namespace rp::light {
namespace {

using testing::Builder;
using testing::Stats;

constexpr int kPhotons = 1000000;

EmissionPlan planFor(const Builder& b, const SceneGeometry& geom, EmissionOptions opt = {}) {
    return EmissionPlan(geom, findLightSources(b.scene(), geom), opt);
}

// Sum of photon weights / N reproduces the plan's RGB flux (0.5 %), and every photon
// carries the same mean flux.
void expectEqualWeights(const EmissionPlan& plan, const Color& analytic) {
    Color sum;
    for (int i = 0; i < kPhotons; ++i) {
        EmittedPhoton ph = plan.emitPhoton(42, uint64_t(i));
        ASSERT_NEAR(ph.weight.average(), plan.totalFluxW(), 1e-9 * plan.totalFluxW());
        sum += ph.weight;
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c] / kPhotons, analytic[c], 5e-3 * analytic[c]);
}

TEST(Emitter, SphereLightFluxAndDirections) {
    // The furnace emitter: r = 0.05, L = 100 -> 9.8696 W.
    Builder b;
    b.add(PrimType::Sphere, "s", {0, 0, 0, 0.05}, b.light("l", 100, 100, 100));
    b.add(PrimType::Bubble, "wall", {0, 0, 0, 1},
          b.add(PrimType::Plastic, "p", {.5, .5, .5, 0, 0}));
    SceneGeometry geom(b.scene());
    EmissionPlan plan = planFor(b, geom);
    EXPECT_NEAR(plan.totalFluxW(), 100 * kPi * 4 * kPi * 0.0025, 1e-9);
    expectEqualWeights(plan, Color::grey(9.869604401));
    Stats cosTheta;
    for (int i = 0; i < kPhotons; ++i) {
        EmittedPhoton ph = plan.emitPhoton(1, uint64_t(i));
        Vec3 n = normalize(ph.ray.origin);
        ASSERT_NEAR(length(ph.ray.origin), 0.05, 1e-9);
        ASSERT_GT(length(ph.ray.origin), 0.05);  // spawned outside
        cosTheta.add(dot(ph.ray.dir, n));
    }
    EXPECT_NEAR(cosTheta.mean(), 2.0 / 3, 4 * cosTheta.sigmaOfMean());
}

TEST(Emitter, ConcavePolygonLightUniformPositions) {
    Builder b;
    int32_t l = b.light("l", 1, 2, 3);
    // L shape in z = 0 facing +z, area 3.
    b.add(PrimType::Polygon, "L", {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0}, l);
    SceneGeometry geom(b.scene());
    EmissionOptions opt;
    opt.partitionSize = 0.05;
    EmissionPlan plan = planFor(b, geom, opt);
    Color exact = Color{1, 2, 3} * (kPi * 3);
    EXPECT_NEAR(plan.totalFlux().b, exact.b, 1e-9);
    expectEqualWeights(plan, exact);
    // Chi-square over a 4x4 grid of 0.5 m cells: the 12 cells inside get N/12 each, the
    // 4 in the cut-out none. 11 dof: chi2 < 37.4 at p = 1e-4.
    std::vector<long> count(16, 0);
    Stats cosTheta;
    for (int i = 0; i < kPhotons; ++i) {
        EmittedPhoton ph = plan.emitPhoton(2, uint64_t(i));
        ASSERT_GT(ph.ray.origin.z, 0);
        ASSERT_LT(ph.ray.origin.z, 1e-5);
        int ix = std::min(3, int(ph.ray.origin.x / 0.5)),
            iy = std::min(3, int(ph.ray.origin.y / 0.5));
        ++count[size_t(iy * 4 + ix)];
        cosTheta.add(ph.ray.dir.z);
    }
    double chi2 = 0, expected = kPhotons / 12.0;
    for (int iy = 0; iy < 4; ++iy)
        for (int ix = 0; ix < 4; ++ix) {
            long c = count[size_t(iy * 4 + ix)];
            if (ix >= 2 && iy >= 2)
                EXPECT_EQ(c, 0);
            else
                chi2 += (c - expected) * (c - expected) / expected;
        }
    EXPECT_LT(chi2, 37.4);
    EXPECT_NEAR(cosTheta.mean(), 2.0 / 3, 4 * cosTheta.sigmaOfMean());
}

TEST(Emitter, RingAndConeLights) {
    Builder b;
    int32_t l = b.light("l", 2, 2, 2);
    b.add(PrimType::Ring, "r", {0, 0, 0, 0, 0, 1, 0.5, 1}, l);
    b.add(PrimType::Cylinder, "c", {3, 0, 0, 3, 0, 2, 0.1}, l);
    SceneGeometry geom(b.scene());
    EmissionPlan plan = planFor(b, geom);
    double ring = 2 * kPi * kPi * (1 - 0.25), cyl = 2 * kPi * (2 * kPi * 0.1 * 2);
    EXPECT_NEAR(plan.sourceFlux(0).r, ring, 1e-9);
    EXPECT_NEAR(plan.sourceFlux(1).r, cyl, 1e-9);
    expectEqualWeights(plan, Color::grey(ring + cyl));
}

TEST(Emitter, FlatSpotlightExactAndIndependentOfDs) {
    // 1 x 1 spotlight facing down, 30 deg full cone: flux = pi L A sin^2(15 deg).
    Builder b;
    int32_t spot = b.add(PrimType::Spotlight, "spot", {50, 50, 50, 30, 0, 0, -1});
    b.squareZ(spot, 0, 1, 0, 1, 3, /*down=*/true);
    b.squareZ(b.add(PrimType::Plastic, "p", {.5, .5, .5, 0, 0}), -5, 5, -5, 5, 0);
    SceneGeometry geom(b.scene());
    double s = std::sin(15 * kPi / 180), exact = kPi * 50 * s * s;
    double cosHalf = std::cos(15 * kPi / 180);
    for (double ds : {0.01, 0.001}) {
        EmissionOptions opt;
        opt.partitionSize = ds;
        EmissionPlan plan = planFor(b, geom, opt);
        EXPECT_NEAR(plan.totalFluxW(), exact, 1e-9 * exact) << ds;
    }
    EmissionPlan plan = planFor(b, geom);
    expectEqualWeights(plan, Color::grey(exact));
    for (int i = 0; i < 200000; ++i)
        ASSERT_GE(-plan.emitPhoton(3, uint64_t(i)).ray.dir.z, cosHalf - 1e-12);
}

TEST(Emitter, SphereSpotlightExactAndIndependentOfDs) {
    // The caustic scene's emitter: r = 0.02, L = 1e4, 10 deg cone aimed down:
    // flux = L pi r^2 Omega (any direction sees the projected disk pi r^2) = 0.30046 W.
    Builder b;
    int32_t spot = b.add(PrimType::Spotlight, "spot", {1e4, 1e4, 1e4, 10, 0, 0, -1});
    b.add(PrimType::Sphere, "bulb", {0, 0, 5, 0.02}, spot);
    b.squareZ(b.add(PrimType::Plastic, "p", {.5, .5, .5, 0, 0}), -2, 2, -2, 2, 0);
    SceneGeometry geom(b.scene());
    double omega = 2 * kPi * (1 - std::cos(5 * kPi / 180));
    double exact = 1e4 * kPi * 0.0004 * omega;
    EmissionOptions fine;
    fine.partitionSize = 0.001;
    EXPECT_NEAR(planFor(b, geom).totalFluxW(), exact, 1e-12);
    EXPECT_NEAR(planFor(b, geom, fine).totalFluxW(), exact, 1e-12);
    EmissionPlan plan = planFor(b, geom, fine);
    expectEqualWeights(plan, Color::grey(exact));
    double cosHalf = std::cos(5 * kPi / 180);
    for (int i = 0; i < 200000; ++i) {
        EmittedPhoton ph = plan.emitPhoton(4, uint64_t(i));
        ASSERT_GE(-ph.ray.dir.z, cosHalf - 1e-12);
        ASSERT_GT(dot(ph.ray.dir, ph.ray.origin - Vec3{0, 0, 5}), 0);  // leaves the surface
    }
}

TEST(Emitter, LocalGlowLimitsPath) {
    Builder b;
    b.add(PrimType::Sphere, "g", {0, 0, 0, 0.1}, b.add(PrimType::Glow, "glow", {1, 1, 1, 2.5}));
    SceneGeometry geom(b.scene());
    EmissionPlan plan = planFor(b, geom);
    EXPECT_DOUBLE_EQ(plan.emitPhoton(0, 0).ray.tmax, 2.5);
}

TEST(Emitter, ModifierHookCosineGivesTwoThirds) {
    Builder b;
    int32_t pat = b.add(PrimType::Brightfunc, "cosfunc", {}, kVoid, {"f", "."});
    b.squareZ(b.light("l", 3, 3, 3, pat), 0, 1, 0, 1, 0);
    SceneGeometry geom(b.scene());
    EXPECT_THROW(planFor(b, geom), InputError);  // modified, no modifier supplied
    EmissionOptions opt;
    opt.modifierFor = [](const LightSource&) {
        EmissionModifier m;
        // D points towards the origin: -D . N = cos(theta) of the emitted photon.
        m.eval = [](const EmissionQuery& q) {
            EXPECT_NEAR(q.rdot, -dot(q.rayDir, q.normal), 1e-12);
            return Color::grey(q.rdot);
        };
        m.directionalOnly = true;
        return m;
    };
    EmissionPlan plan = planFor(b, geom, opt);
    double unmodified = 3 * kPi;
    EXPECT_NEAR(plan.totalFluxW() / unmodified, 2.0 / 3, 2e-3);
    expectEqualWeights(plan, Color::grey(plan.totalFluxW()));
    // Density ~ cos^2: mean cos = integral(cos^3) / integral(cos^2) = 3/4. The table's
    // cells add a small discretisation error (-dp 1000): 1e-3 on top of 4 sigma.
    Stats st;
    for (int i = 0; i < kPhotons; ++i) st.add(plan.emitPhoton(5, uint64_t(i)).ray.dir.z);
    EXPECT_NEAR(st.mean(), 0.75, 4 * st.sigmaOfMean() + 1e-3);
}

// A 3 x 1.5 m window at y = 0 (normal +y, into the room) and the daylight sun.
struct PortScene {
    Builder b;
    int32_t window;
    PortScene(bool sky) {
        int32_t pl = b.add(PrimType::Plastic, "wall", {.5, .5, .5, 0, 0});
        int32_t glass = b.add(PrimType::Glass, "window_glass", {.96, .96, .96});
        if (sky) {
            int32_t g = b.add(PrimType::Glow, "sky_glow", {1, 1, 1, 0});
            b.add(PrimType::Source, "sky", {0, 0, 1, 180}, g);
        } else {
            int32_t sol = b.light("solar", 6.69e6, 6.69e6, 6.69e6);
            b.add(PrimType::Source, "sun", {0.153855, -0.727432, 0.668708, 0.5}, sol);
        }
        window = b.add(PrimType::Polygon, "window",
                       {1.5, 0, 0.9, 1.5, 0, 2.4, 4.5, 0, 2.4, 4.5, 0, 0.9}, glass);
        b.squareZ(pl, 0, 6, 0, 4, 0);  // floor (inside)
    }
};

TEST(Emitter, SunThroughPort) {
    PortScene s(false);
    SceneGeometry geom(s.b.scene());
    EmissionOptions opt;
    opt.ports = findPhotonPorts(s.b.scene(), geom, {PortSpec{"window_glass"}});
    EmissionPlan plan = planFor(s.b, geom, opt);
    Vec3 sun = normalize(Vec3{0.153855, -0.727432, 0.668708});
    double omega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
    double exact = 6.69e6 * omega * 4.5 * dot(sun, Vec3{0, -1, 0});  // L Omega A cos
    EXPECT_NEAR(plan.totalFluxW(), exact, 5e-3 * exact);
    expectEqualWeights(plan, Color::grey(exact));
    for (int i = 0; i < 100000; ++i) {
        EmittedPhoton ph = plan.emitPhoton(6, uint64_t(i));
        ASSERT_EQ(ph.port, 0);
        ASSERT_EQ(ph.portPrim, s.window);
        ASSERT_LT(ph.ray.origin.y, 0);  // just behind (outside) the port
        ASSERT_GT(ph.ray.origin.y, -1e-4);
        ASSERT_GT(dot(-ph.ray.dir, sun), std::cos(0.25 * kPi / 180) - 1e-9);
        auto hit = geom.closestHit(ph.ray);
        ASSERT_TRUE(hit.has_value()) << ph.ray.origin.x << " " << ph.ray.origin.y << " "
                                     << ph.ray.origin.z << " / " << ph.ray.dir.y;
        ASSERT_EQ(hit->prim, s.window) << hit->t << " at " << i << ": " << ph.ray.origin.x << " "
                                       << ph.ray.origin.y << " " << ph.ray.origin.z;
    }
}

// -apE: a port also emits what its exterior table sees (here a uniform ground of radiance
// 100 below the horizon): L A times the projected solid angle of the lower half of the
// hemisphere outside, pi / 2, beside the sun's own flux; those photons are marked
// exterior, carry no source, and enter the room upwards.
TEST(Emitter, PortExteriorAddsWhatThePortSees) {
    PortScene s(false);
    SceneGeometry geom(s.b.scene());
    EmissionOptions opt;
    opt.ports = findPhotonPorts(s.b.scene(), geom, {PortSpec{"window_glass"}});
    const double sunOnly = planFor(s.b, geom, opt).totalFluxW();
    long calls = 0;
    // The ground: a plane 1 m below the port's centre (z = 0.65) with ambient
    // irradiance 10 W/m2.
    opt.exterior.view = [&](const Vec3& from, const Vec3& w, uint64_t) {
        ++calls;
        EXPECT_LT(from.y, 0);  // just outside the port, looking out
        EXPECT_LT(w.y, 0);
        ExteriorView v;
        if (!(w.z < 0)) return v;
        v.surface = true;
        v.radiance = Color::grey(100);
        v.ambient = Color::grey(10);
        v.distance = (from.z - 0.65) / -w.z;
        v.point = from + w * v.distance;
        v.normal = {0, 0, 1};
        return v;
    };
    EmissionPlan plan = planFor(s.b, geom, opt);
    const double exact = 100 * 4.5 * kPi / 2;
    // The photons left on the ground tile what the port sees of it: near the port, their
    // flux per unit area is the ambient irradiance (every ray of the 16 positions crosses
    // this patch, one cell's solid angle t^2 / cos apart).
    double nearFlux = 0;
    for (const ExteriorPhoton& ph : plan.exteriorPhotons()) {
        ASSERT_NEAR(ph.point.z, 0.65, 1e-9);
        if (ph.point.x > 2 && ph.point.x < 4 && ph.point.y > -1.5) nearFlux += ph.flux.average();
    }
    EXPECT_NEAR(nearFlux / (2 * 1.5), 10, 1.0);
    // The cells' 4 x 4 sample grids split where the horizon splits the cells (it runs
    // along cell edges or middles here): exact but for float sums.
    EXPECT_NEAR(plan.exteriorFlux().average(), exact, 1e-4 * exact);
    EXPECT_NEAR(plan.totalFluxW(), sunOnly + plan.exteriorFlux().average(), 1e-9 * exact);
    EXPECT_GT(calls, 1000);
    const double share = plan.exteriorFlux().average() / plan.totalFluxW();
    Stats st;
    for (int i = 0; i < 100000; ++i) {
        EmittedPhoton ph = plan.emitPhoton(8, uint64_t(i));
        st.add(ph.exterior ? 1 : 0);
        ASSERT_EQ(ph.port, 0);
        if (!ph.exterior) continue;
        ASSERT_EQ(ph.source, -1);
        ASSERT_GT(ph.ray.dir.y, 0);
        ASSERT_GT(ph.ray.dir.z, -0.2);  // upwards, but for the cells across the horizon
        ASSERT_EQ(geom.closestHit(ph.ray)->prim, s.window);
    }
    EXPECT_NEAR(st.mean(), share, 4 * st.sigmaOfMean());
}

// -apE with a port set back from its opening: past the port's edges its rays meet the
// room's own wall around the opening, just beyond the port and facing back through it;
// that is the room's light, not the outside's, and brings nothing. A facade across the
// street faces the port too, but metres away, and counts.
TEST(Emitter, PortExteriorIgnoresTheWallAroundASetBackPort) {
    PortScene s(false);
    SceneGeometry geom(s.b.scene());
    EmissionOptions opt;
    opt.ports = findPhotonPorts(s.b.scene(), geom, {PortSpec{"window_glass"}});
    for (double depth : {0.01, 5.0}) {
        opt.exterior.view = [&](const Vec3& from, const Vec3& w, uint64_t) {
            ExteriorView v;
            v.surface = true;
            v.radiance = Color::grey(100);
            v.ambient = Color::grey(10);
            v.distance = depth / -w.y;
            v.point = from + w * v.distance;
            v.normal = {0, 1, 0};  // facing back into the room
            return v;
        };
        EmissionPlan plan = planFor(s.b, geom, opt);
        if (depth < 1) {
            EXPECT_EQ(plan.exteriorFlux().average(), 0);
            EXPECT_TRUE(plan.exteriorPhotons().empty());
        } else {
            // All of the hemisphere outside: L A pi.
            EXPECT_NEAR(plan.exteriorFlux().average(), 100 * 4.5 * kPi, 1e-3 * 100 * 4.5 * kPi);
        }
    }
}

// A port set back behind the glass (a BSDF layer used as the port; smaller than the
// window, so that the sun is seen through the glass only): the glass stops the sources'
// test, so no source reaches it and mkpmap stops with RADIANCE 5.4's error
// (its mkpmap gives the same for such a port). With -apE it must too, rather than emit
// the outside's reflections without the sun.
TEST(Emitter, PortBehindGlassSeesNoSourceEvenWithExterior) {
    PortScene s(false);
    const int32_t layer = s.b.add(PrimType::Plastic, "layer", {.5, .5, .5, 0, 0});
    s.b.add(PrimType::Polygon, "blinds_layer",
            {1.6, 0.03, 1.0, 1.6, 0.03, 2.3, 4.4, 0.03, 2.3, 4.4, 0.03, 1.0}, layer);
    SceneGeometry geom(s.b.scene());
    EmissionOptions opt;
    opt.ports = findPhotonPorts(s.b.scene(), geom, {PortSpec{"layer"}});
    EXPECT_THROW(planFor(s.b, geom, opt), InputError);
    opt.exterior.view = [](const Vec3& from, const Vec3& w, uint64_t) {
        ExteriorView v;
        v.surface = true;
        v.radiance = Color::grey(100);
        v.ambient = Color::grey(10);
        v.distance = 5 / -w.y;
        v.point = from + w * v.distance;
        v.normal = {0, 1, 0};
        return v;
    };
    try {
        planFor(s.b, geom, opt);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("zero flux from light sources"), std::string::npos);
    }
}

TEST(Emitter, SkyThroughPortAndBidirectional) {
    PortScene s(true);
    SceneGeometry geom(s.b.scene());
    EmissionOptions opt;
    opt.ports = findPhotonPorts(s.b.scene(), geom, {PortSpec{"window_glass"}});
    // Uniform sky (upper hemisphere) through a vertical port: L A pi/2. The floor lies
    // inside, behind the port, so nothing outside occludes.
    double exact = 4.5 * kPi / 2;
    EXPECT_NEAR(planFor(s.b, geom, opt).totalFluxW(), exact, 5e-3 * exact);
    size_t oneWay = planFor(s.b, geom, opt).partitionCount(0);
    // Bidirectional: the inside face also emits (towards the sky it sees through the
    // opening: nothing in this scene occludes the upper hemisphere from either face).
    opt.ports[0].direction = PortDirection::Bidirectional;
    EmissionPlan bi = planFor(s.b, geom, opt);
    EXPECT_NEAR(bi.totalFluxW(), 2 * exact, 1e-2 * exact);
    EXPECT_EQ(bi.partitionCount(0), 2 * oneWay);
}

TEST(Emitter, DistantSourceFromSceneCube) {
    Builder b;
    b.squareZ(b.add(PrimType::Plastic, "p", {.5, .5, .5, 0, 0}), 0, 2, 0, 2, 0);
    b.add(PrimType::Sphere, "s", {1, 1, 1, 0.5}, b.add(PrimType::Plastic, "q", {.5, .5, .5, 0, 0}));
    Vec3 d = normalize(Vec3{1, 2, 3});
    b.add(PrimType::Source, "sun", {d.x, d.y, d.z, 2}, b.light("sol", 1000, 1000, 1000));
    SceneGeometry geom(b.scene());
    SceneCube cube = geom.sceneCube();
    EmissionPlan plan = planFor(b, geom);
    // A disk wholly above three faces: L size^2 (dx + dy + dz) pi sin^2(1 deg).
    double s = std::sin(1 * kPi / 180);
    double exact = 1000 * cube.size * cube.size * (d.x + d.y + d.z) * kPi * s * s;
    EXPECT_NEAR(plan.totalFluxW(), exact, 1e-9 * exact);
    EXPECT_EQ(plan.partitionCount(0), 6u * 100u * 100u);
    expectEqualWeights(plan, Color::grey(exact));
    for (int i = 0; i < 100000; ++i) {
        EmittedPhoton ph = plan.emitPhoton(7, uint64_t(i));
        ASSERT_GT(dot(-ph.ray.dir, d), std::cos(1 * kPi / 180) - 1e-12);
        Vec3 rel = ph.ray.origin - cube.origin;
        bool onFace = false;
        for (int a = 0; a < 3; ++a)
            onFace |= std::fabs(rel[a] - cube.size) < 1e-9 * cube.size;  // faces facing d
        ASSERT_TRUE(onFace);
    }
}

TEST(Emitter, CornellLampFlux) {
    RP_REQUIRE_SHARED("validation/cornell");
    Scene scene = loadScene({std::string(RP_SHARED_DIR) + "/validation/cornell/scene.rad"});
    SceneGeometry geom(scene);
    EmissionPlan plan(geom, findLightSources(scene, geom));
    ASSERT_EQ(plan.sources().size(), 1u);
    EXPECT_NEAR(plan.totalFluxW(), 40 * kPi * 1.3 * 1.05, 1e-9);  // 171.531 W per channel
    EmittedPhoton ph = plan.emitPhoton(0, 0);
    EXPECT_LT(ph.ray.dir.z, 0);
    EXPECT_LT(ph.ray.origin.z, 5.495);
}

TEST(Emitter, DaylightSourcesThroughWindow) {
    RP_REQUIRE_SHARED("validation/daylight");
    Scene scene = loadScene({std::string(RP_SHARED_DIR) + "/validation/daylight/scene.rad"});
    SceneGeometry geom(scene);
    EmissionOptions opt;
    opt.ports = findPhotonPorts(scene, geom, {PortSpec{"window_glass"}});
    opt.modifierFor = [](const LightSource&) {
        return EmissionModifier{[](const EmissionQuery&) { return Color::grey(1); }, true};
    };
    EmissionPlan plan(geom, findLightSources(scene, geom), opt);
    ASSERT_EQ(plan.sources().size(), 3u);
    Vec3 sun = normalize(Vec3{0.153855, -0.727432, 0.668708});
    double omega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
    double sunFlux = 6.69e6 * omega * 4.5 * dot(sun, Vec3{0, -1, 0});
    EXPECT_NEAR(plan.sourceFlux(0).r, sunFlux, 5e-3 * sunFlux);
    // Sky (glow 1, uniform here) through the window: the outside ground polygon does not
    // rise above the horizon, so L A pi/2 to the table's accuracy.
    EXPECT_NEAR(plan.sourceFlux(1).r, 4.5 * kPi / 2, 5e-3 * 4.5 * kPi / 2);
    // Ground glow below the horizon: the 100 m ground polygon hides all but a sliver
    // just under the horizon (< 5 % of the sky's flux).
    EXPECT_LT(plan.sourceFlux(2).r, 0.05 * plan.sourceFlux(1).r);
}

// Two lamps facing +z: A, 1 x 1 m at radiance la in z = 0, and B, 2 x 2 m at radiance 1
// in z = 1, partitioned at -ds `ds`. Gives the partition count and the fraction of
// kPhotons emitted from A, whose flux share is la / (la + 4).
struct TwoLampPicks {
    size_t partitions;
    double fromA;
};
TwoLampPicks twoLampPicks(double la, double ds) {
    Builder b;
    b.add(PrimType::Polygon, "a", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, b.light("la", la, la, la));
    b.add(PrimType::Polygon, "b", {3, 0, 1, 5, 0, 1, 5, 2, 1, 3, 2, 1}, b.light("lb", 1, 1, 1));
    SceneGeometry geom(b.scene());
    EmissionOptions opt;
    opt.partitionSize = ds;
    EmissionPlan plan = planFor(b, geom, opt);
    long fromA = 0;
    for (int i = 0; i < kPhotons; ++i) fromA += plan.emitPhoton(3, uint64_t(i)).ray.origin.z < 0.5;
    return {plan.partitionCount(), double(fromA) / kPhotons};
}

// Many partitions of very different flux: the alias table (emitter.cpp pickAny) must
// pick each source in proportion to its flux (4 sigma).
TEST(Emitter, ManyPartitionsPickedByFlux) {
    const TwoLampPicks r = twoLampPicks(100, 0.01);
    ASSERT_GT(r.partitions, 100u);
    const double p = 100.0 / 104.0;  // A's share of the flux
    EXPECT_NEAR(r.fromA, p, 4 * std::sqrt(p * (1 - p) / kPhotons));
}

// Few partitions (under 16) of unequal flux: picked in proportion to flux (4 sigma).
TEST(Emitter, FewPartitionsPickedByFlux) {
    const TwoLampPicks r = twoLampPicks(3, 1);
    ASSERT_GE(r.partitions, 2u);
    ASSERT_LT(r.partitions, 16u);
    const double p = 3.0 / 7.0;  // A's share of the flux
    EXPECT_NEAR(r.fromA, p, 4 * std::sqrt(p * (1 - p) / kPhotons));
}

// Seven unit-square lamps of radiance 1..7, two partitions each: every slot of the alias
// table is kept or aliased, and each lamp must get k/28 of the photons (4 sigma), which
// a wrong keep probability or alias in the construction would break.
TEST(Emitter, AliasTablePicksEveryPartitionByFlux) {
    Builder b;
    constexpr int kLamps = 7;
    for (int k = 0; k < kLamps; ++k) {
        const double x = 2.0 * k, r = k + 1;
        b.add(PrimType::Polygon, "p" + std::to_string(k),
              {x, 0, 0, x + 1, 0, 0, x + 1, 1, 0, x, 1, 0},
              b.light("l" + std::to_string(k), r, r, r));
    }
    SceneGeometry geom(b.scene());
    EmissionOptions opt;
    opt.partitionSize = 1;
    EmissionPlan plan = planFor(b, geom, opt);
    ASSERT_EQ(plan.partitionCount(), size_t(2 * kLamps));  // two triangles each
    std::array<long, kLamps> count{};
    for (int i = 0; i < kPhotons; ++i)
        ++count[size_t(plan.emitPhoton(5, uint64_t(i)).ray.origin.x / 2)];
    for (int k = 0; k < kLamps; ++k) {
        const double p = (k + 1) / 28.0;
        EXPECT_NEAR(double(count[size_t(k)]) / kPhotons, p, 4 * std::sqrt(p * (1 - p) / kPhotons))
            << "lamp " << k;
    }
}

TEST(Emitter, DeterministicPerPhotonIndex) {
    Builder b;
    b.add(PrimType::Sphere, "s", {0, 0, 0, 0.5}, b.light("l", 1, 1, 1));
    SceneGeometry geom(b.scene());
    EmissionPlan plan = planFor(b, geom);
    EmittedPhoton a = plan.emitPhoton(9, 12345), c = plan.emitPhoton(9, 12345);
    EXPECT_EQ(a.ray.origin, c.ray.origin);
    EXPECT_EQ(a.ray.dir, c.ray.dir);
}

}  // namespace
}  // namespace rp::light
