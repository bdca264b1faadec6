// End-to-end check of the forward pass against the integrating sphere of
// tests/data/furnace: mkpmap's global map, read back, gives the analytic
// indirect irradiance E_i = E_d(R) rho/(1-rho) = 0.785398 W/m2 at the 20 sensors through
// RADIANCE's density estimate (what `rtrace -ab -1` shows minus direct). This exercises
// emission (spherical light), transport (bubble, roulette), the global storage rule (no
// photon at its first hit), flux normalisation, the file round trip and the estimator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "pmap/density.h"
#include "pmap/mkpmap.h"
#include "pmap/mkpmap_options.h"
#include "pmap/photon_map.h"
#include "scene/scene_load.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

struct Sensor {
    Vec3 pos, dir;
};

std::vector<Sensor> furnaceSensors() {
    std::ifstream in(std::string(RP_SOURCE_DIR) + "/tests/data/furnace/points.txt");
    std::vector<Sensor> s;
    Sensor x;
    while (in >> x.pos.x >> x.pos.y >> x.pos.z >> x.dir.x >> x.dir.y >> x.dir.z) s.push_back(x);
    return s;
}

// mkpmap's global map of the sphere `scene` (centred at `centre`), checked against the
// analytic answer at the 20 sensors of tests/data/furnace moved to `centre`.
void expectFurnace(const std::string& scene, const Vec3& centre, const std::string& map,
                   const char* label) {
    std::vector<std::string> args = {"mkpmap", "-apg", map, "200k", "-apr", "11", "-n", "2", scene};
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::ostringstream diag;
    runMkpmap(parseMkpmapArgs(int(argv.size()), argv.data()), "mkpmap furnace test", diag);

    PhotonMap g = PhotonMap::open(map, StoreOptions{});
    // Stored flux = Phi rho / (1 - rho (1 - a)): photons die on the lamp with probability
    // a = (r/R)^2 per bounce. Phi = 9.8696 W, rho = 0.5, a = 0.0025 -> 9.8450 W per channel.
    double stored = g.stats().avgFlux[1] * double(g.size());
    EXPECT_NEAR(stored, 9.8450, 0.01 * 9.8450);

    const double analytic = 0.785398 * (9.8450 / 9.8696);  // with the lamp's shadow
    constexpr int kBandwidth = 500;
    PhotonLookup lookup(g, LookupParams{kBandwidth, 0, 0.5});
    std::vector<Sensor> sensors = furnaceSensors();
    ASSERT_EQ(sensors.size(), 20u);
    double sum = 0;
    for (const Sensor& s : sensors) {
        Vec3 n = normalize(s.dir);
        // irradiance = pi x estimate
        double e = kPi * lookup.surfaceDensity(s.pos + centre, n)[1];
        // One estimate of k = 500 photons: relative sd ~ 1/sqrt(500) = 4.5 %; 4 sigma.
        EXPECT_NEAR(e, analytic, 0.18 * analytic) << "sensor at " << s.pos.x << " " << s.pos.y;
        sum += e;
    }
    // Mean of 20 (mostly non-overlapping) estimates: 4.5 %/sqrt(20) = 1 %; the sensors sit
    // 1 mm inside the wall (boundary bias well below that at this radius). 3 sigma.
    std::printf(
        "%s: stored flux %.4f W (expected 9.8450), mean indirect irradiance %.5f "
        "W/m2 vs analytic %.5f (%+.2f %%)\n",
        label, stored, sum / 20, analytic, 100 * (sum / 20 / analytic - 1));
    EXPECT_NEAR(sum / 20, analytic, 0.03 * analytic);
}

TEST(FurnaceValidation, GlobalMapGivesTheAnalyticIndirectIrradiance) {
    TempDir dir("rp_furnace");
    expectFurnace(std::string(RP_SOURCE_DIR) + "/tests/data/furnace/scene.rad", Vec3{},
                  dir.file("g.pm"), "furnace");
}

// The same sphere as an instanced octree: a bubble of radius 0.5 placed with -s 2 and
// moved away from the origin, around the lamp of the scene itself. Photons scatter on
// the instanced surface exactly as on the plain one: the same stored flux and the same
// analytic irradiance (scale and translation carried through emission, hits, normals).
TEST(FurnaceValidation, InstancedSphereGivesTheSameIrradiance) {
    TempDir dir("rp_furnace_inst");
    {
        std::ofstream w(dir.file("wall.rad"));
        w << "void plastic wall_grey 0 0 5 0.5 0.5 0.5 0 0\n"
             "wall_grey bubble furnace_wall 0 0 4 0 0 0 0.5\n";
    }
    OconvRequest oc;
    oc.files = {dir.file("wall.rad")};
    oc.commandLine = "oconv wall.rad";
    { std::ofstream(dir.file("wall.oct"), std::ios::binary) << oconvOutput(oc); }
    {
        std::ofstream s(dir.file("scene.rad"));
        s << "void instance furnace 7 " << dir.file("wall.oct") << " -s 2 -t 30 -20 5 0 0\n"
          << "void light emitter 0 0 3 100 100 100\n"
             "emitter sphere lamp 0 0 4 30 -20 5 0.05\n";
    }
    expectFurnace(dir.file("scene.rad"), Vec3{30, -20, 5}, dir.file("g.pm"), "instanced furnace");
}

}  // namespace
}  // namespace rp::pmap
