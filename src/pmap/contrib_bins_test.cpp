#include "pmap/contrib_bins.h"

#include <gtest/gtest.h>

#include "util/dir_code.h"
#include "util/error.h"

namespace rp::pmap {
namespace {

TEST(ContribBins, BinCountFromDefinitions) {
    // RADIANCE's documented sky binning: rcontrib -e MF:1 -f reinhart.cal -bn Nrbins.
    EXPECT_EQ(evalBinCount({{false, "MF:1"}, {true, "reinhart.cal"}}, "Nrbins"), 146);
    EXPECT_EQ(evalBinCount({{false, "MF:2;"}, {true, "reinhart.cal"}}, "Nrbins"), 578);
    EXPECT_EQ(evalBinCount({{true, "reinhartb.cal"}}, "Nrbins"), 145);
    EXPECT_THROW(evalBinCount({}, "Nrbins"), InputError);
}

TEST(ContribBins, BinCountSeesTheParameters) {
    // RADIANCE 5.4: rcontrib -f reinhartb.cal -p MF=2 -b rbin -bn Nrbins -m sky has 577.
    std::vector<ContribModifier> mods;
    std::vector<CalcDefinition> defs{{true, "reinhartb.cal"}};
    ModifierOptions m(mods, defs, &evalBinCount);
    OptionTable t;
    m.addTo(t, false);
    std::vector<std::string> args{"x", "-p", "MF=2", "-b", "rbin", "-bn", "Nrbins", "-m", "sky"};
    t.parse(args, 1);
    ASSERT_EQ(mods.size(), 1u);
    EXPECT_EQ(mods[0].bins, 577);
    EXPECT_EQ(mods[0].params, "MF=2");
}

TEST(ContribBins, BinsOfReinhartSky) {
    ContribModifier sky;
    sky.name = "skyglow";
    sky.binExpr = "rbin";
    sky.bins = 146;
    sky.params = "MF=1";
    ContribModifier sun;
    sun.name = "solar";
    const ContribBins bins({sky, sun}, {{true, "reinhart.cal"}});
    EXPECT_EQ(bins.size(), 147u);
    EXPECT_EQ(bins.offset(1), 146u);
    ContribBins::Binner b(bins);
    EXPECT_EQ(b.bin(0, {}, {0, 0, 1}), 145);   // zenith: the last patch
    EXPECT_EQ(b.bin(0, {}, {0, 0, -1}), 0);    // ground
    EXPECT_EQ(b.bin(0, {}, {0, 1, 0.01}), 1);  // north at the horizon: the first
    EXPECT_EQ(b.bin(1, {}, {0, 0, 1}), 0);     // a constant bin
}

TEST(PrimaryBins, EachPrimaryOnceWhateverTheThreads) {
    // A distant sky binned by direction (two bins) and a lamp in one: every primary's
    // photons go where rcontrib's binner puts them, divided by the source's radiance for
    // coefficients, and the table is the same for any number of threads.
    ContribModifier sky;
    sky.name = "skymat";
    sky.binExpr = "if(Dx, 1, 0) + if(Px*Px, 5, 0)";  // a distant source's P is 0
    sky.bins = 2;
    ContribModifier lamp;
    lamp.name = "lampmat";
    const ContribBins bins({sky, lamp}, {});
    const std::vector<ContribSource> sources{
        {"skymat", {2, 4, 8}, true}, {"lampmat", {1, 1, 0}, false}, {"other", {1, 1, 1}, false}};
    std::vector<PhotonPrimary> primaries;
    std::vector<PrimaryRay> rays;
    for (int i = 0; i < 100000; ++i) {
        primaries.push_back({int16_t(i % 3)});
        const double dx = i % 2 ? 0.6 : -0.6;
        rays.push_back({{3, 0, 0}, encodeDirection({dx, 0, 0.8})});
    }
    const PrimaryBins one(bins, sources, false, primaries, rays, 1);
    const PrimaryBins four(bins, sources, false, primaries, rays, 4);
    for (uint32_t i = 0; i < primaries.size(); ++i) {
        ASSERT_EQ(one.key(i), four.key(i));
        const PrimaryBins::Share& s = one.share(i);
        const int want = i % 3 == 2 ? PrimaryBins::kUntracked : i % 3 == 1 ? 2 : i % 2 ? 1 : 0;
        ASSERT_EQ(s.slot, want) << i;
    }
    EXPECT_EQ(one.shares().size(), 4u);  // untracked, two sky bins, the lamp
    EXPECT_EQ(one.share(0).of({2, 4, 8}), (std::array<double, 3>{1, 1, 1}));
    EXPECT_EQ(one.share(1).of({3, 3, 3}), (std::array<double, 3>{3, 3, 0}));  // no blue
    const PrimaryBins asContributions(bins, sources, true, primaries, rays, 2);
    EXPECT_EQ(asContributions.share(0).of({2, 4, 8}), (std::array<double, 3>{2, 4, 8}));
    // Without primary rays only the constant bins can be placed.
    const PrimaryBins noRays(bins, sources, false, primaries, {}, 1);
    EXPECT_EQ(noRays.share(0).slot, PrimaryBins::kNoRay);
    EXPECT_EQ(noRays.share(1).slot, 2);
    EXPECT_EQ(noRays.share(uint32_t(primaries.size())).slot, PrimaryBins::kUntracked);
}

TEST(PrimaryBins, ManyBinsKeepWideKeys) {
    // More shares than a byte holds: every primary still finds its own bin.
    ContribModifier lamp;
    lamp.name = "lampmat";
    lamp.binExpr = "Px";  // a local source: the point where the primary left it
    lamp.bins = 600;
    const ContribBins bins({lamp}, {});
    const std::vector<ContribSource> sources{{"lampmat", {1, 1, 1}, false}};
    std::vector<PhotonPrimary> primaries(3000, PhotonPrimary{0});
    std::vector<PrimaryRay> rays;
    for (int i = 0; i < 3000; ++i)
        rays.push_back({{float(i % 700), 0, 0}, encodeDirection({0, 0, 1})});
    const PrimaryBins pb(bins, sources, true, primaries, rays, 2);
    EXPECT_EQ(pb.shares().size(), 602u);  // untracked, 600 bins, past the count
    for (uint32_t i = 0; i < 3000; ++i)
        ASSERT_EQ(pb.share(i).slot, i % 700 < 600 ? int32_t(i % 700) : PrimaryBins::kPastEnd) << i;
}

}  // namespace
}  // namespace rp::pmap
