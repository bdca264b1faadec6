#include "pmap/precomp_contrib.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "pmap/contrib_coeffs.h"
#include "pmap/density.h"
#include "pmap/photon_map.h"
#include "util/dir_code.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

// Photons on the unit square of z = 0 facing up, from two sources: a distant "sky" whose
// primaries arrive from +x or -x (its two bins), and a local "lamp" (one bin).
struct Scene {
    std::vector<Photon> photons;
    std::vector<PhotonPrimary> primaries;
    std::vector<PrimaryRay> rays;
    std::vector<ContribSource> sources{{"skymat", {2, 2, 2}, true}, {"lampmat", {1, 1, 1}, false}};

    explicit Scene(int n) {
        Rng rng(3, RngDomain::Sampling, 9);
        for (int i = 0; i < n; ++i) {
            const int src = i % 3 == 0 ? 1 : 0;
            const double dx = (i % 2 == 0) ? 0.6 : -0.6;  // back toward the source
            primaries.push_back({int16_t(src)});
            PrimaryRay r;
            r.pos = {float(dx), 0, 1};
            r.dir = encodeDirection({dx, 0, 0.8});
            rays.push_back(r);
            photons.push_back(makePhoton({rng.uniform(), rng.uniform(), 0}, {0, 0, 1},
                                         {0.01, 0.02, 0.03}, false, uint32_t(i)));
        }
    }
};

std::vector<ContribModifier> modifiers() {
    ContribModifier sky;
    sky.name = "skymat";
    sky.binExpr = "if(Dx, 1, 0)";
    sky.bins = 2;
    ContribModifier lamp;
    lamp.name = "lampmat";
    return {sky, lamp};
}

PrecompContribSettings settings(const TempDir& dir, double comp, int threads) {
    PrecompContribSettings s;
    s.fraction = 0.25;
    s.bandwidth = 30;
    s.compression = comp;
    s.pass.threads = threads;
    s.mapFile = dir.file("map.pm");
    return s;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(PrecompContrib, BinsSumToTheContributionDensity) {
    TempDir dir;
    Scene sc(4000);
    const ContribBins bins(modifiers(), {});
    const PrecompContribResult r =
        precomputeContrib(sc.photons, sc.primaries, sc.rays, sc.sources, bins, settings(dir, 0, 1));
    ASSERT_EQ(r.photons.size(), 1000u);
    CoeffFile sky(coeffFile(dir.file("map.pm"), "skymat"));
    CoeffFile lamp(coeffFile(dir.file("map.pm"), "lampmat"));
    EXPECT_EQ(sky.info().bins, 2);
    EXPECT_EQ(sky.info().records, 1000u);
    EXPECT_FALSE(sky.info().contributions);

    // The same estimate made directly: each neighbour's share, by source.
    PhotonMap map(PhotonMapType::Contrib, sc.photons, sc.primaries);
    map.makeSearchable(false);
    LookupParams lp;
    lp.bandwidth = 30;
    lp.gatherTolerance = 1;
    CoeffCodec::Scratch s;
    for (size_t i = 0; i < r.photons.size(); i += 97) {
        const Photon& p = r.photons[i];
        EXPECT_EQ(p.primary, i);
        PhotonLookup lookup(map, lp);
        std::array<double, 3> want[3] = {};  // sky bin 0, sky bin 1, lamp
        lookup.contribDensity(p.position(), p.normal(), [&](auto photons, double scale) {
            for (const FoundPhoton& f : photons) {
                const int src = sc.primaries[f.primary].srcIdx;
                const double dx = sc.rays[f.primary].pos[0];
                const int slot = src == 1 ? 2 : dx > 0 ? 1 : 0;
                const double rad = src == 1 ? 1 : 2;  // -V-: per unit radiance
                const auto flux = f.fluxRgb();
                for (int c = 0; c < 3; ++c) want[slot][c] += flux[size_t(c)] * scale / rad;
            }
        });
        std::vector<Rgb> got(2), gotLamp(1);
        ASSERT_TRUE(sky.decode(i, got, s));
        ASSERT_TRUE(lamp.decode(i, gotLamp, s));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(got[0][c], want[0][c], 1e-6 * want[0][c] + 1e-12) << i;
            EXPECT_NEAR(got[1][c], want[1][c], 1e-6 * want[1][c] + 1e-12) << i;
            EXPECT_NEAR(gotLamp[0][c], want[2][c], 1e-6 * want[2][c] + 1e-12) << i;
        }
        EXPECT_GT(want[0][0], 0);
        EXPECT_GT(want[1][0], 0);
    }
    std::vector<Rgb> past(2);
    EXPECT_FALSE(sky.decode(1000, past, s));
}

TEST(PrecompContrib, SameFilesForAnyThreadCount) {
    TempDir one("rp_pc1"), two("rp_pc2");
    Scene sc(6000);
    const ContribBins bins(modifiers(), {});
    auto a = precomputeContrib(sc.photons, sc.primaries, sc.rays, sc.sources, bins,
                               settings(one, 0.5, 1));
    auto b = precomputeContrib(sc.photons, sc.primaries, sc.rays, sc.sources, bins,
                               settings(two, 0.5, 2));
    ASSERT_EQ(a.photons, b.photons);
    for (const char* m : {"skymat", "lampmat"}) {
        const std::string fa = slurp(coeffFile(one.file("map.pm"), m));
        const std::string fb = slurp(coeffFile(two.file("map.pm"), m));
        EXPECT_FALSE(fa.empty());
        EXPECT_EQ(fa, fb) << m;
    }
}

TEST(PrecompContrib, ModifierThatIsNoSourceIsRefused) {
    TempDir dir;
    Scene sc(100);
    std::vector<ContribModifier> mods = modifiers();
    mods[1].name = "wall";
    const ContribBins bins(mods, {});
    EXPECT_THROW(
        precomputeContrib(sc.photons, sc.primaries, sc.rays, sc.sources, bins, settings(dir, 0, 1)),
        InputError);
}

TEST(PrecompContrib, OptionFileGivesRcontribTheSameBins) {
    std::vector<ContribModifier> mods = modifiers();
    mods[0].params = "MF=1";
    const std::string text = rcontribOptionText(mods, {{true, "reinhartb.cal"}}, false);
    EXPECT_EQ(text,
              "-V-\n-f reinhartb.cal\n-p MF=1 -b \"if(Dx, 1, 0)\" -bn 2 -m skymat\n"
              "-p \"\" -b 0 -bn 1 -m lampmat\n");
}

// Maps larger than memory: searched out of core (photons through a page cache of 64) with
// the coefficients memory-mapped, every lookup finds the in-core store's nearest photon
// and decodes the same coefficients (golden.precomp_contrib runs rcontrib both ways).
TEST(PrecompContrib, OutOfCoreLookupsAreInCoreLookups) {
    TempDir dir;
    Scene sc(3000);
    const ContribBins bins(modifiers(), {});
    PrecompContribResult r = precomputeContrib(sc.photons, sc.primaries, sc.rays, sc.sources, bins,
                                               settings(dir, 0.5, 2));
    PhotonMap(PhotonMapType::PreCompContrib, std::move(r.photons))
        .save(dir.file("map.pm"), "", true);
    const PhotonMap inCore = PhotonMap::open(dir.file("map.pm"), StoreOptions{});
    StoreOptions tiny;
    tiny.cachePhotons = 64;
    tiny.pageSize = 4;
    tiny.bandwidth = 2;
    const PhotonMap ooc = PhotonMap::open(dir.file("map.pm"), tiny);
    EXPECT_EQ(inCore.store().describe(), "in core");
    ASSERT_NE(ooc.store().describe().find("out of core"), std::string::npos);
    ASSERT_EQ(ooc.store().size(), inCore.store().size());
    const CoeffFile sky(coeffFile(dir.file("map.pm"), "skymat"));
    auto a = inCore.store().makeCursor(), b = ooc.store().makeCursor();
    std::vector<FoundPhoton> fa, fb;
    std::vector<Rgb> ca(size_t(sky.info().bins)), cb(ca.size());
    CoeffCodec::Scratch scratch;
    Rng rng(8, RngDomain::Test, 0);
    const Vec3 up{0, 0, 1};
    for (int i = 0; i < 500; ++i) {
        const PhotonQuery q{{rng.uniform(), rng.uniform(), 0},
                            &up,
                            false,
                            std::numeric_limits<float>::infinity(),
                            1};
        ASSERT_EQ(inCore.store().findNearest(*a, q, fa), 1u);
        ASSERT_EQ(ooc.store().findNearest(*b, q, fb), 1u);
        ASSERT_EQ(fa[0].dist2, fb[0].dist2) << i;
        ASSERT_EQ(fa[0].primary, fb[0].primary) << i;
        ASSERT_TRUE(sky.decode(fa[0].primary, ca, scratch));
        ASSERT_TRUE(sky.decode(fb[0].primary, cb, scratch));
        for (size_t k = 0; k < ca.size(); ++k) ASSERT_EQ(ca[k], cb[k]) << i;
    }
}

TEST(PrecompContrib, CompressedFilesReadBack) {
    TempDir dir;
    Scene sc(3000);
    const ContribBins bins(modifiers(), {});
    precomputeContrib(sc.photons, sc.primaries, sc.rays, sc.sources, bins, settings(dir, 0.8, 2));
    CoeffFile sky(coeffFile(dir.file("map.pm"), "skymat"));
    EXPECT_EQ(sky.info().records, 750u);
    EXPECT_NEAR(sky.info().compression, 0.8, 0.1);
}

}  // namespace
}  // namespace rp::pmap

namespace rp::pmap {
namespace {

TEST(PrecompContrib, CoefficientFileRoundTrip) {
    TempDir dir;
    for (double comp : {0.0, 0.5, 0.8, 0.95}) {
        const std::string path = dir.file("c.rc");
        CoeffInfo info{"sky", 146, comp, true, 3};
        CoeffWriter w(path, info, "mkpmap test");
        std::vector<Rgb> v(146), back(146);
        for (size_t b = 0; b < v.size(); ++b) v[b] = {double(b), 1.0, 0.5};
        std::vector<uint8_t> rec(w.codec().recordBytes());
        CoeffCodec::Scratch s;
        for (uint64_t i = 0; i < 3; ++i) {
            w.codec().encode(v, rec.data(), s);
            w.write(i, rec.data());
        }
        w.commit(true);
        CoeffFile f(path);
        EXPECT_EQ(f.info().bins, 146);
        EXPECT_TRUE(f.info().contributions);
        EXPECT_NEAR(f.info().compression, comp, 0.01) << comp;
        ASSERT_TRUE(f.decode(2, back, s));
        if (comp <= 0.5) {
            EXPECT_NEAR(back[100][0], 100, 0.5) << comp;
        }
    }
}

}  // namespace
}  // namespace rp::pmap
