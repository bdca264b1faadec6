// Loading -ap maps for the renderer: type detection, defaults, the stale check and the
// density a uniform map gives.
#include "render/photon_lighting.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pmap/photon.h"
#include "pmap/pmap_test_util.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/temp_dir_for_tests.h"
#include "util/warnings.h"

namespace rp::render {
namespace {

// A map of n photons uniform on the unit square z = 0 (normal +z), total flux `total`
// per channel: irradiance = total (W/m^2), so the density estimate is total / pi.
std::string writeMap(const std::filesystem::path& dirPath, const std::string& name,
                     pmap::PhotonMapType type, int n, double total) {
    std::vector<pmap::Photon> photons;
    Rng rng(7, RngDomain::Test, 0);
    for (int i = 0; i < n; ++i)
        photons.push_back(pmap::makePhoton({rng.uniform(), rng.uniform(), 0}, {0, 0, 1},
                                           {total / n, total / n, total / n}));
    pmap::PhotonMap map(type, std::move(photons));
    std::string path = (dirPath / name).string();
    map.save(path, "test", true);
    return path;
}

Scene emptyScene() { return Scene{}; }

TEST(PhotonLighting, GlobalAndCausticDensityOfUniformMaps) {
    TempDir tmp;
    std::vector<PhotonMapUse> uses = {
        {writeMap(tmp.path(), "g.pm", pmap::PhotonMapType::Global, 20000, 2.0), 100, 0},
        {writeMap(tmp.path(), "c.pm", pmap::PhotonMapType::Caustic, 20000, 1.0), 100, 0}};
    Scene scene = emptyScene();
    PhotonLighting pl(uses, 0, scene);
    ASSERT_TRUE(pl.hasGlobal());
    ASSERT_TRUE(pl.hasCaustic());
    EXPECT_FALSE(pl.hasDirect());
    auto l = pl.makeLookups();
    Color g = pl.globalDensity(*l, {0.5, 0.5, 0}, {0, 0, 1});
    Color c = pl.causticDensity(*l, {0.5, 0.5, 0}, {0, 0, 1});
    // Relative noise of a k = 100 estimate is about 10 %.
    EXPECT_NEAR(g.g * kPi, 2.0, 0.4);
    EXPECT_NEAR(c.g * kPi, 1.0, 0.2);
    // Wrong-facing query: the normal filter finds nothing.
    EXPECT_EQ(pl.globalDensity(*l, {0.5, 0.5, 0}, {0, 0, -1}).g, 0);
}

// A map searched out of core (-aC smaller than the map) gives the densities it gives in
// core (no ties here); a damaged record out of core is reported by the search that reads
// it, naming the file (in core, the records are all checked at load).
TEST(PhotonLighting, OutOfCoreMapGivesInCoreDensities) {
    TempDir tmp;
    Scene scene = emptyScene();
    const std::string c = writeMap(tmp.path(), "c.pm", pmap::PhotonMapType::Caustic, 20000, 1.0);
    pmap::StoreOptions ooc;
    ooc.cachePhotons = 1000;
    PhotonLighting in({{c, 50, 0}}, 0, scene);
    PhotonLighting out({{c, 50, 0}}, 0, scene, nullptr, ooc);
    auto li = in.makeLookups();
    auto lo = out.makeLookups();
    Rng rng(3, RngDomain::Test, 0);
    for (int i = 0; i < 50; ++i) {
        const Vec3 q(rng.uniform(), rng.uniform(), 0);
        li->startRay();
        lo->startRay();
        const Color a = in.causticDensity(*li, q, {0, 0, 1});
        const Color b = out.causticDensity(*lo, q, {0, 0, 1});
        EXPECT_GT(a.g, 0);
        EXPECT_EQ(a.r, b.r);
        EXPECT_EQ(a.g, b.g);
        EXPECT_EQ(a.b, b.b);
    }

    // Exchange two photon records deep in the tree (their subtrees no longer split at
    // their positions): walks that visit them fail. The map is made one as RADIANCE
    // writes it first: ours carry record checksums, which would refuse it at opening.
    const std::string plain = pmap::test::withoutChecksums(pmap::test::slurp(c), 20000);
    std::ofstream(c, std::ios::binary) << plain;
    std::fstream f(c, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(0, std::ios::end);
    const std::streamoff rec = std::streamoff(f.tellg()) - 20000 * 27;
    for (int k = 0; k < 20; ++k) {
        const std::streamoff at = rec + std::streamoff(2000 + 700 * k) * 27;
        char a[27], b[27];
        f.seekg(at);
        f.read(a, 27);
        f.seekg(at + 350 * 27);
        f.read(b, 27);
        f.seekp(at);
        f.write(b, 27);
        f.seekp(at + 350 * 27);
        f.write(a, 27);
    }
    f.close();
    PhotonLighting bad({{c, 50, 0}}, 0, scene, nullptr, ooc);
    auto lb = bad.makeLookups();
    int refused = 0;
    for (int i = 0; i < 100; ++i) {
        lb->startRay();
        try {
            bad.causticDensity(*lb, {0.1 * (i % 10) + 0.05, 0.1 * (i / 10) + 0.05, 0}, {0, 0, 1});
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("not a valid kd-tree"), std::string::npos);
            EXPECT_NE(std::string(e.what()).find(c), std::string::npos);
            ++refused;
        }
    }
    EXPECT_GT(refused, 0);
}

TEST(PhotonLighting, DefaultBandwidthWarns) {
    TempDir tmp;
    std::vector<std::string> warnings;
    setWarningSink([&](const std::string& m) { warnings.push_back(m); });
    Scene scene = emptyScene();
    PhotonLighting pl({{writeMap(tmp.path(), "g.pm", pmap::PhotonMapType::Global, 500, 1), 0, 0}},
                      0, scene);
    setWarningSink(nullptr);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("using 40"), std::string::npos);
}

TEST(PhotonLighting, RejectsTwoMapsOfOneTypeContribAndBadRange) {
    TempDir tmp;
    Scene scene = emptyScene();
    std::string g = writeMap(tmp.path(), "g.pm", pmap::PhotonMapType::Global, 500, 1);
    EXPECT_THROW(PhotonLighting({{g, 50, 0}, {g, 50, 0}}, 0, scene), InputError);
    EXPECT_THROW(PhotonLighting({{g, 50, 40}}, 0, scene), InputError);
    EXPECT_THROW(PhotonLighting({{tmp.file("missing.pm"), 50, 0}}, 0, scene), InputError);
}

TEST(PhotonLighting, StaleMapIsAnError) {
    TempDir tmp;
    std::string g = writeMap(tmp.path(), "g.pm", pmap::PhotonMapType::Global, 500, 1);
    auto mapTime = std::filesystem::last_write_time(g);
    Scene scene;
    int64_t mapSec = std::chrono::duration_cast<std::chrono::seconds>(
                         std::chrono::file_clock::to_sys(mapTime).time_since_epoch())
                         .count();
    scene.inputs.push_back({"old.rad", mapSec - 100});
    EXPECT_NO_THROW(PhotonLighting({{g, 50, 0}}, 0, scene));
    scene.inputs.push_back({"edited.rad", mapSec + 100});
    try {
        PhotonLighting({{g, 50, 0}}, 0, scene);
        FAIL() << "stale map accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("edited.rad"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("stale"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rp::render
