// Contribution photon maps (contrib.h, mkpmap -apC): about the same number of photons
// per light source whatever its flux, per-source stored flux proportional to what a
// global map stores from it, valid primaries shared along a path, the file round trip
// with its primaries, -n independence, and that -apC ignores other maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "pmap/mkpmap.h"
#include "pmap/mkpmap_options.h"
#include "pmap/photon_map.h"
#include "pmap/pmap_test_util.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

using test::slurp;

class ContribRun : public ::testing::Test {
protected:
    // The validation room with its three lamps, their radiances replaced when asked.
    std::string scene(bool greyLamps) {
        std::string s = slurp(std::string(RP_SHARED_DIR) + "/validation/contrib/scene.rad");
        if (greyLamps) {
            auto sub = [&](const std::string& a, const std::string& b) {
                size_t at = s.find(a);
                EXPECT_NE(at, std::string::npos) << a;
                if (at != std::string::npos) s.replace(at, a.size(), b);
            };
            sub("3 100 10 10", "3 1000 1000 1000");  // lamp_red: 100x the flux of blue
            sub("3 10 100 10", "3 100 100 100");
            sub("3 10 10 100", "3 10 10 10");
        }
        std::string path = dir_.file(greyLamps ? "grey.rad" : "rgb.rad");
        std::ofstream(path) << s;
        return path;
    }
    MkpmapReport run(std::vector<std::string> args, std::ostream* diagOut = nullptr) {
        args.insert(args.begin(), "mkpmap");
        std::vector<const char*> argv;
        for (const auto& a : args) argv.push_back(a.c_str());
        std::ostringstream diag;
        return runMkpmap(parseMkpmapArgs(int(argv.size()), argv.data()), "mkpmap test",
                         diagOut ? *diagOut : diag);
    }
    std::string path(const std::string& n) { return dir_.file(n); }
    TempDir dir_{"rp_contrib"};
};

struct PerSource {
    std::array<uint64_t, 3> photons{};
    std::array<std::array<double, 3>, 3> flux{};  // [source][channel]
    std::array<uint64_t, 3> primaries{};
};

PerSource split(const PhotonMap& m) {
    PerSource r;
    for (const PhotonPrimary& p : m.primaries()) {
        EXPECT_GE(p.srcIdx, 0);
        EXPECT_LT(p.srcIdx, 3);
        if (p.srcIdx >= 0 && p.srcIdx < 3) ++r.primaries[size_t(p.srcIdx)];
    }
    for (const Photon& p : m.photons()) {
        EXPECT_LT(p.primary, m.primaries().size());
        if (p.primary >= m.primaries().size()) continue;
        int s = m.primaries()[p.primary].srcIdx;
        if (s < 0 || s > 2) continue;
        ++r.photons[size_t(s)];
        auto f = p.fluxRgb();
        for (int c = 0; c < 3; ++c) r.flux[size_t(s)][size_t(c)] += f[size_t(c)];
    }
    return r;
}

TEST_F(ContribRun, EqualPhotonCountsAndFluxProportionalToSources) {
    RP_REQUIRE_SHARED("validation/contrib");
    const std::string sc = scene(true);
    run({"-apC", path("c.pm"), "60k", "-apr", "2", sc});
    run({"-apg", path("g.pm"), "60k", "-apr", "2", sc});
    PhotonMap c = PhotonMap::load(path("c.pm"));
    PhotonMap g = PhotonMap::load(path("g.pm"));
    EXPECT_EQ(c.type(), PhotonMapType::Contrib);
    EXPECT_NEAR(double(c.size()), 60000, 0.05 * 60000);
    ASSERT_FALSE(c.primaries().empty());
    EXPECT_LT(c.primaries().size(), c.size());  // several photons per path on average

    PerSource r = split(c);
    // Each source stores about a third (RADIANCE's per-source target n / nsources; the
    // per-source two-pass prediction is good to a few percent): 5 % of the total.
    for (int s = 0; s < 3; ++s)
        EXPECT_NEAR(double(r.photons[size_t(s)]) / double(c.size()), 1.0 / 3, 0.05) << s;
    // Every primary is indexed by at least one photon (one primary per storing path).
    std::vector<char> used(c.primaries().size(), 0);
    for (const Photon& p : c.photons()) used[p.primary] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), long(used.size()));

    // Stored flux per source is proportional to its emitted flux (1000 : 100 : 10, same
    // geometry): ~20k photons per source, noise ~1-2 %.
    EXPECT_NEAR(r.flux[0][1] / r.flux[1][1], 10.0, 0.5);
    EXPECT_NEAR(r.flux[1][1] / r.flux[2][1], 10.0, 0.5);
    // And the sum is what a global map of the same scene stores (energy balance).
    double cSum = r.flux[0][1] + r.flux[1][1] + r.flux[2][1];
    double gSum = g.stats().avgFlux[1] * double(g.size());
    EXPECT_NEAR(cSum / gSum, 1.0, 0.03);
    // The global map stores ~100x fewer photons from the dim source than from the bright one;
    // the contribution map gives every source the same share, so its dim-source photons
    // carry ~100x less flux.
    double f0 = r.flux[0][1] / double(r.photons[0]), f2 = r.flux[2][1] / double(r.photons[2]);
    EXPECT_NEAR(f0 / f2, 100.0, 10.0);
}

TEST_F(ContribRun, ColouredLampsDeterministicAndOthersIgnored) {
    RP_REQUIRE_SHARED("validation/contrib");
    const std::string sc = scene(false);
    std::ostringstream diag;
    run({"-apC", path("c1.pm"), "30k", "-apg", path("ignored.pm"), "10k", "-apr", "7", sc});
    run({"-apC", path("c2.pm"), "30k", "-apr", "7", "-n", "2", sc}, &diag);
    EXPECT_FALSE(std::filesystem::exists(path("ignored.pm")));
    EXPECT_EQ(slurp(path("c1.pm")), slurp(path("c2.pm"))) << "-n 1 and -n 2 differ";

    PhotonMap c = PhotonMap::load(path("c1.pm"));
    PerSource r = split(c);
    // Grey room: a lamp's photons keep its colour (red lamp 100 10 10 -> G/R = 0.1).
    EXPECT_NEAR(r.flux[0][1] / r.flux[0][0], 0.1, 0.005);
    EXPECT_NEAR(r.flux[1][0] / r.flux[1][1], 0.1, 0.005);
    EXPECT_NEAR(r.flux[2][1] / r.flux[2][2], 0.1, 0.005);
    // Equal channel means: each lamp's (mean) flux is the same, so are the stored sums.
    for (int s = 0; s < 3; ++s)
        EXPECT_NEAR(double(r.photons[size_t(s)]) / double(c.size()), 1.0 / 3, 0.05) << s;

    // The header has RADIANCE's "<k> primary rays" line; the file round-trips.
    Header h = c.fileHeader("x");
    bool found = false;
    for (const std::string& l : h.lines)
        found = found || l == std::to_string(c.primaries().size()) + " primary rays";
    EXPECT_TRUE(found);
    std::ostringstream out;
    c.write(out, "x");
    std::istringstream in(out.str());
    PhotonMap back = PhotonMap::read(in, "round trip");
    EXPECT_EQ(back.primaries(), c.primaries());
    EXPECT_TRUE(std::equal(back.photons().begin(), back.photons().end(), c.photons().begin()));
}

}  // namespace
}  // namespace rp::pmap
